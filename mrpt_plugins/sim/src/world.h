/* rfir-sim: the simulated world (tag carpet, emitter lattice, landmarks) and
 * the sensor models that read it. */
#pragma once

#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/obs/ir_lattice.h>
#include <rfir/sim/simulator.h>

#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include "sim_random.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace rfir::sim::detail {
struct TPoint {
    std::string id;
    double x = 0, y = 0;
};

struct TWorld {
    std::vector<TPoint> tags;
    std::vector<rfir::ir::TEmitter> emitters;
    std::vector<bool> emitterFailed;  //!< parallel to `emitters`
    std::vector<TPoint> landmarks;

    /** Tags bucketed on a square grid (cell `cell_` m) for fast lookup. */
    void indexTags(double cell);
    /** Indices of the tags within `radius` of (x, y) (a superset: whole cells). */
    void tagsNear(double x, double y, double radius, std::vector<size_t>& out) const;

  private:
    double cell_ = 0.5;
    std::unordered_map<int64_t, std::vector<size_t>> buckets_;
};

/** Builds the tag carpet, the emitter lattice and the landmarks of `cfg`,
 * each from its own generator so that enabling one does not move another. */
TWorld buildWorld(const TSimConfig& cfg, uint64_t seed);

/** One RFID poll: every reader, with the tags inside its square (SPEC 2, the
 * step model), each missed with cfg.rfid.missProbability. */
rfir::obs::CObservationRFIDReaders::Ptr senseRFID(const TSimConfig& cfg, const TWorld& w,
                                                  const mrpt::poses::CPose2D& robot,
                                                  rfir::sim::TSimRandom& rng);

/** One IR reading per receiver (thesis eq. 5.3 plus noise; raw window if so
 * configured). */
rfir::obs::CObservationIRSignals::Ptr senseIR(const TSimConfig& cfg, const TWorld& w,
                                              const mrpt::poses::CPose2D& robot,
                                              rfir::sim::TSimRandom& rng);

/** Range and bearing of every landmark in range and field of view (SPEC 7). */
mrpt::obs::CObservationBearingRange::Ptr senseRB(const TSimConfig& cfg, const TWorld& w,
                                                 const mrpt::poses::CPose2D& robot,
                                                 rfir::sim::TSimRandom& rng);

/** Noise-free voltage of an emitter at horizontal distance d and vertical
 * distance h: eq. 5.3 scaled by (referenceHeight / h)^2 (inverse-square law;
 * the seed fitted it at 1.2 m only). */
double modelVoltage(const TIRConfig& ir, double d, double h);

/** Deterministic per-purpose generator seed derived from the run seed. */
uint32_t streamSeed(uint64_t seed, uint64_t stream);

}  // namespace rfir::sim::detail
