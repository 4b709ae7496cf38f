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

namespace rfir::ir {
namespace {
size_t nextPow2(size_t n) {
    size_t p = 1;
    while (p < n) p <<= 1;
    return p;
}

/** Hann-windowed, zero-padded magnitude spectrum of the mean-removed window. */
struct TSpectrum {
    std::vector<double> mag;  //!< |X_k|, k = 0..N/2
    double binHz = 0;
    double wsum = 0, w2sum = 0;  //!< sum of the window and of its square
};

TSpectrum spectrum(const std::vector<float>& x, double rateHz) {
    const size_t n = x.size();
    double mean = 0;
    for (float v : x) mean += v;
    mean /= n;
    // Hann window against leakage; zero-padding to refine the peak search.
    const size_t N = nextPow2(4 * n);
    mrpt::math::CVectorFloat in(N), re, im, mag;
    in.setZero();
    TSpectrum s;
    for (size_t i = 0; i < n; i++) {
        const double w = 0.5 - 0.5 * std::cos(2 * M_PI * i / (n - 1));
        in[i] = float((x[i] - mean) * w);
        s.wsum += w;
        s.w2sum += w * w;
    }
    mrpt::math::fft_real(in, re, im, mag);
    s.binHz = rateHz / N;
    s.mag.resize(N / 2);
    for (size_t k = 0; k < N / 2; k++)
        s.mag[k] = std::hypot(double(re[k]), double(im[k]));
    return s;
}

/** Median magnitude over the bins where no code's fundamental or odd harmonic
 * (up to `maxHarmonic`) can fall, nor the DC/drift leakage: those bins hold
 * noise only. 0 when fewer than `minBins` such bins remain. */
double noiseMedian(const TSpectrum& s, double rateHz, double lobeHz, int maxHarmonic,
                   size_t minBins) {
    std::vector<char> masked(s.mag.size(), 0);
    auto mask = [&](double f) {
        const long lo = std::max<long>(0, long(std::floor((f - lobeHz) / s.binHz)));
        const long hi = std::min<long>(long(s.mag.size()) - 1,
                                       long(std::ceil((f + lobeHz) / s.binHz)));
        for (long k = lo; k <= hi; k++) masked[k] = 1;
    };
    mask(0);
    for (int c = 1; c <= kNumCodes; c++)
        for (int h = 1; h <= maxHarmonic && h * codeFrequencyHz(c) < 0.5 * rateHz; h += 2)
            mask(h * codeFrequencyHz(c));
    std::vector<double> v;
    for (size_t k = 0; k < s.mag.size(); k++)
        if (!masked[k]) v.push_back(s.mag[k]);
    if (v.size() < minBins) return 0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

/** Noise floor: bins clear of harmonics up to the 7th (higher ones are weak
 * and few enough for the median to ignore); at low rates or short windows,
 * where those masks leave too few bins, clear of the fundamentals only. */
double noiseFloor(const TSpectrum& s, double rateHz, double lobeHz) {
    const double m = noiseMedian(s, rateHz, lobeHz, 7, 128);
    return m > 0 ? m : noiseMedian(s, rateHz, lobeHz, 1, 64);
}
}  // namespace

TDecodedIR decodeIRWindow(const std::vector<float>& x, double rateHz,
                          const TDecoderParams& p) {
    if (!(rateHz > 2 * codeFrequencyHz(1)))
        throw std::invalid_argument(
            "decodeIRWindow: rate_hz must exceed twice the lowest code frequency "
            "(200 Hz)");
    if (x.size() < 16 || x.size() / rateHz < kMinWindowSeconds)
        throw std::invalid_argument(
            "decodeIRWindow: window of " + std::to_string(x.size()) + " samples at " +
            std::to_string(rateHz) + " Hz is shorter than " +
            std::to_string(kMinWindowSeconds) + " s (codes 50 Hz apart would merge)");
    const double T = x.size() / rateHz;
    const TSpectrum s = spectrum(x, rateHz);
    // Peak search +-10 Hz: the emitters' frequency tolerance. With the main
    // lobe (+-2/T) it stays within the 50 Hz between codes for T >= 0.06 s.
    const double halfBand = 10.0;
    // Noise: a Rayleigh magnitude whose median is sqrt(2 ln 2) times the std of
    // each complex component (bin std = sigma * sqrt(w2sum / 2)).
    const double med = noiseFloor(s, rateHz, 2.0 / T + halfBand);
    const double compStd = med / std::sqrt(2 * std::log(2.0));
    double amp[kNumCodes];  // sinusoid amplitude per code (volts)
    for (int c = 1; c <= kNumCodes; c++) {
        const double f = codeFrequencyHz(c);
        double peak = 0;
        if (f < 0.5 * rateHz) {
            const long lo = std::max<long>(1, long(std::floor((f - halfBand) / s.binHz)));
            const long hi = std::min<long>(long(s.mag.size()) - 1,
                                           long(std::ceil((f + halfBand) / s.binHz)));
            for (long k = lo; k <= hi; k++) peak = std::max(peak, s.mag[k]);
        }
        // Rician bias: E|A + n|^2 = A^2 + 2 compStd^2.
        const bool above = peak > p.noiseFactor * med;
        const double unbiased =
            std::sqrt(std::max(0.0, peak * peak - 2 * compStd * compStd));
        amp[c - 1] = above ? unbiased * 2.0 / s.wsum : 0.0;
    }
    const double best = *std::max_element(amp, amp + kNumCodes);
    TDecodedIR out;
    out.noiseVolts = compStd / std::sqrt(s.w2sum / 2);
    std::vector<double> levels;
    for (int c = 1; c <= kNumCodes; c++) {
        const double v = amp[c - 1] * M_PI / 2;  // fundamental 2V/pi -> V
        if (v > 0 && v >= p.minVolts && amp[c - 1] >= p.relativeThreshold * best) {
            out.codes.push_back(uint8_t(c));
            levels.push_back(v);
        }
    }
    if (!levels.empty()) {
        std::sort(levels.begin(), levels.end());
        const size_t m = levels.size() / 2;
        out.volts = levels.size() % 2 ? levels[m] : 0.5 * (levels[m - 1] + levels[m]);
    }
    return out;
}

std::vector<float> synthesizeIRWindow(const std::vector<uint8_t>& codes, double volts,
                                      double offset, double rateHz, size_t n,
                                      const std::vector<double>& phases) {
    // Band-limited square wave (its Fourier series below Nyquist), as a
    // receiver's anti-aliasing filter leaves it: V/2 + (2V/pi) sum sin(k w t)/k.
    std::vector<float> x(n, float(offset));
    for (size_t c = 0; c < codes.size(); c++) {
        const double f = codeFrequencyHz(codes[c]);
        const double ph = c < phases.size() ? phases[c] : 0.0;
        for (size_t i = 0; i < n; i++) {
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
