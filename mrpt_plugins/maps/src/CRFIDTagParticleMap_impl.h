/* rfir: CRFIDTagParticleMap internals: visits, per-tag updates, the robot's
 * likelihood per read, and the robot- / tag-uncertainty options (included by
 * CRFIDTagParticleMap.cpp and CRFIDTagParticleMap_prior.cpp). */
#pragma once

#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/models/range_bearing.h>
#include <rfir/models/read_model.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include "unread_readers.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservationBearingRange.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rfir::maps {
using rfir::models::PointEstimate;
using rfir::models::ReaderArea;

struct CRFIDTagParticleMapImpl {
    using Map = CRFIDTagParticleMap;
    using Entry = Map::TTagEntry;

    /** The generator of one insert: a fresh MT19937 seeded by splitmix64 of
     * (seed, sensor step). Why per step and not one generator for the run:
     * the map's draws then depend only on (seed, step), not on what was drawn
     * before, so a map copied by serialization (each robot particle of an
     * RBPF keeps its own) continues exactly as the original would, and the
     * result does not depend on how many threads weigh the robot particles
     * (the map is only written between weighings, on one thread). The
     * smoother's random steps come from its own counter-based stream per tag
     * (see TagFixedLagSmoother), for the same reason. */
    static uint32_t stepSeed(uint64_t seed, uint64_t salt) {
        // splitmix64: decorrelates consecutive steps.
        uint64_t z = seed * 0x9E3779B97F4A7C15ULL + salt + 0x632BE59BD9B4E019ULL;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return static_cast<uint32_t>((z ^ (z >> 31)) & 0xFFFFFFFFULL);
    }

    static rfir::models::CTagEstimatorPtr makeEstimator(const Map::TInsertionOptions& o) {
        return rfir::models::createTagEstimator(o.estimator, o.params);
    }

    /** Refreshes the cached estimate and, for robot_likelihood = tag_particles,
     * the K evenly spaced particles of the set the estimate is built from (PF:
     * the resampled set; smoother: the smoothed set). */
    static void refresh(const Map& m, Entry& e) {
        e.estimate = e.estimator->estimate();
        const bool spread = !e.spreadPoses.empty();
        if (!spread &&
            m.likelihoodOptions.robotLikelihood != TRobotLikelihood::TagParticles)
            return;
        auto pts = e.estimator->smoothedParticles();
        if (spread) {
            for (size_t j = 0; j < pts.size(); j++) pts[j] = spreadPoint(e, j, pts[j]);
            e.estimate = rfir::models::weightedEstimate(pts, {});
        }
        if (m.likelihoodOptions.robotLikelihood != TRobotLikelihood::TagParticles) return;
        // Options set in code skip the INI's check; the weighing holds at most
        // kMax terms, so a larger K must not be cut silently.
        if (m.likelihoodOptions.robotLikelihoodK >
            Map::TLikelihoodOptions::kMaxRobotLikelihoodK)
            throw std::invalid_argument(
                "CRFIDTagParticleMap: robot_likelihood_k above " +
                std::to_string(Map::TLikelihoodOptions::kMaxRobotLikelihoodK));
        const size_t n = pts.size(),
                     K = std::min(n, m.likelihoodOptions.robotLikelihoodK);
        e.sample.resize(K);
        for (size_t k = 0; k < K; k++) e.sample[k] = pts[(2 * k + 1) * n / (2 * K)];
    }

    /** SamplesVisit: particle j, placed by the robot mean C, as if the robot
     * had been at the drawn pose S_j: S_j + R(S_j) R(C)^T (p - C). */
    static mrpt::math::TPoint2D spreadPoint(const Entry& e, size_t j,
                                            const mrpt::math::TPoint2D& p) {
        const auto& C = e.spreadOrigin;
        const auto& S = e.spreadPoses[j % e.spreadPoses.size()];
        double lx, ly;
        rfir::models::worldToRobotFrame(C.x, C.y, std::cos(C.phi), std::sin(C.phi), p.x,
                                        p.y, lx, ly);
        return rfir::models::robotFrameToWorld(S, std::cos(S.phi), std::sin(S.phi), lx,
                                               ly);
    }

