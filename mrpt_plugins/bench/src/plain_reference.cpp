/* rfir-bench: the plain reference fed the engines' own inputs. The reads
 * view the observation's tag IDs; nothing is copied per read. */
#include <rfir/bench/plain_reference.h>

#include <rfir/obs/CObservationRFIDReaders.h>

namespace rfir::bench {

void CPlainPsSlam::reset(const mrpt::poses::CPose2D& start) {
    m_core.reset(start.x(), start.y(), start.phi());
}

void CPlainPsSlam::step(const rfir::slam::TSlamInput& in) {
    m_reads.clear();
    if (in.rfid)
        for (const auto& rd : in.rfid->readings) {
            const TPlainArea a{rd.reader.x, rd.reader.y, rd.reader.halfX,
                               rd.reader.halfY};
            for (const auto& id : rd.tags) m_reads.push_back({a, id});
        }
    double u[3];
    const auto& inc = in.odometryIncrement;
    if (inc) u[0] = inc->x(), u[1] = inc->y(), u[2] = inc->phi();
    m_core.step(inc ? u : nullptr, m_reads.data(), m_reads.size());
}

TPlainOptions plainOptionsFor(const rfir::slam::TSlamConfig& cfg) {
    TPlainOptions o;
    o.M = cfg.slam.robot_particles;
    o.resampleEss = cfg.slam.resample_ess;
    const auto& mo = cfg.motion;
    o.motion = {mo.a1, mo.a2, mo.a3, mo.a4, mo.min_std_xy, mo.min_std_phi};
    o.seed = cfg.seed;
    return o;
}

}  // namespace rfir::bench
