/* rfir: the tag-estimator registry, the one reader-area sampler and the
 * anchored storage helpers. */
#include <rfir/models/anchored_points.h>
#include <rfir/models/tag_estimator.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>

namespace rfir::models {
namespace {
struct TRegistry {
    std::mutex mtx;
    std::map<std::string, TTagEstimatorFactory> byName;
};
TRegistry& registry() {
    static TRegistry r;  // first use, whatever the static-initialisation order
    return r;
}
}  // namespace

std::vector<mrpt::math::TPoint2D> sampleReaderArea(
    const std::function<mrpt::math::TPose2D()>& robotPerPoint, const ReaderArea& r,
    size_t n, TRandom& rng) {
    // Uniform over the reader's rectangle, drawn in the robot frame and placed
    // in the world by the robot pose (003 eq. 6).
    std::vector<mrpt::math::TPoint2D> pts(n);
    for (auto& p : pts) {
        const mrpt::math::TPose2D robot = robotPerPoint();
        ReaderArea off = r;
        off.x = r.x + rng.drawUniform(-r.halfX, r.halfX);
        off.y = r.y + rng.drawUniform(-r.halfY, r.halfY);
        p = readerCentreInWorld(robot, off);
    }
    return pts;
}

std::vector<mrpt::math::TPoint2D> sampleReaderArea(const mrpt::math::TPose2D& robot,
                                                   const ReaderArea& r, size_t n,
                                                   TRandom& rng) {
    return sampleReaderArea([&] { return robot; }, r, n, rng);
}

void CTagEstimator::initUniform(const mrpt::math::TPose2D& robot,
                                const ReaderArea& reader, TRandom& rng) {
    if (numParticles() == 0)
        throw std::invalid_argument(std::string(name()) + ": num_particles = 0");
    initFromPoints(sampleReaderArea(robot, reader, numParticles(), rng));
}

bool registerTagEstimator(const std::string& name, TTagEstimatorFactory f) {
    auto& r = registry();
    std::lock_guard<std::mutex> lock(r.mtx);
    if (!r.byName.emplace(name, std::move(f)).second)
        throw std::logic_error("tag estimator '" + name + "' registered twice");
    return true;
}

std::unique_ptr<CTagEstimator> createTagEstimator(const std::string& name,
                                                  const TTagEstimatorParams& p) {
    TTagEstimatorFactory f;
    {
        auto& r = registry();
        std::lock_guard<std::mutex> lock(r.mtx);
        const auto it = r.byName.find(name);
        if (it != r.byName.end()) f = it->second;
    }
    if (!f) {
        std::ostringstream s;
        s << "unknown tag estimator '" << name << "' (known:";
        for (const auto& n : tagEstimatorNames()) s << ' ' << n;
        s << ')';
        throw std::invalid_argument(s.str());
    }
    return f(p);
}

std::vector<std::string> tagEstimatorNames() {
    auto& r = registry();
    std::lock_guard<std::mutex> lock(r.mtx);
    std::vector<std::string> v;
    for (const auto& kv : r.byName) v.push_back(kv.first);
    return v;
}

TQPoint TAnchor::quantize(const mrpt::math::TPoint2D& p) const {
    const double qx = std::round((p.x - m_x) * kInvQuantum),
                 qy = std::round((p.y - m_y) * kInvQuantum);
    constexpr double lim = 2147483647.0;
    if (!(std::abs(qx) <= lim) || !(std::abs(qy) <= lim)) {
        std::ostringstream s;
        s << "tag state (" << p.x << ", " << p.y << ") more than 2048 m from its anchor ("
          << m_x << ", " << m_y << ") or not finite";
        throw std::range_error(s.str());
    }
    return {static_cast<int32_t>(qx), static_cast<int32_t>(qy)};
}

TAnchor anchorAtMean(const std::vector<mrpt::math::TPoint2D>& pts) {
    double mx = 0, my = 0;
    for (const auto& p : pts) {
        mx += p.x;
        my += p.y;
    }
    const double n = std::max<double>(1, pts.size());
    return TAnchor({mx / n, my / n});
}

TQPoint streamGaussian(uint64_t stream, uint64_t slot, uint64_t particle,
                       double sigmaQuanta) {
    if (sigmaQuanta == 0) return {};
    const uint64_t z = splitmix64(stream ^ splitmix64(slot * 0xD1B54A32D192ED03ULL +
                                                      particle * 0x8CB92BA72F3D8DD7ULL));
    // Two 32-bit uniforms, u1 in (0, 1] so the log is finite.
    const double u1 = (double(z >> 32) + 1.0) * (1.0 / 4294967296.0);
    const double u2 = double(z & 0xFFFFFFFFULL) * (1.0 / 4294967296.0);
    const double r = sigmaQuanta * std::sqrt(-2.0 * std::log(u1));
    const double a = 6.283185307179586 * u2;
    return {static_cast<int32_t>(std::lround(r * std::cos(a))),
            static_cast<int32_t>(std::lround(r * std::sin(a)))};
}

}  // namespace rfir::models
