/* rfir: CRFIDTagParticleMap: insertion (tag updates) and the robot's
 * observation likelihood (PF-SLAM 003 Algorithm 1, PS-SLAM thesis Algorithm 2). */
#include "CRFIDTagParticleMap_impl.h"

#include <algorithm>

using namespace rfir::maps;
using rfir::models::PointEstimate;
using rfir::models::ReaderArea;

size_t CRFIDTagParticleMap::TTagEntry::memoryBytes() const {
    const auto pts = [](const std::vector<mrpt::math::TPoint2D>& v) {
        return v.capacity() * sizeof(mrpt::math::TPoint2D);
    };
    // The id's heap block only when it outgrows the short-string buffer.
    const size_t idHeap =
        id.capacity() > std::string().capacity() ? id.capacity() + 1 : 0;
    return sizeof(*this) + idHeap + (estimator ? estimator->memoryBytes() : 0) +
           pts(sample) + pts(visitStartSample) +
           spreadPoses.capacity() * sizeof(mrpt::math::TPose2D);
}

size_t CRFIDTagParticleMap::memoryBytes() const {
    // A node of std::unordered_map<std::string, TTagEntry> (libstdc++): next
    // pointer, key, value and the cached hash; plus one bucket pointer each.
    constexpr size_t kNode = sizeof(void*) + sizeof(std::string) + sizeof(size_t);
    size_t b = sizeof(*this);
    for (const auto* t : {&m_tags, &m_landmarks}) {
        b += t->bucket_count() * sizeof(void*);
        for (const auto& kv : *t) b += kNode + kv.second.memoryBytes();
    }
    return b;
}

using Impl = rfir::maps::CRFIDTagParticleMapImpl;

CRFIDTagParticleMap::CRFIDTagParticleMap() = default;

const CRFIDTagParticleMap::TTagEntry* CRFIDTagParticleMap::getTag(
    const std::string& id) const {
    const auto it = m_tags.find(id);
    return it == m_tags.end() ? nullptr : &it->second;
}

const CRFIDTagParticleMap::TTagEntry* CRFIDTagParticleMap::getLandmark(
    const std::string& id) const {
    const auto it = m_landmarks.find(id);
    return it == m_landmarks.end() ? nullptr : &it->second;
}

bool CRFIDTagParticleMap::translateEntry(const std::string& id, bool landmark, double dx,
                                         double dy) {
    auto& table = landmark ? m_landmarks : m_tags;
    const auto it = table.find(id);
    if (it == table.end()) return false;
    TTagEntry& e = it->second;
    e.estimator->translate(dx, dy);
    // What the robot is weighed against during a visit moves with the tag.
    e.visitStartEstimate.mean.x += dx;
    e.visitStartEstimate.mean.y += dy;
    for (auto& q : e.visitStartSample) q.x += dx, q.y += dy;
    e.spreadOrigin.x += dx;
    e.spreadOrigin.y += dy;
    for (auto& q : e.spreadPoses) q.x += dx, q.y += dy;
    Impl::refresh(*this, e);
    return true;
}

static std::vector<const CRFIDTagParticleMap::TTagEntry*> sortedEntries(
    const std::unordered_map<std::string, CRFIDTagParticleMap::TTagEntry>& t) {
    std::vector<const CRFIDTagParticleMap::TTagEntry*> v;
    v.reserve(t.size());
    for (const auto& kv : t) v.push_back(&kv.second);
    std::sort(v.begin(), v.end(), [](auto a, auto b) { return a->id < b->id; });
    return v;
}

std::vector<const CRFIDTagParticleMap::TTagEntry*> CRFIDTagParticleMap::tags() const {
    return sortedEntries(m_tags);
}

std::vector<const CRFIDTagParticleMap::TTagEntry*> CRFIDTagParticleMap::landmarks()
    const {
    return sortedEntries(m_landmarks);
}

bool CRFIDTagParticleMap::updateTagsBeforeWeighing() const {
    return likelihoodOptions.robotUpdate == TRobotUpdatePolicy::Literal;
}

bool CRFIDTagParticleMap::weighsOnlyFirstReads() const {
    return likelihoodOptions.robotUpdate == TRobotUpdatePolicy::Revisit;
}

std::string CRFIDTagParticleMap::landmarkName(int32_t id) const {
    if (id >= 0 && static_cast<size_t>(id) < m_landmarkNames.size() &&
        !m_landmarkNames[id].empty())
        return m_landmarkNames[id];
    return std::to_string(id);
}

bool CRFIDTagParticleMap::isNewVisit(const std::string& tagId) const {
    const TTagEntry* e = getTag(tagId);
    return e && Impl::newVisit(*this, *e, m_track[0]);
}

bool CRFIDTagParticleMap::isEmpty() const {
    return m_tags.empty() && m_landmarks.empty();
}

void CRFIDTagParticleMap::internal_clear() {
    m_tags.clear();
    m_landmarks.clear();
    m_track[0] = m_track[1] = TSensorTrack();
    m_notReadTravel = -1;
    m_lastTouched = 0;
    m_totalTouched = 0;
}

bool CRFIDTagParticleMap::internal_insertObservation(
    const mrpt::obs::CObservation& obs,
    const std::optional<const mrpt::poses::CPose3D>& pose) {
    const mrpt::poses::CPose3D p = pose ? *pose : mrpt::poses::CPose3D();
    const mrpt::math::TPose2D robot(p.x(), p.y(), p.yaw());
    m_lastTouched = 0;
    bool done = false;
    if (const auto* o = dynamic_cast<const rfir::obs::CObservationRFIDReaders*>(&obs)) {
        Impl::insertRFID(*this, *o, robot);
        done = true;
    } else if (const auto* b =
                   dynamic_cast<const mrpt::obs::CObservationBearingRange*>(&obs)) {
        Impl::insertRB(*this, *b, robot);
        done = true;
    }
    m_totalTouched += m_lastTouched;
    return done;
}