    /** SamplesVisit: the first visit is over; move the estimator's states for
     * good (the later reads are placed by a robot that has moved on). */
    static void commitSpread(const Map& m, Entry& e) {
        if (e.spreadPoses.empty()) return;
        const auto f = [&](size_t j, const mrpt::math::TPoint2D& p) {
            return spreadPoint(e, j, p);
        };
        e.estimator->moveStates(f);
        e.spreadPoses.clear();
        e.spreadPoses.shrink_to_fit();
        refresh(m, e);
    }

    /** Re-weigh/resample an entry's estimator with a likelihood, refresh cache. */
    static void update(const Map& m, Entry& e, const rfir::models::PointLogLikelihood& f,
                       rfir::models::TRandom& rng) {
        e.estimator->update(f, rng);
        refresh(m, e);
    }

    /** The robot pose that places the reader for one tag particle: the insert
     * pose, or (tag_robot_pose = samples) a pose drawn from the robot set. */
    static const mrpt::math::TPose2D& robotFor(const Map& m, bool drawn,
                                               const mrpt::math::TPose2D& robot,
                                               rfir::models::TRandom& rng) {
        const auto& s = m.m_robotSamples;
        if (!drawn || s.empty()) return robot;
        return s[rng.drawUniform32bit() % s.size()];
    }

    /** A new tag's particles: uniform over the reader's rectangle placed by the
     * robot mean (the papers) or, per particle, by a drawn robot pose. */
    static void initTag(const Map& m, Entry& e, const mrpt::math::TPose2D& robot,
                        const ReaderArea& r, rfir::models::TRandom& rng) {
        const auto mode = m.insertionOptions.tagRobotPose;
        if (mode == TTagRobotPose::Mean || mode == TTagRobotPose::SamplesVisit ||
            m.m_robotSamples.empty()) {
            e.estimator->initUniform(robot, r, rng);
            if (mode == TTagRobotPose::SamplesVisit && !m.m_robotSamples.empty()) {
                e.spreadOrigin = robot;
                e.spreadTravel = m.m_track[0].travel;
                e.spreadPoses.resize(m.insertionOptions.params.numParticles);
                for (auto& q : e.spreadPoses) q = robotFor(m, true, robot, rng);
            }
        } else {
            // Per particle, a robot pose drawn from the robot set places it.
            const auto pts = rfir::models::sampleReaderArea(
                [&] { return robotFor(m, true, robot, rng); }, r,
                m.insertionOptions.params.numParticles, rng);
            e.estimator->initFromPoints(pts);
        }
        refresh(m, e);
    }

    /** Would a read of `e` in the next observation of a sensor whose track is
     * `t` (not yet advanced by that observation) start a new visit? The same
     * test serves the likelihood (before insertion) and the insertion. */
    static bool newVisit(const Map& m, const Entry& e, const Map::TSensorTrack& t) {
        const auto& lo = m.likelihoodOptions;
        return e.visits == 0 || (t.steps - e.lastReadStep >= lo.revisitMinGap &&
                                 t.travel - e.lastReadTravel >= lo.revisitMinTravel);
    }

    /** Advances a sensor's track by one inserted observation at `robot`. */
    static uint64_t advance(Map::TSensorTrack& t, const mrpt::math::TPose2D& robot) {
        if (t.hasPose) t.travel += std::hypot(robot.x - t.lastX, robot.y - t.lastY);
        t.hasPose = true;
        t.lastX = robot.x;
        t.lastY = robot.y;
        return ++t.steps;
    }

    /** Marks a read; starts a new visit (freezing the estimate) if due. `before`
     * is the track as it was before this observation. */
    static void markRead(const Map& m, Entry& e, const Map::TSensorTrack& before,
                         const Map::TSensorTrack& now, size_t reads) {
        if (newVisit(m, e, before)) {
            if (e.visits >= 1 &&
                now.travel - e.spreadTravel >= m.insertionOptions.spreadCommitTravel)
                commitSpread(m, e);
            e.visits++;
            e.visitStartEstimate = e.estimate;
            e.visitStartSample = e.sample;
        }
        e.lastReadStep = now.steps;
        e.lastReadTravel = now.travel;
        e.detections += reads;
    }

