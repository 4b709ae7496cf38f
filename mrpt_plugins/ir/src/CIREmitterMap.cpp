/* rfir: CIREmitterMap, the likelihood and the CMetricMap plumbing. */
#include <rfir/common/map_io.h>
#include <rfir/maps/CIREmitterMap.h>
#include <rfir/obs/bounded_read.h>
#include <rfir/obs/ir_codes.h>
#include <rfir/obs/registerAllClasses.h>

#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include <sstream>

using namespace rfir::maps;
using rfir::obs::CObservationIRSignals;

IMPLEMENTS_SERIALIZABLE(CIREmitterMap, CMetricMap, rfir::maps)

namespace rfir::maps {
void registerIRClasses() {
    mrpt::rtti::registerClass(CLASS_ID(CIREmitterMap));
}
}  // namespace rfir::maps

RFIR_REGISTER_CLASS(CIREmitterMap, rfir::maps::CIREmitterMap)

void CIREmitterMap::loadEmitterFile(const std::string& path) {
    m_emitters = rfir::ir::TEmitterSet::load(path);
    m_weights.clear();
}

double CIREmitterMap::verticalDistance(const rfir::ir::TEmitter& e,
                                       const rfir::obs::TIRReceiver& r) const {
    if (likelihoodOptions.verticalDistance > 0) return likelihoodOptions.verticalDistance;
    const double h = e.z - r.z;
    return h > 0 ? h : likelihoodOptions.params.curve.fitHeight;
}

std::optional<size_t> CIREmitterMap::associate(const CObservationIRSignals::TReading& r,
                                               const mrpt::math::TPose2D& robot,
                                               TAssociation how) const {
    if (r.codes.empty()) return std::nullopt;
    const auto* cand = m_emitters.candidates(rfir::ir::emitterIdFromCodes(r.codes));
    if (!cand) return std::nullopt;
    if (cand->size() == 1) return (*cand)[0];
    if (how == TAssociation::Particle)
        return rfir::ir::mostLikelyEmitter(*cand, m_emitters.emitters(),
                                           rfir::ir::receiverInWorld(robot, r.receiver));
    if (!m_reference) return std::nullopt;
    // Eq. 5.1 against the robot estimate (the receiver it places).
    return rfir::ir::mostLikelyEmitter(
        *cand, m_emitters.emitters(),
        rfir::ir::receiverInWorld(*m_reference, r.receiver));
}

bool CIREmitterMap::outOfArea(const CObservationIRSignals& obs,
                              const mrpt::math::TPose2D& robot) const {
    const auto& lp = likelihoodOptions.params;
    if (lp.outOfAreaLogLik == 0 || obs.readings.empty()) return false;
    double x0, y0, x1, y1;
    m_emitters.bounds(x0, y0, x1, y1);
    const double m = lp.areaMargin;
    return robot.x < x0 - m || robot.x > x1 + m || robot.y < y0 - m || robot.y > y1 + m;
}

bool CIREmitterMap::countsAsMiss(const CObservationIRSignals::TReading& r,
                                 const mrpt::math::TPose2D& robot) const {
    const auto& lp = likelihoodOptions.params;
    // A receiver that saw nothing (not an undecoded raw window).
    if (!r.codes.empty() || r.hasRaw() || lp.missLogLik == 0) return false;
    const double h = likelihoodOptions.verticalDistance > 0
                         ? likelihoodOptions.verticalDistance
                         : lp.curve.fitHeight;
    const double R = std::min(rfir::ir::TEmitterSet::kGridCell,
                              lp.missRadiusFraction * lp.curve.visibleRadius(h));
    const auto q = rfir::ir::receiverInWorld(robot, r.receiver);
    // An emitter known to have failed (weight 0) says nothing by its silence.
    const auto k = m_emitters.nearestIndexWithin(q.x, q.y, R);
    return k && (*k >= m_weights.size() || m_weights[*k] != 0);
}

std::optional<CIREmitterMap::TReadingTerm> CIREmitterMap::readingTerm(
    const CObservationIRSignals::TReading& r, const mrpt::math::TPose2D& robot,
    TAssociation how) const {
    const auto idx = associate(r, robot, how);
    if (!idx) return std::nullopt;
    const auto& e = m_emitters.emitters()[*idx];
    return TReadingTerm{*idx,
                        rfir::ir::readingLogLikelihood(
                            r.volts, rfir::ir::receiverInWorld(robot, r.receiver), e,
                            verticalDistance(e, r.receiver), likelihoodOptions.params)};
}

double CIREmitterMap::observationLogLikelihood(const CObservationIRSignals& obs,
                                               const mrpt::math::TPose2D& robot) const {
    return observationLogLikelihood(
        obs, robot, [&](size_t k) { return readingTerm(obs.readings[k], robot); });
}

double CIREmitterMap::internal_computeObservationLikelihood(
    const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& takenFrom) const {
    const auto* ir = dynamic_cast<const CObservationIRSignals*>(&obs);
    if (!ir) return 0;
    return observationLogLikelihood(
        *ir, mrpt::math::TPose2D(takenFrom.x(), takenFrom.y(), takenFrom.yaw()));
}

