/* rfir: the ziggurat tables and slow path of TRandom's normal draw
 * (Marsaglia and Tsang 2000, "The ziggurat method for generating random
 * variables", 128 layers, r = 3.442619855899, v = 9.91256303526217e-3). */
#include <rfir/models/random.h>

namespace rfir::models {
namespace detail {
TZigguratTables::TZigguratTables() {
    const double m1 = 2147483648.0;  // 2^31: h is a signed 32-bit draw
    const double vn = 9.91256303526217e-3;
    double dn = 3.442619855899, tn = dn;
    const double q = vn / std::exp(-0.5 * dn * dn);
    k[0] = uint32_t((dn / q) * m1);
    k[1] = 0;
    w[0] = q / m1;
    w[127] = dn / m1;
    f[0] = 1.0;
    f[127] = std::exp(-0.5 * dn * dn);
    for (int i = 126; i >= 1; i--) {
        dn = std::sqrt(-2.0 * std::log(vn / dn + std::exp(-0.5 * dn * dn)));
        k[i + 1] = uint32_t((dn / tn) * m1);
        tn = dn;
        f[i] = std::exp(-0.5 * dn * dn);
        w[i] = dn / m1;
    }
}

const TZigguratTables& zigguratTables() {
    static const TZigguratTables t;
    return t;
}
}  // namespace detail

double TRandom::gaussianTail(int32_t h, unsigned i) {
    constexpr double r = 3.442619855899;
    // Uniform in (0, 1), never 0: the tail takes its logarithm.
    const auto open01 = [this]() {
        return (double(drawUniform64bit() >> 11) + 0.5) * 0x1.0p-53;
    };
    for (;;) {
        const double x = double(h) * m_z->w[i];
        if (i == 0) {
            // Base layer: the tail beyond r (Marsaglia's exponential method).
            double xt, y;
            do {
                xt = -std::log(open01()) / r;
                y = -std::log(open01());
            } while (y + y < xt * xt);
            return h > 0 ? r + xt : -r - xt;
        }
        // Wedge between layers i and i-1: accept under the density.
        if (m_z->f[i] + open01() * (m_z->f[i - 1] - m_z->f[i]) < std::exp(-0.5 * x * x))
            return x;
        const uint64_t u = drawUniform64bit();
        i = unsigned(u & 127);
        h = int32_t(uint32_t(u >> 32));
        const uint32_t a = h < 0 ? uint32_t(-int64_t(h)) : uint32_t(h);
        if (a < m_z->k[i]) return double(h) * m_z->w[i];
    }
}

}  // namespace rfir::models