    enum class Which { None, Current, VisitStart };
    /** Which estimate (if any) weighs the robot for a read of `e`, per policy. */
    static Which whichForRobot(const Map& m, const Entry& e, const Map::TSensorTrack& t) {
        const auto& lo = m.likelihoodOptions;
        if (lo.robotUpdate == TRobotUpdatePolicy::Literal) return Which::Current;
        // Called before this observation is inserted.
        if (newVisit(m, e, t)) return Which::Current;  // the estimate before this visit
        if (lo.robotUpdate == TRobotUpdatePolicy::RevisitAll && e.visits >= 2)
            return Which::VisitStart;
        return Which::None;  // consecutive re-read (or first pass): nothing new
    }
    static const PointEstimate* estimateForRobot(const Map& m, const Entry& e,
                                                 const Map::TSensorTrack& t) {
        const Which w = whichForRobot(m, e, t);
        return w == Which::None      ? nullptr
               : w == Which::Current ? &e.estimate
                                     : &e.visitStartEstimate;
    }

    /** Robot log-likelihood of one read by reader `r` of a tag with estimate
     * `est`, base model (the caller applies the outlier mixture): against the
     * tag mean, or (tag_particles) log of the mean likelihood over the K
     * stored tag particles `smp`, i.e. the detection likelihood marginalised
     * over the tag's uncertainty (O(K), K <= 64, the INI bound of
     * robot_likelihood_k). c, s: cos and sin of robot.phi, computed once per
     * robot pose by the caller. */
    static double robotReadLogLik(const Map& m, const PointEstimate& est,
                                  const std::vector<mrpt::math::TPoint2D>& smp,
                                  const mrpt::math::TPose2D& robot, double c, double s,
                                  const ReaderArea& r,
                                  const rfir::models::DetectionLikelihood& det) {
        if (m.likelihoodOptions.robotLikelihood != TRobotLikelihood::TagParticles ||
            smp.empty())
            return det.baseLogLikelihood(robot, c, s, r, est.mean);
        constexpr size_t kMax = Map::TLikelihoodOptions::kMaxRobotLikelihoodK;
        double ll[kMax], best = -1e300;
        const size_t K = std::min(smp.size(), kMax);
        for (size_t k = 0; k < K; k++)
            best = std::max(best, ll[k] = det.baseLogLikelihood(robot, c, s, r, smp[k]));
        double sum = 0;
        for (size_t k = 0; k < K; k++) sum += std::exp(ll[k] - best);
        return best + std::log(sum / double(K));
    }

    /** Judges the reads of `e` at this instant (areas from `first` on)
     * against its estimate: a read contradicts it when the model without the
     * mixture gives it less than outlier_log_floor, or when the estimate lies
     * more than contradict_margin outside the read's square. Returns the index
     * of the read at which more reads in a row have contradicted the tag than
     * agreed with it since it was placed (it is then placed again there: a
     * tag mapped from a ghost read, or moved), or areas.size(); `update`
     * gets the reads that update the tag: not that one, nor (hold_outvoted)
     * a contradicting read the agreeing ones still out-vote. */
    static size_t judgeReads(const Map& m, Entry& e, const mrpt::math::TPose2D& robot,
                             const std::vector<ReaderArea>& areas, size_t first,
                             const rfir::models::DetectionLikelihood& det,
                             std::vector<ReaderArea>& update) {
        const auto& io = m.insertionOptions;
        const auto& tag = e.estimate.mean;
        size_t reseat = areas.size();
        update.clear();
        for (size_t k = first; k < areas.size(); k++) {
            if (!det.contradicts(robot, areas[k], tag, io.contradictMargin)) {
                e.support++;
                e.againstRun = 0;
                update.push_back(areas[k]);
                continue;
            }
            e.contradicted++;
            if (++e.againstRun <= e.support && io.holdOutvoted) continue;
            if (e.againstRun > e.support && reseat == areas.size() &&
                io.reseatContradicted) {
                reseat = k;
                continue;
            }
            update.push_back(areas[k]);
        }
        return reseat;
    }

    /** Places `e` again over one reader's square: its former reads no longer
     * count for it, and it starts over as a tag on its first visit: the
     * placement comes from the robot's own pose, so the rest of this visit
     * only refines it, and it weighs the robot from the next visit on (as a
     * new tag does). Weighing the robot against it in the same visit would
     * be the double counting revisit_min_travel keeps out: a 300 mm square
     * places the tag up to 0.15 m off, and the reads of the pass would turn
     * the robot toward that (docs/slam.md, "Reseating contradicted tags"). */
    static void reseatTag(const Map& m, Entry& e, const mrpt::math::TPose2D& robot,
                          const ReaderArea& r, rfir::models::TRandom& rng) {
        initTag(m, e, robot, r, rng);
        e.support = 1;
        e.againstRun = 0;
        e.reseats++;
        e.visits = 1;
        e.visitStartEstimate = e.estimate;
        e.visitStartSample = e.sample;
    }

