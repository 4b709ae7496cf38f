/* rfir: ID scheme arithmetic and the emitter-layout planner (thesis 5.3):
 * how many IDs, microcontrollers and stored records a lattice of unique and
 * repeated emitters needs, against a layout with unique IDs only. */
#pragma once

#include <rfir/obs/ir_lattice.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rfir::ir {
struct TPlanReport {
    std::vector<TEmitter> emitters;
    size_t uniqueEmitters = 0, repeatedEmitters = 0;
    size_t repeatedGridX = 0, repeatedGridY = 0;  //!< L_r x W_r of thesis 5.3
    /** Distinct IDs = microcontrollers (emitters sharing an ID are driven by one
     * microcontroller, thesis 5.4) = map records a robot must store. */
    size_t distinctIds = 0;
    /** The same positions with unique IDs only. */
    size_t uniqueOnlyIds = 0;
    /** IDs available from 9 codes in combinations of 2..9 (511 - 9 = 502). */
    uint64_t availableUniqueIds = 0;
    bool uniqueOnlyFeasible = false;  //!< uniqueOnlyIds <= all 511 IDs
};

/** Lays out makeEmitterLattice(room, p) and counts (throws like it). */
TPlanReport planLattice(const TRoom& room, const TLatticeParams& p);

/** Thesis 5.3 memory sizes for an L_r x W_r repeated grid with `repeatedIds`
 * repeated IDs: mixed = (L-1)(W-1) + repeatedIds, unique only =
 * (L-1)(W-1) + L W (600 x 400, 9 IDs: 239,010 and 479,001). */
uint64_t mixedLayoutRecords(uint64_t L, uint64_t W, uint64_t repeatedIds);
uint64_t uniqueOnlyLayoutRecords(uint64_t L, uint64_t W);

/** Human-readable summary (several lines). */
std::string formatPlanReport(const TPlanReport& r);

}  // namespace rfir::ir