bool CRFIDTagParticleMap::readsNewTags(
    const rfir::obs::CObservationRFIDReaders& o) const {
    for (const auto& rd : o.readings)
        for (const auto& id : rd.tags)
            if (!m_tags.count(id)) return true;
    return false;
}

bool CRFIDTagParticleMap::insertNewTags(const rfir::obs::CObservationRFIDReaders& o,
                                        const mrpt::poses::CPose2D& robot) {
    if (!readsNewTags(o)) return false;
    m_lastTouched = 0;
    Impl::insertRFID(*this, o, robot.asTPose(), Impl::TInsert::NewTagsOnly);
    m_totalTouched += m_lastTouched;
    return true;
}

bool CRFIDTagParticleMap::internal_canComputeObservationLikelihood(
    const mrpt::obs::CObservation& obs) const {
    return dynamic_cast<const rfir::obs::CObservationRFIDReaders*>(&obs) ||
           dynamic_cast<const mrpt::obs::CObservationBearingRange*>(&obs);
}

double CRFIDTagParticleMap::internal_computeObservationLikelihood(
    const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& takenFrom) const {
    // Read-only on the map (thread-safe): the sum of the log-likelihoods of the
    // reads the policy picks (SPEC section 2), each mapped landmark's estimate
    // against the reader or sensor placed by this robot pose. The robot filter
    // resolves the reads once per step and sums them per particle itself.
    TRobotReads r;
    if (!resolveRobotReads(obs, r)) return 0;
    return robotReadsLogLikelihood(r, {takenFrom.x(), takenFrom.y(), takenFrom.yaw()});
}

bool CRFIDTagParticleMap::resolveRobotReads(const mrpt::obs::CObservation& obs,
                                            TRobotReads& out) const {
    // The lookups and policy tests: they do not depend on the robot pose.
    out = TRobotReads();
    out.det = rfir::models::DetectionLikelihood(likelihoodOptions.detection);
    if (const auto* o = dynamic_cast<const rfir::obs::CObservationRFIDReaders*>(&obs)) {
        const bool misses = likelihoodOptions.robotNegativeInformation > 0;
        for (const auto& rd : o->readings)
            for (const auto& id : rd.tags) {
                const auto it = m_tags.find(id);
                if (it == m_tags.end()) continue;
                const TTagEntry& e = it->second;
                const auto w = Impl::whichForRobot(*this, e, m_track[0]);
                if (w != Impl::Which::None) {
                    TRobotReads::TRead r;
                    const bool cur = w == Impl::Which::Current;
                    r.est = cur ? &e.estimate : &e.visitStartEstimate;
                    r.sample = cur ? &e.sample : &e.visitStartSample;
                    r.area = readerArea(rd.reader);
                    r.id = &it->first;
                    // The misses go with the tag's first weighing read only.
                    if (misses && std::none_of(out.reads.begin(), out.reads.end(),
                                               [&](const TRobotReads::TRead& q) {
                                                   return q.id == r.id;
                                               }))
                        r.missedBy = readersThatMissed(
                            *o, rd.reader, id, insertionOptions.negativeMinHalfSize);
                    out.reads.push_back(std::move(r));
                }
            }
        return true;
    }
    if (const auto* b = dynamic_cast<const mrpt::obs::CObservationBearingRange*>(&obs)) {
        out.rangeBearing = true;
        const auto& s = b->sensorLocationOnRobot;
        out.sensorX = s.x();
        out.sensorY = s.y();
        out.sensorYaw = s.yaw();
        for (const auto& z : b->sensedData) {
            const auto it = m_landmarks.find(landmarkName(z.landmarkID));
            if (it == m_landmarks.end()) continue;
            TRobotReads::TRead r;
            r.est = Impl::estimateForRobot(*this, it->second, m_track[1]);
            if (!r.est) continue;
            r.range = z.range;
            r.yaw = z.yaw;
            r.id = &it->first;
            out.reads.push_back(r);
        }
        return true;
    }
    return false;
}

double CRFIDTagParticleMap::robotReadsLogLikelihood(const TRobotReads& r,
                                                    const mrpt::math::TPose2D& robot,
                                                    double* baseSum) const {
    return robotReadsLogLikelihood(r, robot, std::cos(robot.phi), std::sin(robot.phi),
                                   baseSum);
}

double CRFIDTagParticleMap::robotReadsLogLikelihood(const TRobotReads& r,
                                                    const mrpt::math::TPose2D& robot,
                                                    double c, double s,
                                                    double* baseSum) const {
    double sum = 0, base = 0;
    if (!r.rangeBearing) {
        for (const auto& rd : r.reads) {
            const double b = Impl::robotReadLogLik(*this, *rd.est, *rd.sample, robot, c,
                                                   s, rd.area, r.det);
            sum += r.det.withOutliers(b);
            base += b;
            // Misses weigh the robot; the kidnap check reads the reads alone.
            for (const auto& a : rd.missedBy)
                sum += rfir::models::missLogLikelihood(
                    robot, c, s, a, rd.est->mean,
                    likelihoodOptions.robotNegativeInformation);
        }
        if (baseSum) *baseSum = base;
        return sum;
    }
    const auto sensor = Impl::sensorPose(r.sensorX, r.sensorY, r.sensorYaw, robot);
    for (const auto& rd : r.reads)
        sum += Impl::rbLogLik(*this, *rd.est, sensor, rd.range, rd.yaw);
    if (baseSum) *baseSum = sum;  // no mixture on range-bearing reads
    return sum;
}
