/* rfir: FFT decoder of on-off-keyed IR windows. A 50 % duty square wave
 * between 0 and V has a fundamental of amplitude 2V/pi at its own frequency and
 * only odd harmonics, none of which lands on another code's frequency. */
#include <rfir/obs/ir_codes.h>
#include <rfir/obs/ir_decoder.h>

#include <mrpt/math/CVectorDynamic.h>
#include <mrpt/math/fourier.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rfir::ir
{
namespace
{
size_t nextPow2(size_t n)
{
    size_t p = 1;
    while (p < n) p <<= 1;
    return p;
}
}  // namespace

TDecodedIR decodeIRWindow(const std::vector<float>& x, double rateHz,
                          const TDecoderParams& p)
{
    if (rateHz <= 0) throw std::invalid_argument("decodeIRWindow: rate_hz must be > 0");
    if (x.size() < 16) throw std::invalid_argument("decodeIRWindow: window too short");
    const size_t n = x.size();
    double mean = 0;
    for (float v : x) mean += v;
    mean /= n;
    // Hann window against leakage; zero-padding to refine the peak search.
    const size_t N = nextPow2(4 * n);
    mrpt::math::CVectorFloat in(N), re, im, mag;
    in.setZero();
    double wsum = 0;
    for (size_t i = 0; i < n; i++)
    {
        const double w = 0.5 - 0.5 * std::cos(2 * M_PI * i / (n - 1));
        in[i] = float((x[i] - mean) * w);
        wsum += w;
    }
    mrpt::math::fft_real(in, re, im, mag);
    const double binHz = rateHz / N;
    const double halfBand = std::min(20.0, 0.5 * rateHz / n * 2.0);  // +- main lobe
    double amp[kNumCodes];
    for (int c = 1; c <= kNumCodes; c++)
    {
        const double f = codeFrequencyHz(c);
        amp[c - 1] = 0;
        if (f >= 0.5 * rateHz) continue;
        const long lo = std::max<long>(1, long(std::floor((f - halfBand) / binHz)));
        const long hi = std::min<long>(long(N / 2) - 1, long(std::ceil((f + halfBand) / binHz)));
        for (long k = lo; k <= hi; k++)
            amp[c - 1] = std::max(amp[c - 1], std::hypot(double(re[k]), double(im[k])));
        amp[c - 1] *= 2.0 / wsum;  // single-sided amplitude of a sinusoid
    }
    const double best = *std::max_element(amp, amp + kNumCodes);
    TDecodedIR out;
    std::vector<double> levels;
    for (int c = 1; c <= kNumCodes; c++)
    {
        const double v = amp[c - 1] * M_PI / 2;  // fundamental 2V/pi -> V
        if (v >= p.minVolts && amp[c - 1] >= p.relativeThreshold * best)
        {
            out.codes.push_back(uint8_t(c));
            levels.push_back(v);
        }
    }
    if (!levels.empty())
    {
        std::sort(levels.begin(), levels.end());
        out.volts = levels[levels.size() / 2];
    }
    return out;
}

std::vector<float> synthesizeIRWindow(const std::vector<uint8_t>& codes, double volts,
                                      double offset, double rateHz, size_t n,
                                      const std::vector<double>& phases)
{
    // Band-limited square wave (its Fourier series below Nyquist), as a
    // receiver's anti-aliasing filter leaves it: V/2 + (2V/pi) sum sin(k w t)/k.
    std::vector<float> x(n, float(offset));
    for (size_t c = 0; c < codes.size(); c++)
    {
        const double f = codeFrequencyHz(codes[c]);
        const double ph = c < phases.size() ? phases[c] : 0.0;
        for (size_t i = 0; i < n; i++)
        {
            const double t = i / rateHz;
            double s = 0;
            for (int k = 1; k * f < 0.5 * rateHz; k += 2)
                s += std::sin(2 * M_PI * k * (f * t + ph)) / k;
            x[i] += float(volts * (0.5 + 2.0 / M_PI * s));
        }
    }
    return x;
}

}  // namespace rfir::ir
