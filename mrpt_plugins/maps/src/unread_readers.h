/* rfir: the evidence of readers that were polled and did not read a tag
 * ([tagmap] negative_information; docs/slam.md, "Negative information"): a
 * reader whose square holds the tag reads it with probability p_d, so a poll
 * without the tag weighs a tag position p by 1 - p_d P(read at p), P the
 * miss model's square (miss_model.h, the smoother's miss factors' shape).
 * The squares and centres of one observation's large readers are placed
 * once, then asked per tag. */
#pragma once

#include <rfir/models/detection_likelihood.h>  // ReaderArea
#include <rfir/models/miss_model.h>
#include <rfir/models/read_model.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace rfir::maps {

/** A reader's square in the robot frame; throws on a non-positive half-size. */
inline rfir::models::ReaderArea readerArea(const rfir::obs::TRFIDReader& r) {
    if (!(r.halfX > 0) || !(r.halfY > 0))
        throw std::runtime_error("CRFIDTagParticleMap: reader '" + r.id +
                                 "' has a non-positive half-size");
    return {r.x, r.y, r.halfX, r.halfY};
}

/** The reading names tag `id`. */
inline bool readsTag(const std::vector<std::string>& tags, const std::string& id) {
    return std::find(tags.begin(), tags.end(), id) != tags.end();
}

/** m past a reader's square beyond which a miss weighs nothing worth the
 * work (the miss model's P(read) is about 0 a few centimetres out). */
constexpr double kMissReach = 0.3;

/** [tagmap_likelihood] robot_negative_information: the readers of `o` with
 * both half-sizes >= minHalfSize that did not read `id`, whose squares come
 * within kMissReach of the square of `by` (the reader that did: the tag lies about
 * in its square). Robot frame. */
inline std::vector<rfir::models::ReaderArea> readersThatMissed(
    const rfir::obs::CObservationRFIDReaders& o, const rfir::obs::TRFIDReader& by,
    const std::string& id, double minHalfSize) {
    std::vector<rfir::models::ReaderArea> out;
    for (const auto& rd : o.readings) {
        const auto& q = rd.reader;
        if (std::min(q.halfX, q.halfY) < minHalfSize ||
            std::abs(q.x - by.x) > q.halfX + by.halfX + kMissReach ||
            std::abs(q.y - by.y) > q.halfY + by.halfY + kMissReach ||
            readsTag(rd.tags, id))
            continue;
        out.push_back(readerArea(q));
    }
    return out;
}

class CUnreadReaders {
  public:
    /** The readers of `o` with both half-sizes >= minHalfSize, placed by the
     * robot's mean pose; pd = p_d. */
    CUnreadReaders(const rfir::obs::CObservationRFIDReaders& o,
                   const mrpt::math::TPose2D& robot, double minHalfSize, double pd)
        : m_robot(robot), m_c(std::cos(robot.phi)), m_s(std::sin(robot.phi)), m_pd(pd) {
        for (const auto& rd : o.readings) {
            if (std::min(rd.reader.halfX, rd.reader.halfY) < minHalfSize) continue;
            const auto a = readerArea(rd.reader);
            // Beyond reach every particle keeps its weight.
            m_polls.push_back({&rd.tags, a,
                               rfir::models::robotFrameToWorld(robot, m_c, m_s, a.x, a.y),
                               std::max(a.halfX, a.halfY) + kMissReach});
        }
    }
    bool empty() const { return m_polls.empty(); }
    size_t size() const { return m_polls.size(); }

    /** Reader k did not read `id` and its reach holds `tagMean`. */
    bool missed(size_t k, const std::string& id,
                const mrpt::math::TPoint2D& tagMean) const {
        const auto& q = m_polls[k];
        const double dx = tagMean.x - q.centre.x, dy = tagMean.y - q.centre.y;
        return dx * dx + dy * dy <= q.reach * q.reach && !readsTag(*q.tags, id);
    }

    /** log(1 - p_d P(read)) of reader k for a tag at p (miss_model.h: a
     * square whose soft edge lies inside the reader's). */
    double logLik(size_t k, const mrpt::math::TPoint2D& p) const {
        return rfir::models::missLogLikelihood(m_robot, m_c, m_s, m_polls[k].area, p,
                                               m_pd);
    }

  private:
    struct TPoll {
        const std::vector<std::string>* tags;
        rfir::models::ReaderArea area;
        mrpt::math::TPoint2D centre;
        double reach;  //!< m
    };
    std::vector<TPoll> m_polls;
    mrpt::math::TPose2D m_robot;
    double m_c = 1, m_s = 0, m_pd = 0;
};

}  // namespace rfir::maps
