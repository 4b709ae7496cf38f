/* rfir-bench: the plain reference on the engines' own inputs (TSlamInput),
 * so that every engine figure reads as a multiple of what the method needs.
 * The loop itself is CPlainPsCore (plain_ps_core.h). */
#pragma once

#include <rfir/bench/plain_ps_core.h>
#include <rfir/slam/slam_engine.h>

namespace rfir::bench {
class CPlainPsSlam {
  public:
    explicit CPlainPsSlam(const TPlainOptions& o) : m_core(o) {}
    void reset(const mrpt::poses::CPose2D& start);
    void step(const rfir::slam::TSlamInput& in);
    size_t tagsMapped() const { return m_core.tagsMapped(); }

  private:
    CPlainPsCore m_core;
    std::vector<TPlainRead> m_reads;
};

/** The stock slam_ps.ini [motion] (what the engines read) for the reference. */
TPlainOptions plainOptionsFor(const rfir::slam::TSlamConfig& cfg);

}  // namespace rfir::bench
