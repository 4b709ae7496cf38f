/* rfir: CRFIDTagParticleMap serialization (versioned), text output and 3D view. */
#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/models/tag_fixed_lag_smoother.h>
#include <rfir/models/tag_particle_filter.h>
#include <rfir/obs/bounded_read.h>
#include <rfir/obs/registerAllClasses.h>

#include <mrpt/opengl/CEllipsoid2D.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

using namespace rfir::maps;
using mrpt::math::TPoint2D;
using mrpt::serialization::CArchive;

IMPLEMENTS_SERIALIZABLE(CRFIDTagParticleMap, CMetricMap, rfir::maps)
RFIR_REGISTER_CLASS(CRFIDTagParticleMap, rfir::maps::CRFIDTagParticleMap)

namespace {
using rfir::obs::readBoundedCount64;
using rfir::obs::readBoundedString;
using rfir::obs::readStrictBool;
using B = rfir::obs::TReadBounds;
constexpr const char* kWhat = "CRFIDTagParticleMap";

void writePts(CArchive& a, const std::vector<TPoint2D>& v) {
    a.WriteAs<uint64_t>(v.size());
    for (const auto& p : v) a << p.x << p.y;
}
std::vector<TPoint2D> readPts(CArchive& a) {
    std::vector<TPoint2D> v(readBoundedCount64(a, kWhat, B::kMaxMapEntries, 16));
    for (auto& p : v) a >> p.x >> p.y;
    return v;
}
void writeEst(CArchive& a, const rfir::models::PointEstimate& e) {
    a << e.mean.x << e.mean.y << e.cov(0, 0) << e.cov(0, 1) << e.cov(1, 1);
}
rfir::models::PointEstimate readEst(CArchive& a) {
    rfir::models::PointEstimate e;
    double c01;
    a >> e.mean.x >> e.mean.y >> e.cov(0, 0) >> c01 >> e.cov(1, 1);
    e.cov(0, 1) = e.cov(1, 0) = c01;
    return e;
}

void writeEstimator(CArchive& a, const rfir::models::CTagEstimator& est) {
    // v3: the registry name, then the estimator's own versioned state.
    a << std::string(est.name());
    est.writeState(a);
}

/** Version 0-2 streams: a kind byte (0 particle filter, 1 smoother) and the
 * whole particle sets / histories in doubles. */
rfir::models::CTagEstimatorPtr readLegacyEstimator(
    CArchive& a, const rfir::models::PointEstimate& est) {
    const auto kind = a.ReadAs<uint8_t>();
    if (kind == 0) {
        rfir::models::TagParticleFilterParams p;
        p.numParticles = a.ReadAs<uint64_t>();
        p.resampling = static_cast<rfir::models::ResamplingScheme>(a.ReadAs<uint8_t>());
        a >> p.essThreshold >> p.rougheningSigma;
        auto pts = readPts(a);
        std::vector<double> w(pts.size());
        for (double& x : w) a >> x;
        const auto upd = a.ReadAs<uint64_t>();
        auto pf = std::make_unique<rfir::models::TagParticleFilter>();
        pf->setState(p, pts, w, upd, est);
        return rfir::models::CTagEstimatorPtr(std::move(pf));
    }
    if (kind != 1)
        throw std::runtime_error("CRFIDTagParticleMap: unknown estimator kind");
    rfir::models::TagFixedLagSmootherParams p;
    p.numParticles = a.ReadAs<uint64_t>();
    p.lag = a.ReadAs<uint64_t>();
    a >> p.stepSigma;
    p.resampling = static_cast<rfir::models::ResamplingScheme>(a.ReadAs<uint8_t>());
    auto pts = readPts(a);
    auto hist = readPts(a);
    const auto head = a.ReadAs<uint64_t>();
    const auto count = a.ReadAs<uint64_t>();
    const auto upd = a.ReadAs<uint64_t>();
    auto ps = std::make_unique<rfir::models::TagFixedLagSmoother>();
    ps->setLegacyState(p, pts, hist, head, count, upd);
    return rfir::models::CTagEstimatorPtr(std::move(ps));
}

rfir::models::CTagEstimatorPtr readEstimator(CArchive& a, uint8_t version,
                                             const rfir::models::PointEstimate& est) {
    if (version < 3) return readLegacyEstimator(a, est);
    const std::string name = readBoundedString(a, kWhat);
    // Parameters come with the state; the factory's defaults are replaced.
    auto e = rfir::models::createTagEstimator(name, {});
    e->readState(a);
    return rfir::models::CTagEstimatorPtr(std::move(e));
}

void writeEntries(CArchive& a,
                  const std::vector<const CRFIDTagParticleMap::TTagEntry*>& v) {
    a.WriteAs<uint64_t>(v.size());
    for (const auto* e : v) {
        a << e->id;
        a.WriteAs<uint64_t>(e->detections);
        a.WriteAs<uint64_t>(e->visits);
        a.WriteAs<uint64_t>(e->lastReadStep);
        a << e->lastReadTravel;
        writeEst(a, e->visitStartEstimate);
        writeEst(a, e->estimate);
        writeEstimator(a, *e->estimator);
        writePts(a, e->sample);  // v2
        writePts(a, e->visitStartSample);
        a.WriteAs<uint64_t>(e->spreadPoses.size());
        for (const auto& q : e->spreadPoses) a << q.x << q.y << q.phi;
        a << e->spreadOrigin.x << e->spreadOrigin.y << e->spreadOrigin.phi
          << e->spreadTravel;
        a.WriteAs<uint64_t>(e->contradicted);  // v4
        a.WriteAs<uint64_t>(e->support);       // v5
        a.WriteAs<uint64_t>(e->againstRun);
        a.WriteAs<uint64_t>(e->reseats);
    }
}

template <class TABLE>
void readEntries(CArchive& a, TABLE& t, uint8_t version) {
    t.clear();
    // An entry takes at least an id, three counts and two estimates on disk.
    const auto n = readBoundedCount64(a, kWhat, B::kMaxMapEntries, 4 + 24 + 80);
    for (uint64_t i = 0; i < n; i++) {
        CRFIDTagParticleMap::TTagEntry e;
        e.id = readBoundedString(a, kWhat);
        e.detections = a.ReadAs<uint64_t>();
        e.visits = a.ReadAs<uint64_t>();
        e.lastReadStep = a.ReadAs<uint64_t>();
        if (version >= 1) a >> e.lastReadTravel;
        e.visitStartEstimate = readEst(a);
        const auto est = readEst(a);
        e.estimator = readEstimator(a, version, est);
        // v3 keeps the cached estimate as written (under samples_visit it is
        // the spread one, not the estimator's own).
        e.estimate = version >= 3 ? est : e.estimator->estimate();
        if (version >= 2) {
            e.sample = readPts(a);
            e.visitStartSample = readPts(a);
            e.spreadPoses.resize(readBoundedCount64(a, kWhat, B::kMaxMapEntries, 24));
            for (auto& q : e.spreadPoses) a >> q.x >> q.y >> q.phi;
            a >> e.spreadOrigin.x >> e.spreadOrigin.y >> e.spreadOrigin.phi >>
                e.spreadTravel;
        }
        if (version >= 4) e.contradicted = a.ReadAs<uint64_t>();
        if (version >= 5) {
            e.support = a.ReadAs<uint64_t>();
            e.againstRun = a.ReadAs<uint64_t>();
            e.reseats = a.ReadAs<uint64_t>();
        } else  // older maps: the reads that did not contradict the tag
            e.support = e.detections - std::min(e.detections, e.contradicted);
        const std::string id = e.id;
        t.emplace(id, std::move(e));
    }
}
}  // namespace