    enum class TInsert { All, NewTagsOnly };
    static void insertRFID(Map& m, const rfir::obs::CObservationRFIDReaders& o,
                           const mrpt::math::TPose2D& robot,
                           TInsert which = TInsert::All) {
        const Map::TSensorTrack before = m.m_track[0];
        const uint64_t step = advance(m.m_track[0], robot);
        rfir::models::TRandom rng(stepSeed(m.insertionOptions.seed, 2 * step));
        // Group the readers that read each tag at this instant (order kept).
        std::vector<std::pair<std::string, std::vector<ReaderArea>>> groups;
        std::unordered_map<std::string, size_t> where;
        for (const auto& rd : o.readings)
            for (const auto& id : rd.tags) {
                if (which == TInsert::NewTagsOnly && m.m_tags.count(id)) continue;
                auto [it, isNew] = where.emplace(id, groups.size());
                if (isNew) groups.push_back({id, {}});
                groups[it->second].second.push_back(readerArea(rd.reader));
            }
        const rfir::models::DetectionLikelihood det(m.likelihoodOptions.detection);
        for (auto& [id, areas] : groups) {
            auto it = m.m_tags.find(id);
            size_t first = 0;
            if (it == m.m_tags.end()) {
                // New tag: particles over the first detecting reader (geometry
                // from the observation), weighed by any other reader.
                Entry e;
                e.id = id;
                e.support = 1;  // the read that places it
                e.estimator = makeEstimator(m.insertionOptions);
                initTag(m, e, robot, areas[0], rng);
                it = m.m_tags.emplace(id, std::move(e)).first;
                first = 1;
            }
            Entry& e = it->second;
            // Judged against the estimate before this instant's reads move it.
            std::vector<ReaderArea> rest;
            const size_t reseat = judgeReads(m, e, robot, areas, first, det, rest);
            markRead(m, e, before, m.m_track[0], areas.size());
            if (reseat < areas.size()) reseatTag(m, e, robot, areas[reseat], rng);
            if (!rest.empty()) {
                const bool drawn =
                    m.insertionOptions.tagRobotPose == TTagRobotPose::Samples;
                // The mean pose's cos and sin once per tag, not per tag
                // particle (a sincos per particle was 5 % of the floor run).
                const double c0 = std::cos(robot.phi), s0 = std::sin(robot.phi);
                update(
                    m, e,
                    [&](const mrpt::math::TPoint2D& p) {
                        const auto& pose = robotFor(m, drawn, robot, rng);
                        const bool mean = &pose == &robot;
                        const double c = mean ? c0 : std::cos(pose.phi),
                                     sn = mean ? s0 : std::sin(pose.phi);
                        double s = 0;
                        for (const auto& a : rest)
                            s += det.logLikelihood(pose, c, sn, a, p);
                        return s;
                    },
                    rng);
            }
            m.m_lastTouched++;
        }
        // Only the whole observation's polls say which tags were missed.
        if (m.insertionOptions.negativeInformation > 0 && which == TInsert::All)
            notRead(m, o, robot, rng);
    }

    /** negative_information: each polled reader large enough that did not
     * read a recently read tag near it says the tag is not in its square
     * (the smoother's negative factors, in the tag filters: docs/slam.md).
     * Only tags on their first visit, read in the last negative_window
     * observations: their estimates come from this pass's robot. A
     * revisited tag's estimate is older and better than the robot at the
     * revisit, and cutting it with the robot's error moved it (after a
     * kidnapping at 300 mm PS stayed 110-140 mm off for 30 s where without
     * the option it came back to 50-100). And only after the
     * robot moved kNotReadTravel since the last such update: polls from one
     * pose repeat one piece of evidence (a robot stopped, or carried with
     * its odometry frozen, would otherwise push the tags it was reading out
     * of its squares, 0.5^n after n polls). */
    static constexpr double kNotReadTravel = 0.01;  // m
    static void notRead(Map& m, const rfir::obs::CObservationRFIDReaders& o,
                        const mrpt::math::TPose2D& robot, rfir::models::TRandom& rng) {
        const auto& io = m.insertionOptions;
        const CUnreadReaders unread(o, robot, io.negativeMinHalfSize,
                                    io.negativeInformation);
        if (unread.empty()) return;
        const double travel = m.m_track[0].travel;
        if (m.m_notReadTravel >= 0 && travel - m.m_notReadTravel < kNotReadTravel) return;
        m.m_notReadTravel = travel;
        const uint64_t now = m.m_track[0].steps;
        std::vector<size_t> ks;  // the readers that missed one tag
        for (auto& [id, e] : m.m_tags) {
            if (now - e.lastReadStep >= io.negativeWindow || e.visits > 1) continue;
            // One update per tag and observation, the terms of its unread
            // readers summed (their product is the miss likelihood); each
            // reader's reach is judged against the estimate before it. One
            // update per reader cost PS a smoother step each (docs/slam.md,
            // "Its cost").
            ks.clear();
            for (size_t k = 0; k < unread.size(); k++)
                if (unread.missed(k, id, e.estimate.mean)) ks.push_back(k);
            if (ks.empty()) continue;
            update(
                m, e,
                [&](const auto& p) {
                    double s = 0;
                    for (const size_t k : ks) s += unread.logLik(k, p);
                    return s;
                },
                rng);
        }
    }

