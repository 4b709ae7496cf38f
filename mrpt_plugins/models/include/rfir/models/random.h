/* rfir: the random generator type every model, filter and simulator draws
 * from. One generator per run is owned by its engine and passed down by
 * reference; code takes a `TRandom&`, never a global.
 *
 * Our own class rather than MRPT's CRandomGenerator: the particle loops draw
 * three Gaussians per robot particle per step, and MRPT's generator (a
 * Mersenne twister behind a Box-Muller draw) costs several times the rest of
 * the loop. xoshiro256++ (Blackman and Vigna 2019), seeded by splitmix64, and
 * a 128-layer ziggurat for the normal draw (Marsaglia and Tsang 2000), with
 * the layer index and the value taken from separate bits of one 64-bit draw.
 * The method names are MRPT's, so that code written for it compiles. */
#pragma once

#include <cmath>
#include <cstdint>

namespace rfir::models {
namespace detail {
/** The ziggurat's layer tables (built once, shared, read-only). */
struct TZigguratTables {
    uint32_t k[128];
    double w[128], f[128];
    TZigguratTables();
};
const TZigguratTables& zigguratTables();
}  // namespace detail

class TRandom {
  public:
    /** Same default seed as MRPT's generator; any seed gives a full stream. */
    explicit TRandom(uint64_t seed = 4357) { randomize(seed); }

    /** Restarts the stream from `seed` (splitmix64 expands it to 256 bits). */
    void randomize(uint64_t seed) {
        uint64_t z = seed;
        for (uint64_t& s : m_s) s = splitmix64(z);
        m_z = &detail::zigguratTables();
    }

    /** 64 uniformly distributed bits (xoshiro256++). */
    uint64_t drawUniform64bit() {
        const uint64_t r = rotl(m_s[0] + m_s[3], 23) + m_s[0];
        const uint64_t t = m_s[1] << 17;
        m_s[2] ^= m_s[0];
        m_s[3] ^= m_s[1];
        m_s[1] ^= m_s[2];
        m_s[0] ^= m_s[3];
        m_s[2] ^= t;
        m_s[3] = rotl(m_s[3], 45);
        return r;
    }
    uint32_t drawUniform32bit() { return uint32_t(drawUniform64bit() >> 32); }
    /** Uniform in [0, 1): the top 53 bits. */
    double drawUniform01() { return double(drawUniform64bit() >> 11) * 0x1.0p-53; }
    /** Uniform in [min, max). */
    double drawUniform(double min, double max) {
        return min + (max - min) * drawUniform01();
    }

    /** Standard normal draw (ziggurat: one 64-bit draw and one multiply in
     * about 99 % of the calls). */
    double drawGaussian1D_normalized() {
        const uint64_t u = drawUniform64bit();
        const unsigned i = unsigned(u & 127);
        const int32_t h = int32_t(uint32_t(u >> 32));
        const uint32_t a = h < 0 ? uint32_t(-int64_t(h)) : uint32_t(h);
        if (a < m_z->k[i]) return double(h) * m_z->w[i];
        return gaussianTail(h, i);
    }
    double drawGaussian1D(double mean, double std) {
        return mean + std * drawGaussian1D_normalized();
    }

  private:
    static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    static uint64_t splitmix64(uint64_t& z) {
        uint64_t r = (z += 0x9E3779B97F4A7C15ULL);
        r = (r ^ (r >> 30)) * 0xBF58476D1CE4E5B9ULL;
        r = (r ^ (r >> 27)) * 0x94D049BB133111EBULL;
        return r ^ (r >> 31);
    }
    /** The ziggurat's slow path: the wedge test or the base layer's tail. */
    double gaussianTail(int32_t h, unsigned i);

    uint64_t m_s[4];
    const detail::TZigguratTables* m_z = nullptr;
};

}  // namespace rfir::models