uint8_t CRFIDTagParticleMap::serializeGetVersion() const {
    // 3: estimators by registry name with their own compact state; 4: the
    // outlier mixture's options and the contradicted-read counts; 5: the
    // reseat counts and option (reseat_contradicted); 6: contradict_margin
    // and hold_outvoted; 7: negative_information, its window and minimum
    // reader half-size; 8: robot_negative_information.
    return 8;
}

void CRFIDTagParticleMap::serializeTo(CArchive& out) const {
    out << genericMapParams;
    const auto& io = insertionOptions;
    out << io.estimator;  // v3: a registry name (v0-2: 0 / 1)
    out.WriteAs<uint64_t>(io.params.numParticles);
    out.WriteAs<uint64_t>(io.params.lag);
    out << io.params.stepSigma << io.params.rougheningSigma << io.params.essThreshold;
    out.WriteAs<uint8_t>(static_cast<uint8_t>(io.params.resampling));
    out.WriteAs<uint64_t>(io.seed);
    const auto& lo = likelihoodOptions;
    out.WriteAs<uint8_t>(static_cast<uint8_t>(lo.detection.model));
    out << lo.detection.beta << lo.detection.gaussianSigmaScale;
    out << lo.rangeBearing.sigmaRange << lo.rangeBearing.sigmaBearing;
    out.WriteAs<uint8_t>(static_cast<uint8_t>(lo.robotUpdate));
    out.WriteAs<uint64_t>(lo.revisitMinGap);
    out << lo.rbUseLandmarkCov << lo.revisitMinTravel;            // v1: travel
    out.WriteAs<uint8_t>(static_cast<uint8_t>(io.tagRobotPose));  // v2
    out.WriteAs<uint8_t>(static_cast<uint8_t>(lo.robotLikelihood));
    out.WriteAs<uint64_t>(lo.robotLikelihoodK);
    out << io.spreadCommitTravel;
    out << lo.detection.outlierWeight << lo.detection.outlierLogFloor;  // v4
    out << io.reseatContradicted;                                       // v5
    out << io.contradictMargin << io.holdOutvoted;                      // v6
    out << io.negativeInformation;                                      // v7
    out.WriteAs<uint64_t>(io.negativeWindow);
    out << io.negativeMinHalfSize;
    out << lo.robotNegativeInformation;  // v8
    out << m_landmarkNames;
    out.WriteAs<uint64_t>(m_track[0].steps);
    out.WriteAs<uint64_t>(m_track[1].steps);
    out.WriteAs<uint64_t>(m_totalTouched);
    for (const auto& t : m_track) out << t.travel << t.hasPose << t.lastX << t.lastY;
    writeEntries(out, tags());
    writeEntries(out, landmarks());
}

