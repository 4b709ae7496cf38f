/* rfir: the ceiling emitter lattice (thesis 5.1). */
#include <rfir/obs/ir_codes.h>
#include <rfir/obs/ir_lattice.h>

#include <cmath>
#include <stdexcept>

namespace rfir::ir {
namespace {
/** Next combination of k codes out of 1..9 in lexicographic order; false when
 * `c` was the last one. */
bool nextCombination(std::vector<uint8_t>& c) {
    const int k = int(c.size());
    for (int i = k - 1; i >= 0; i--) {
        if (c[i] < kNumCodes - (k - 1 - i)) {
            c[i]++;
            for (int j = i + 1; j < k; j++) c[j] = uint8_t(c[j - 1] + 1);
            return true;
        }
    }
    return false;
}

std::vector<uint8_t> firstCombination(int k) {
    std::vector<uint8_t> c(k);
    for (int i = 0; i < k; i++) c[i] = uint8_t(i + 1);
    return c;
}

/** Number of grid lines from lo to hi (borders included) at spacing p. */
int gridCount(double lo, double hi, double p) {
    return int(std::floor((hi - lo) / p + 1e-9)) + 1;
}
}  // namespace

std::vector<TEmitter> makeEmitterLattice(const TRoom& room, const TLatticeParams& p) {
    if (!(room.maxX > room.minX && room.maxY > room.minY))
        throw std::invalid_argument("makeEmitterLattice: empty room");
    if (!(p.pitch > 0))
        throw std::invalid_argument("makeEmitterLattice: pitch must be > 0");
    if (p.withRepeated && p.repeatedCodes.empty())
        throw std::invalid_argument("makeEmitterLattice: no repeated-ID codes");
    for (auto c : p.repeatedCodes)
        if (c < 1 || c > kNumCodes)
            throw std::invalid_argument("makeEmitterLattice: repeated code out of 1..9");
    if (p.uniqueCodesPerId < 2 || p.uniqueCodesPerId > kNumCodes)
        throw std::invalid_argument("makeEmitterLattice: uniqueCodesPerId must be 2..9");

    const int nx = gridCount(room.minX, room.maxX, p.pitch);
    const int ny = gridCount(room.minY, room.maxY, p.pitch);
    std::vector<TEmitter> out;
    if (p.withRepeated) {
        const int n = int(p.repeatedCodes.size());
        const int cols = int(std::ceil(std::sqrt(double(n))));
        const int rows = (n + cols - 1) / cols;
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                TEmitter e;
                const int k = ((i % cols) + cols * (j % rows)) % n;
                e.codes = {p.repeatedCodes[k]};
                e.x = room.minX + i * p.pitch;
                e.y = room.minY + j * p.pitch;
                e.repeated = !p.allUnique;
                out.push_back(e);
            }
    }
    if (p.withUnique)
        for (int j = 0; j + 1 < ny; j++)
            for (int i = 0; i + 1 < nx; i++) {
                TEmitter e;
                e.x = room.minX + (i + 0.5) * p.pitch;
                e.y = room.minY + (j + 0.5) * p.pitch;
                out.push_back(e);
            }
    int k = p.uniqueCodesPerId;
    auto combo = firstCombination(k);
    for (auto& e : out) {
        e.z = p.height;
        if (!e.repeated) {
            if (k > kNumCodes)
                throw std::invalid_argument(
                    "makeEmitterLattice: the room needs more unique IDs than 9 codes "
                    "give");
            e.codes = combo;
            if (!nextCombination(combo) && ++k <= kNumCodes) combo = firstCombination(k);
        }
        e.id = emitterIdFromCodes(e.codes);
    }
    return out;
}

}  // namespace rfir::ir
