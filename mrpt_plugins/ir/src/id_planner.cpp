/* rfir: emitter-layout planner and ID counts (thesis 5.3). */
#include <rfir/ir/id_planner.h>
#include <rfir/obs/ir_codes.h>

#include <set>
#include <sstream>

namespace rfir::ir {
TPlanReport planLattice(const TRoom& room, const TLatticeParams& p) {
    TPlanReport r;
    r.emitters = makeEmitterLattice(room, p);
    std::set<std::string> ids;
    std::set<double> xs, ys;
    for (const auto& e : r.emitters) {
        ids.insert(e.id);
        if (e.codes.size() == 1) {
            r.repeatedEmitters++;
            xs.insert(e.x);
            ys.insert(e.y);
        } else
            r.uniqueEmitters++;
    }
    r.repeatedGridX = xs.size();
    r.repeatedGridY = ys.size();
    r.distinctIds = ids.size();
    r.uniqueOnlyIds = r.emitters.size();
    r.availableUniqueIds = countIds(kNumCodes, kNumCodes) - kNumCodes;
    r.uniqueOnlyFeasible = r.uniqueOnlyIds <= countIds(kNumCodes, kNumCodes);
    return r;
}

uint64_t mixedLayoutRecords(uint64_t L, uint64_t W, uint64_t repeatedIds) {
    return (L - 1) * (W - 1) + repeatedIds;
}

uint64_t uniqueOnlyLayoutRecords(uint64_t L, uint64_t W) {
    return (L - 1) * (W - 1) + L * W;
}

std::string formatPlanReport(const TPlanReport& r) {
    std::ostringstream o;
    o << "emitters:          " << r.emitters.size() << " (" << r.uniqueEmitters
      << " unique-ID LED arrays, " << r.repeatedEmitters << " repeated-ID single LEDs)\n"
      << "repeated grid:     " << r.repeatedGridX << " x " << r.repeatedGridY << "\n"
      << "IDs used:          " << r.distinctIds
      << " (= microcontrollers, = map records to store)\n"
      << "unique IDs only:   " << r.uniqueOnlyIds
      << " IDs / microcontrollers / records for the same positions"
      << (r.uniqueOnlyFeasible ? "" : " (more than the 511 IDs of 9 codes: infeasible)")
      << "\n";
    if (r.distinctIds)
        o << "saving:            " << r.uniqueOnlyIds - r.distinctIds << " IDs ("
          << (100.0 * double(r.uniqueOnlyIds - r.distinctIds) / double(r.uniqueOnlyIds))
          << " %)\n";
    return o.str();
}

}  // namespace rfir::ir