namespace {
using TInsertionOptions = CRFIDTagParticleMap::TInsertionOptions;
using TLikelihoodOptions = CRFIDTagParticleMap::TLikelihoodOptions;

/** The options of versions 0-3: the estimator, the detection model and the
 * robot-update policy; what a version lacks takes the value it behaved with. */
void readBaseOptions(CArchive& in, uint8_t version, TInsertionOptions& io,
                     TLikelihoodOptions& lo) {
    if (version >= 3)
        io.estimator = readBoundedString(in, kWhat);
    else
        io.estimator = in.ReadAs<uint8_t>() == 0 ? rfir::models::kParticleFilterName
                                                 : rfir::models::kFixedLagSmootherName;
    io.params.numParticles = in.ReadAs<uint64_t>();
    io.params.lag = in.ReadAs<uint64_t>();
    in >> io.params.stepSigma >> io.params.rougheningSigma >> io.params.essThreshold;
    io.params.resampling =
        static_cast<rfir::models::ResamplingScheme>(in.ReadAs<uint8_t>());
    io.seed = in.ReadAs<uint64_t>();
    lo.detection.model = static_cast<rfir::models::DetectionModel>(in.ReadAs<uint8_t>());
    in >> lo.detection.beta >> lo.detection.gaussianSigmaScale;
    in >> lo.rangeBearing.sigmaRange >> lo.rangeBearing.sigmaBearing;
    lo.robotUpdate = static_cast<TRobotUpdatePolicy>(in.ReadAs<uint8_t>());
    lo.revisitMinGap = in.ReadAs<uint64_t>();
    lo.rbUseLandmarkCov = readStrictBool(in, kWhat);
    lo.revisitMinTravel = 0;
    if (version >= 1) in >> lo.revisitMinTravel;
    io.tagRobotPose = TTagRobotPose::Mean;
    lo.robotLikelihood = TRobotLikelihood::TagMean;
    lo.robotLikelihoodK = 12;
    io.spreadCommitTravel = 0;
    if (version < 2) return;
    io.tagRobotPose = static_cast<TTagRobotPose>(in.ReadAs<uint8_t>());
    lo.robotLikelihood = static_cast<TRobotLikelihood>(in.ReadAs<uint8_t>());
    lo.robotLikelihoodK = in.ReadAs<uint64_t>();
    if (lo.robotLikelihoodK < 1 ||
        lo.robotLikelihoodK > TLikelihoodOptions::kMaxRobotLikelihoodK)
        throw std::runtime_error(
            "CRFIDTagParticleMap: robot_likelihood_k = " +
            std::to_string(lo.robotLikelihoodK) + " read from the stream, outside 1.." +
            std::to_string(TLikelihoodOptions::kMaxRobotLikelihoodK));
    in >> io.spreadCommitTravel;
}

/** The robustness options of versions 4-8 (the outlier mixture, reseating,
 * contradict_margin, hold_outvoted, negative_information): maps written
 * before an option behaved without it. */
void readRobustOptions(CArchive& in, uint8_t version, TInsertionOptions& io,
                       TLikelihoodOptions& lo) {
    lo.detection.outlierWeight = 0;
    lo.detection.outlierLogFloor = rfir::models::DetectionModelParams().outlierLogFloor;
    if (version >= 4) in >> lo.detection.outlierWeight >> lo.detection.outlierLogFloor;
    io.reseatContradicted = version >= 5 && readStrictBool(in, kWhat);
    io.contradictMargin = -1;
    io.holdOutvoted = false;
    if (version >= 6) {
        in >> io.contradictMargin;
        io.holdOutvoted = readStrictBool(in, kWhat);
        if (!(io.contradictMargin >= -1 && io.contradictMargin <= 10))
            throw std::runtime_error(
                "CRFIDTagParticleMap: contradict_margin read from the stream "
                "is outside [-1, 10]");
    }
    // Off, the window and half-size at their code defaults.
    io.negativeInformation = 0;
    io.negativeWindow = TInsertionOptions().negativeWindow;
    io.negativeMinHalfSize = TInsertionOptions().negativeMinHalfSize;
    lo.robotNegativeInformation = 0;
    if (version < 7) return;
    in >> io.negativeInformation;
    io.negativeWindow = in.ReadAs<uint64_t>();
    in >> io.negativeMinHalfSize;
    if (!(io.negativeInformation >= 0 && io.negativeInformation <= 0.99) ||
        io.negativeWindow < 1 || io.negativeWindow > 1000000 ||
        !(io.negativeMinHalfSize >= 0 && io.negativeMinHalfSize <= 10))
        throw std::runtime_error(
            "CRFIDTagParticleMap: negative_information, negative_window or "
            "negative_min_half_size read from the stream is out of range");
    if (version < 8) return;
    in >> lo.robotNegativeInformation;
    if (!(lo.robotNegativeInformation >= 0 && lo.robotNegativeInformation <= 0.99))
        throw std::runtime_error(
            "CRFIDTagParticleMap: robot_negative_information read from the stream is "
            "outside [0, 0.99]");
}
}  // namespace

