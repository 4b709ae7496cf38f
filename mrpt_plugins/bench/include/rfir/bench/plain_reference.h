/* rfir-bench: the plain reference, the cheapest honest PS-SLAM (see
 * plain_reference.cpp). rfir-bench times it on the same inputs as the engine,
 * so that every engine figure reads as a multiple of what the method needs. */
#pragma once

#include <rfir/models/odometry_noise.h>
#include <rfir/slam/slam_engine.h>

#include <memory>

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

class CPlainPsSlam {
  public:
    explicit CPlainPsSlam(const TPlainOptions& o);
    ~CPlainPsSlam();
    void reset(const mrpt::poses::CPose2D& start);
    void step(const rfir::slam::TSlamInput& in);
    size_t tagsMapped() const;

  private:
    struct TImpl;
    std::unique_ptr<TImpl> m_;
};

/** The stock slam_ps.ini [motion] (what the engines read) for the reference. */
TPlainOptions plainOptionsFor(const rfir::slam::TSlamConfig& cfg);

}  // namespace rfir::bench
