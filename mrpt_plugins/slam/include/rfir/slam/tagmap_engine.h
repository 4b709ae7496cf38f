/* rfir: PF-SLAM and PS-SLAM = the robot particle filter (CRobotPoseParticles)
 * + the tag map (rfir::maps::CRFIDTagParticleMap), whose estimator option
 * selects per-tag particle filters (pf) or fixed-lag smoothers (ps). The call
 * order follows the map's robot-update policy: "literal" updates the tags
 * with the predicted robot mean and then weighs the robot (003 Algorithm 1
 * as written); the "revisit" policies weigh first, then update the tags. */
#pragma once

#include <rfir/slam/slam_config.h>

#include <mrpt/config/CConfigFileBase.h>

#include <cstdint>
#include <memory>
#include <set>
#include <string>

namespace rfir::obs {
class CObservationLogHeader;
}

namespace rfir::slam {
class CSlamEngine;

/** INI sections of the tag map: [tagmap] (insertion: estimator, particles,
 * lag, ...) and [tagmap_likelihood] (detection model, robot_update, ...). */
std::set<std::string> tagMapSections();

/** The tag map's options plus how the robot filter uses the map. */
struct TTagMapSettings;
std::shared_ptr<TTagMapSettings> loadTagMapOptions(
    const mrpt::config::CConfigFileBase& ini, TMethod method);
/** The [tagmap] and [tagmap_likelihood] sections as INI text. */
std::string dumpTagMapOptions(const std::shared_ptr<TTagMapSettings>& s, uint64_t seed);

std::unique_ptr<CSlamEngine> makeTagMapEngine(
    const TSlamConfig& cfg, const rfir::obs::CObservationLogHeader& hdr);

}  // namespace rfir::slam