void CRFIDTagParticleMap::serializeFrom(CArchive& in, uint8_t version) {
    if (version > 8) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    in >> genericMapParams;
    readBaseOptions(in, version, insertionOptions, likelihoodOptions);
    readRobustOptions(in, version, insertionOptions, likelihoodOptions);
    m_landmarkNames.resize(rfir::obs::readBoundedCount(in, kWhat, B::kMaxMapEntries, 4));
    for (auto& n : m_landmarkNames) n = readBoundedString(in, kWhat);
    m_track[0] = m_track[1] = TSensorTrack();
    m_notReadTravel = -1;
    m_track[0].steps = in.ReadAs<uint64_t>();
    m_track[1].steps = in.ReadAs<uint64_t>();
    m_totalTouched = in.ReadAs<uint64_t>();
    if (version >= 1)
        for (auto& t : m_track) {
            in >> t.travel;
            t.hasPose = readStrictBool(in, kWhat);
            in >> t.lastX >> t.lastY;
        }
    m_lastTouched = 0;
    readEntries(in, m_tags, version);
    readEntries(in, m_landmarks, version);
}

void CRFIDTagParticleMap::saveToTextFile(const std::string& path) const {
    std::ostringstream ss;
    ss << std::setprecision(9);
    ss << "# rfir tag map: <kind> <id> <x> <y> <sx> <sy> (metres) <reads> "
          "<contradicted>\n";
    auto put = [&](const char* kind, const std::vector<const TTagEntry*>& v) {
        for (const auto* e : v)
            ss << kind << ' ' << e->id << ' ' << e->estimate.mean.x << ' '
               << e->estimate.mean.y << ' '
               << std::sqrt(std::max(0.0, e->estimate.cov(0, 0))) << ' '
               << std::sqrt(std::max(0.0, e->estimate.cov(1, 1))) << ' ' << e->detections
               << ' ' << e->contradicted << '\n';
    };
    put("tag", tags());
    put("landmark", landmarks());
    // Whole or nothing: write a sibling temp file, then rename over the target.
    const std::string tmp = path + ".tmp";
    {
        std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
        if (!f) throw std::runtime_error("cannot write '" + tmp + "'");
        f << ss.str();
        f.close();
        if (!f) throw std::runtime_error("error writing '" + tmp + "'");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw std::runtime_error("cannot rename '" + tmp + "' to '" + path + "'");
    }
}