bool CIREmitterMap::internal_canComputeObservationLikelihood(
    const mrpt::obs::CObservation& obs) const {
    return dynamic_cast<const CObservationIRSignals*>(&obs) != nullptr;
}

void CIREmitterMap::internal_clear() {
    m_emitters = {};
    m_reference.reset();
    m_weights.clear();
}

// The map is known in advance (thesis 5.1): observations do not change it.
bool CIREmitterMap::internal_insertObservation(
    const mrpt::obs::CObservation&, const std::optional<const mrpt::poses::CPose3D>&) {
    return false;
}

void CIREmitterMap::saveMetricMapRepresentationToFile(const std::string& prefix) const {
    const auto f = rfir::common::emitterEntries(m_emitters.emitters());
    rfir::common::saveMapFile(prefix + "_emitters.txt", f, "CIREmitterMap");
}

void CIREmitterMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const {
    if (!genericMapParams.enableSaveAs3DObject) return;
    auto pts = mrpt::opengl::CPointCloudColoured::Create();
    pts->setPointSize(6);
    for (const auto& e : m_emitters.emitters()) {
        // Unique-ID emitters orange, repeated-ID emitters blue.
        const float r = e.repeated ? 0.1f : 1.0f, g = e.repeated ? 0.3f : 0.5f,
                    b = e.repeated ? 1.0f : 0.0f;
        pts->push_back(float(e.x), float(e.y), float(e.z), r, g, b);
    }
    o.insert(pts);
}

std::string CIREmitterMap::asString() const {
    std::ostringstream s;
    s << "CIREmitterMap: " << m_emitters.emitters().size() << " emitters ("
      << m_emitters.uniqueEmitterCount() << " unique-ID, "
      << m_emitters.repeatedEmitterCount() << " repeated-ID), "
      << m_emitters.distinctIdCount() << " IDs";
    return s.str();
}

uint8_t CIREmitterMap::serializeGetVersion() const {
    return 4;
}

void CIREmitterMap::serializeTo(mrpt::serialization::CArchive& out) const {
    const auto& p = likelihoodOptions.params;
    out << p.curve.c0 << p.curve.c1 << p.curve.c2 << p.curve.fitHeight
        << p.curve.maxDistance << uint8_t(p.curve.heightModel) << p.sigmaVolts
        << p.sigmaBelief << p.outOfRangeLogLik << uint8_t(likelihoodOptions.association)
        << likelihoodOptions.verticalDistance << p.missLogLik << p.missRadiusFraction
        << p.areaMargin << p.outOfAreaLogLik << p.outOfRangeRamp << p.voltOutlierWeight
        << p.voltOutlierRange;
    out.WriteAs<uint32_t>(m_emitters.emitters().size());
    for (const auto& e : m_emitters.emitters()) out << e.id << e.x << e.y << e.z;
    out << bool(m_reference);
    if (m_reference) out << m_reference->x << m_reference->y << m_reference->phi;
}

void CIREmitterMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version) {
    if (version > 4) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    auto& p = likelihoodOptions.params;
    uint8_t hm = 0, as = 0;
    in >> p.curve.c0 >> p.curve.c1 >> p.curve.c2 >> p.curve.fitHeight >>
        p.curve.maxDistance >> hm >> p.sigmaVolts >> p.sigmaBelief >>
        p.outOfRangeLogLik >> as >> likelihoodOptions.verticalDistance;
    p.curve.heightModel = rfir::ir::TVoltageCurve::HeightModel(hm);
    if (version >= 1)
        in >> p.missLogLik >> p.missRadiusFraction;
    else {
        p.missLogLik = 0;  // version 0 had no negative information
        p.missRadiusFraction = 0.8;
    }
    if (version >= 2)
        in >> p.areaMargin >> p.outOfAreaLogLik;
    else
        p.outOfAreaLogLik = 0;  // no area term before version 2
    if (version >= 3)
        in >> p.outOfRangeRamp;
    else
        p.outOfRangeRamp = 0;  // a step before version 3
    if (version >= 4)
        in >> p.voltOutlierWeight >> p.voltOutlierRange;
    else {
        p.voltOutlierWeight = 0;  // eq. 5.2 alone before version 4
        p.voltOutlierRange = 4;
    }
    likelihoodOptions.association = TAssociation(as);
    using B = rfir::obs::TReadBounds;
    constexpr const char* kWhat = "CIREmitterMap";
    std::vector<rfir::ir::TEmitter> em(
        rfir::obs::readBoundedCount(in, kWhat, B::kMaxMapEntries, 4 + 24));
    for (auto& e : em) {
        e.id = rfir::obs::readBoundedString(in, kWhat);
        in >> e.x >> e.y >> e.z;
    }
    m_emitters = rfir::ir::TEmitterSet(std::move(em));
    m_weights.clear();
    m_reference.reset();
    if (rfir::obs::readStrictBool(in, kWhat)) {
        mrpt::math::TPose2D r;
        in >> r.x >> r.y >> r.phi;
        m_reference = r;
    }
}
