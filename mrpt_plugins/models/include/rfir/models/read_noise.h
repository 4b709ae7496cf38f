/* rfir: noise models of an RFID read, apart from the read model (read_model.h):
 * each maps e (tag minus reader centre, robot frame) and the reader's
 * half-sizes (hx, hy) to an unnormalised log-likelihood (0 at best: only
 * ratios between particles matter), optionally with its gradient wrt e.
 * Inline: they run once per particle and read. */
#pragma once

#include <algorithm>
#include <cmath>

namespace rfir::models {
/** The papers' step model, log of thesis eq. 3.7 with per-axis sigma =
 * half-size: 0 if |ex| < hx and |ey| < hy, else
 * log(beta) - ex^2/(2hx^2) - ey^2/(2hy^2). */
class CStepReadNoise {
  public:
    explicit CStepReadNoise(double beta = 1.618) : m_logBeta(std::log(beta)) {}
    double logLik(double ex, double ey, double hx, double hy,
                  double* grad = nullptr) const {
        // Flat (w = 1) inside the square; outside, a Gaussian tail scaled by
        // beta so that w is about 1 at the edge.
        if (std::abs(ex) < hx && std::abs(ey) < hy) {
            if (grad) grad[0] = grad[1] = 0;
            return 0.0;
        }
        if (grad) grad[0] = -ex / (hx * hx), grad[1] = -ey / (hy * hy);
        return m_logBeta - 0.5 * (ex * ex / (hx * hx) + ey * ey / (hy * hy));
    }

  private:
    double m_logBeta;  //!< hoisted from eq. 3.7
};

/** A plain Gaussian around the reader centre, sigma per axis = scale *
 * half-size: -ex^2/(2sx^2) - ey^2/(2sy^2). */
class CGaussianReadNoise {
  public:
    explicit CGaussianReadNoise(double sigmaScale = 1.0) : m_k(sigmaScale) {}
    double logLik(double ex, double ey, double hx, double hy,
                  double* grad = nullptr) const {
        return logLikSigma(ex, ey, m_k * hx, m_k * hy, grad);
    }
    static double logLikSigma(double ex, double ey, double sx, double sy,
                              double* grad = nullptr) {
        if (grad) grad[0] = -ex / (sx * sx), grad[1] = -ey / (sy * sy);
        return -0.5 * (ex * ex / (sx * sx) + ey * ey / (sy * sy));
    }

  private:
    double m_k;
};

/** The outlier mixture on a base log-likelihood a: a share eps of the reads
 * comes from anywhere, with the flat likelihood `floor` (relative to the base
 * model's best, 1): log((1 - eps) exp(a) + eps floor). A read far from every
 * particle's tag then costs at most log(eps floor) instead of sinking the
 * particle. Linear in the likelihood, so it also applies to a base term
 * already averaged over a tag's samples. eps = 0: a itself. */
class COutlierMixture {
  public:
    COutlierMixture() = default;  // off
    COutlierMixture(double eps, double logFloor)
        : m_on(eps > 0),
          m_log1mEps(std::log1p(-eps)),
          m_logEpsFloor(std::log(eps) + logFloor) {}
    double mix(double a) const {
        if (!m_on) return a;
        const double x = m_log1mEps + a, b = m_logEpsFloor;
        const double hi = std::max(x, b);
        return hi + std::log(std::exp(x - hi) + std::exp(b - hi));
    }

  private:
    bool m_on = false;
    double m_log1mEps = 0, m_logEpsFloor = 0;
};

}  // namespace rfir::models
