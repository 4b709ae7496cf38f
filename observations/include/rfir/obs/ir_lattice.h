/* rfir: the ceiling emitter lattice of the thesis (5.1, fig. 5.1 and 5.9):
 * repeated-ID emitters (one LED, one code) on a square grid of pitch p, and a
 * unique-ID emitter (an LED array, several codes) in the centre of every four. */
#pragma once

#include <rfir/obs/ir_voltage_curve.h>  // TVoltageCurve, eq. 5.3

#include <cstdint>
#include <string>
#include <vector>

namespace rfir::ir {
struct TRoom {
    double minX = 0, minY = 0, maxX = 0, maxY = 0;  //!< metres
};

struct TEmitter {
    std::string id;              //!< ascending codes written together ("39")
    std::vector<uint8_t> codes;  //!< ascending, 1..9
    double x = 0, y = 0, z = 0;  //!< z: height above the floor (m)
    bool repeated = false;       //!< single-code emitter, ID used many times
};

struct TLatticeParams {
    double pitch = 0.8;   //!< distance between two emitters of the same type (m)
    double height = 1.5;  //!< emitter height above the floor (m)
    /** Codes of the repeated-ID emitters, tiled so that grid neighbours differ:
     * with n codes, a ceil(sqrt(n)) x ceil(n / ceil(sqrt(n))) tile (4 codes: 2x2,
     * as in the thesis' room). Must be non-empty. */
    std::vector<uint8_t> repeatedCodes{1, 2, 3, 4};
    /** Unique IDs are the combinations of this many codes (>= 2, so that they
     * never equal a repeated ID) in lexicographic order, then of one more code
     * when those run out. */
    int uniqueCodesPerId = 2;
    /** Leave out one type of emitter. */
    bool withRepeated = true, withUnique = true;
    /** Give the repeated-ID positions unique IDs too (the thesis' comparison
     * layout with unique-ID emitters only, section 5.4.1). */
    bool allUnique = false;
};

/** Repeated-ID emitters at (minX + i p, minY + j p) for every such point inside
 * the room (borders included), then unique-ID emitters at the centres of the
 * grid cells, each group in row-major order (j, then i); unique IDs are handed
 * out in that order. Throws std::invalid_argument on
 * a bad room or parameters, or if the room needs more unique IDs than the
 * 9 codes give. */
std::vector<TEmitter> makeEmitterLattice(const TRoom& room, const TLatticeParams& p = {});

}  // namespace rfir::ir