void CRFIDTagParticleMap::saveMetricMapRepresentationToFile(
    const std::string& filNamePrefix) const {
    saveToTextFile(filNamePrefix + "_tags.txt");
}

void CRFIDTagParticleMap::getVisualizationInto(
    mrpt::opengl::CSetOfObjects& outObj) const {
    if (!genericMapParams.enableSaveAs3DObject) return;
    auto addSet = [&](const std::vector<const TTagEntry*>& v, float r, float g, float b) {
        auto means = mrpt::opengl::CPointCloud::Create();
        auto parts = mrpt::opengl::CPointCloud::Create();
        means->setPointSize(6.0f);
        means->setColor(r, g, b);
        parts->setPointSize(1.5f);
        parts->setColor(r * 0.6f + 0.4f, g * 0.6f + 0.4f, b * 0.6f + 0.4f);
        for (const auto* e : v) {
            means->insertPoint(e->estimate.mean.x, e->estimate.mean.y, 0.001f);
            for (const auto& p : e->particles()) parts->insertPoint(p.x, p.y, 0.0f);
            auto ell = mrpt::opengl::CEllipsoid2D::Create();
            ell->setCovMatrix(e->estimate.cov);
            ell->setQuantiles(2.0f);  // 2-sigma
            ell->setLocation(e->estimate.mean.x, e->estimate.mean.y, 0.002);
            ell->setColor(r, g, b);
            outObj.insert(ell);
        }
        outObj.insert(parts);
        outObj.insert(means);
    };
    addSet(tags(), 0.1f, 0.3f, 0.9f);
    addSet(landmarks(), 0.9f, 0.4f, 0.1f);
}

std::string CRFIDTagParticleMap::asString() const {
    std::ostringstream s;
    s << "rfir::maps::CRFIDTagParticleMap: " << m_tags.size() << " tags, "
      << m_landmarks.size() << " landmarks (" << insertionOptions.estimator
      << ", L=" << insertionOptions.params.numParticles << ")";
    return s.str();
}
