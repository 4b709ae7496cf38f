/* rfir-sim: world generation. */
#include "world.h"

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rfir::sim::detail {
uint32_t streamSeed(uint64_t seed, uint64_t stream) {
    // splitmix64 of (seed, stream): well-spread, independent sub-seeds.
    uint64_t z = seed * 0x9E3779B97F4A7C15ULL + (stream + 1) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return uint32_t(z ^ (z >> 32));
}

namespace {
/** Grid coordinates of n = floor(len / pitch) points centred in [lo, lo + len]. */
std::vector<double> gridLine(double lo, double len, double pitch) {
    const int n = std::max(1, int(std::floor(len / pitch + 1e-9)));
    const double off = lo + 0.5 * (len - (n - 1) * pitch);
    std::vector<double> v(n);
    for (int i = 0; i < n; i++) v[i] = off + i * pitch;
    return v;
}

void buildTags(const TSimConfig& cfg, uint64_t seed, TWorld& w) {
    rfir::sim::TSimRandom rng(streamSeed(seed, 1));
    const double pitch = 1.0 / std::sqrt(cfg.rfid.density);
    const auto xs = gridLine(cfg.areaMinX, cfg.areaMaxX - cfg.areaMinX, pitch);
    const auto ys = gridLine(cfg.areaMinY, cfg.areaMaxY - cfg.areaMinY, pitch);
    std::set<std::string> used;
    for (double y : ys)
        for (double x : xs) {
            TPoint t;
            t.x = x + rng.drawGaussian1D(0, cfg.rfid.placementSigma);
            t.y = y + rng.drawGaussian1D(0, cfg.rfid.placementSigma);
            do {
                char hex[9];
                std::snprintf(hex, sizeof(hex), "%08X", unsigned(rng.drawUniform32bit()));
                t.id = cfg.rfid.uidPrefix + hex;
            } while (!used.insert(t.id).second);
            w.tags.push_back(t);
        }
    w.indexTags(0.5);
}

void buildEmitters(const TSimConfig& cfg, uint64_t seed, TWorld& w) {
    rfir::sim::TSimRandom rng(streamSeed(seed, 2));
    const auto& ir = cfg.ir;
    rfir::ir::TLatticeParams lp;
    lp.pitch = ir.pitch;
    lp.height = ir.ceilingHeight;
    lp.repeatedCodes = ir.repeatedCodes;
    lp.uniqueCodesPerId = ir.uniqueCodesPerId;
    lp.withRepeated = ir.withRepeated;
    lp.withUnique = ir.withUnique;
    lp.allUnique = ir.allUnique;
    try {
        w.emitters = rfir::ir::makeEmitterLattice(
            {cfg.areaMinX, cfg.areaMinY, cfg.areaMaxX, cfg.areaMaxY}, lp);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("[ir] ") + e.what());
    }
    for (auto& e : w.emitters)
        if (ir.heightSpread > 0)
            e.z += rng.drawUniform(-ir.heightSpread, ir.heightSpread);
    w.emitterFailed.assign(w.emitters.size(), false);
    for (const auto& f : ir.failed) {
        bool found = false;
        std::istringstream is(f);
        double x = 0, y = 0;
        const bool isXY = bool(is >> x >> y);
        for (size_t i = 0; i < w.emitters.size(); i++) {
            const auto& e = w.emitters[i];
            const bool hit = isXY ? std::hypot(e.x - x, e.y - y) < 0.05 : e.id == f;
            if (hit) w.emitterFailed[i] = found = true;
        }
        if (!found)
            throw std::invalid_argument("[ir] failed: no emitter '" + f +
                                        "' in the lattice");
    }
}

void buildLandmarks(const TSimConfig& cfg, uint64_t seed, TWorld& w) {
    rfir::sim::TSimRandom rng(streamSeed(seed, 3));
    const double area = (cfg.areaMaxX - cfg.areaMinX) * (cfg.areaMaxY - cfg.areaMinY);
    const int n = std::max(1, int(std::lround(cfg.rb.density * area)));
    for (int i = 0; i < n; i++) {
        char id[16];
        std::snprintf(id, sizeof(id), "L%04d", i + 1);
        w.landmarks.push_back({id, rng.drawUniform(cfg.areaMinX, cfg.areaMaxX),
                               rng.drawUniform(cfg.areaMinY, cfg.areaMaxY)});
    }
}
}  // namespace

void TWorld::indexTags(double cell) {
    grid_.reset(cell);
    for (size_t k = 0; k < tags.size(); k++) grid_.insert(tags[k].x, tags[k].y, k);
}

void TWorld::tagsNear(double x, double y, double r, std::vector<size_t>& out) const {
    out.clear();
    grid_.forEachInSquare(x, y, r, [&](size_t k) { out.push_back(k); });
}

TWorld buildWorld(const TSimConfig& cfg, uint64_t seed) {
    TWorld w;
    if (cfg.rfid.enabled) buildTags(cfg, seed, w);
    if (cfg.ir.enabled) buildEmitters(cfg, seed, w);
    if (cfg.rb.enabled) buildLandmarks(cfg, seed, w);
    return w;
}

}  // namespace rfir::sim::detail
