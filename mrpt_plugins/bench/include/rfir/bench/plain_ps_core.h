/* rfir-bench: the plain reference's PS-SLAM, the cheapest honest loop (see
 * plain_ps_core.cpp). It links no MRPT library, so that rfir-plain-ps loads
 * and runs as a plain single-file program would; rfir-bench also times it in
 * process on the engines' own inputs (plain_reference.h). */
#pragma once

#include <rfir/models/odometry_noise.h>

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace rfir::bench {
/** The stock slam_ps.ini settings the reference hard-codes. */
struct TPlainOptions {
    size_t M = 500;                 //!< robot particles
    size_t J = 100, lag = 25;       //!< per-tag smoother: particles, stored states
    double resampleEss = 0.5;       //!< robot resampling below ESS / M
    double stepSigma = 0.001;       //!< smoother random step (m)
    double beta = 1.618;            //!< step model tail gain
    double revisitMinTravel = 1.0;  //!< m between visits (revisit_all)
    rfir::models::OdometryNoiseParams motion;
    uint64_t seed = 1;
};

/** A reader's square in the robot frame: centre and half-sizes (m). */
struct TPlainArea {
    double x, y, hx, hy;
};

/** One (reader, tag) read; the tag's ID is viewed, not copied. */
struct TPlainRead {
    TPlainArea area;
    std::string_view tag;
};

class CPlainPsCore {
  public:
    explicit CPlainPsCore(const TPlainOptions& o);
    ~CPlainPsCore();
    void reset(double x, double y, double phi);
    /** One sensing instant: the odometry increment u = (dx, dy, dphi), or
     * null, then its n reads. */
    void step(const double* u, const TPlainRead* reads, size_t n);
    size_t tagsMapped() const;
    /** The robot's posterior mean after the last step. */
    void meanPose(double& x, double& y, double& phi) const;

  private:
    struct TImpl;
    std::unique_ptr<TImpl> m_;
};

}  // namespace rfir::bench
