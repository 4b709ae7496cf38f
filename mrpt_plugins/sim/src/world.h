/* rfir-sim: the simulated world (tag carpet, emitter lattice, landmarks) and
 * the sensor models that read it. */
#pragma once

#include <rfir/models/spatial_grid.h>
#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/obs/ir_lattice.h>
#include <rfir/sim/simulator.h>

#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include "sim_random.h"

#include <string>
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
    rfir::models::TSpatialGrid<size_t> grid_{0.5};
};

/** Builds the tag carpet, the emitter lattice and the landmarks of `cfg`,
 * each from its own generator so that enabling one does not move another. */
TWorld buildWorld(const TSimConfig& cfg, uint64_t seed);

/** Where the faults of one sensing instant go: their own generator (so that
 * the clean streams draw the same numbers with faults on or off) and the
 * ground-truth records (TSimOutput::faults). */
struct TFaultContext {
    rfir::sim::TSimRandom* rng = nullptr;
    std::vector<std::string>* log = nullptr;
    double elapsed = 0;  //!< s from the start (dead-reader intervals)
    double t = 0;        //!< clock time of the instant (the records)
};

/** One RFID poll of the readers `which` (empty: all), with the tags inside
 * each square (the step model of the PF-SLAM paper's eq. 5), each missed with
 * cfg.rfid.missProbability; plus the faults (dead readers, ghosts, empty
 * polls omitted). nullptr when nothing is left to write. */
rfir::obs::CObservationRFIDReaders::Ptr senseRFID(const TSimConfig& cfg, const TWorld& w,
                                                  const mrpt::poses::CPose2D& robot,
                                                  rfir::sim::TSimRandom& rng,
                                                  const std::vector<size_t>& which,
                                                  const TFaultContext& f);

/** One IR reading per receiver (thesis eq. 5.3 plus noise; raw window if so
 * configured), with the wrong-code and voltage-outlier faults. */
rfir::obs::CObservationIRSignals::Ptr senseIR(const TSimConfig& cfg, const TWorld& w,
                                              const mrpt::poses::CPose2D& robot,
                                              rfir::sim::TSimRandom& rng,
                                              const TFaultContext& f);

/** Range and bearing of every landmark in range and field of view. */
mrpt::obs::CObservationBearingRange::Ptr senseRB(const TSimConfig& cfg, const TWorld& w,
                                                 const mrpt::poses::CPose2D& robot,
                                                 rfir::sim::TSimRandom& rng);

/** Noise-free voltage of an emitter at horizontal distance d and vertical
 * distance h: eq. 5.3 scaled by (referenceHeight / h)^2 (inverse-square law;
 * the thesis fitted it at 1.2 m only). */
double modelVoltage(const TIRConfig& ir, double d, double h);

/** A number of a ground-truth fault record (the shortest of 15-17
 * significant digits that reads back exactly). */
std::string faultNumber(double v);

/** Deterministic per-purpose generator seed derived from the run seed. */
uint32_t streamSeed(uint64_t seed, uint64_t stream);

}  // namespace rfir::sim::detail