    static mrpt::math::TPose2D sensorPose(const mrpt::obs::CObservationBearingRange& o,
                                          const mrpt::math::TPose2D& robot) {
        const auto& s = o.sensorLocationOnRobot;
        return sensorPose(s.x(), s.y(), s.yaw(), robot);
    }
    static mrpt::math::TPose2D sensorPose(double sx, double sy, double syaw,
                                          const mrpt::math::TPose2D& robot) {
        return rfir::models::sensorPoseInWorld(robot, {sx, sy, syaw});
    }

    static void insertRB(Map& m, const mrpt::obs::CObservationBearingRange& o,
                         const mrpt::math::TPose2D& robot) {
        const Map::TSensorTrack before = m.m_track[1];
        const uint64_t step = advance(m.m_track[1], robot);
        rfir::models::TRandom rng(stepSeed(m.insertionOptions.seed, 2 * step + 1));
        const auto sensor = sensorPose(o, robot);
        const auto& rb = m.likelihoodOptions.rangeBearing;
        for (const auto& z : o.sensedData) {
            const std::string id = m.landmarkName(z.landmarkID);
            auto it = m.m_landmarks.find(id);
            if (it == m.m_landmarks.end()) {
                // New landmark: samples of the noisy inverse model.
                Entry e;
                e.id = id;
                e.estimator = makeEstimator(m.insertionOptions);
                auto pts = rfir::models::sampleRangeBearingInverse(
                    sensor, z.range, z.yaw, rb, m.insertionOptions.params.numParticles,
                    rng);
                e.estimator->initFromPoints(pts);
                refresh(m, e);
                markRead(m, e, before, m.m_track[1], 1);
                m.m_landmarks.emplace(id, std::move(e));
            } else {
                markRead(m, it->second, before, m.m_track[1], 1);
                update(
                    m, it->second,
                    [&](const mrpt::math::TPoint2D& p) {
                        return rfir::models::rangeBearingLogLikelihood(sensor, p, z.range,
                                                                       z.yaw, rb);
                    },
                    rng);
            }
            m.m_lastTouched++;
        }
    }

    static double rbLogLik(const Map& m, const PointEstimate& est,
                           const mrpt::math::TPose2D& sensor, double range, double yaw) {
        auto p = m.likelihoodOptions.rangeBearing;
        if (m.likelihoodOptions.rbUseLandmarkCov) {
            // Linearised: landmark covariance projected on the range and
            // bearing directions, added to the sensor noise.
            double r, b;
            rfir::models::predictRangeBearing(sensor, est.mean, r, b);
            const double a = sensor.phi + b, c = std::cos(a), s = std::sin(a);
            const auto& P = est.cov;
            const double vr = c * c * P(0, 0) + 2 * c * s * P(0, 1) + s * s * P(1, 1);
            const double vt = s * s * P(0, 0) - 2 * c * s * P(0, 1) + c * c * P(1, 1);
            p.sigmaRange = std::sqrt(p.sigmaRange * p.sigmaRange + vr);
            p.sigmaBearing =
                std::sqrt(p.sigmaBearing * p.sigmaBearing + vt / std::max(r * r, 1e-6));
        }
        return rfir::models::rangeBearingLogLikelihood(sensor, est.mean, range, yaw, p);
    }
};
}  // namespace rfir::maps
