/* rfir: decodes a raw IR receiver window into frequency codes and a voltage by
 * FFT (textlog.md `ir_raw`; thesis 5.2). */
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rfir::ir {
/** Shortest window the decoder accepts: the Hann main lobe (+-2/T) plus the
 * +-10 Hz peak search must stay inside the 50 Hz spacing of the closest codes. */
constexpr double kMinWindowSeconds = 0.06;

struct TDecoderParams {
    /** A code is present when its spectral amplitude exceeds this fraction of
     * the strongest code's amplitude and the absolute floor below. */
    double relativeThreshold = 0.25;
    /** Minimum on-level (volts) of a square wave to count as present. */
    double minVolts = 0.05;
    /** A code must also stand this many times above the median spectral
     * magnitude of the noise-only bins (a constant-false-alarm-rate floor, so
     * that a window with no emitter decodes to no code whatever the noise). */
    double noiseFactor = 5.0;
};

struct TDecodedIR {
    std::vector<uint8_t> codes;  //!< ascending; empty: no emitter in view
    double volts = 0;            //!< on-level of the square waves
    /** Estimated standard deviation of the sample noise (volts); 0 when the
     * window has too few noise-only frequency bins to tell. */
    double noiseVolts = 0;
};

/** Decodes one window sampled at rateHz. The signal is an offset plus, per code
 * present, a 50 % duty square wave between 0 and V, plus noise. The window must
 * last at least kMinWindowSeconds (codes 50 Hz apart must fall in separate
 * spectral lobes) and the rate must exceed twice the lowest code frequency;
 * std::invalid_argument otherwise. */
TDecodedIR decodeIRWindow(const std::vector<float>& samples, double rateHz,
                          const TDecoderParams& p = {});

/** Synthesizes such a window (for the simulator and the tests); phases in
 * [0, 1) per code, noise added by the caller. */
std::vector<float> synthesizeIRWindow(const std::vector<uint8_t>& codes, double volts,
                                      double offset, double rateHz, size_t n,
                                      const std::vector<double>& phases);

}  // namespace rfir::ir
