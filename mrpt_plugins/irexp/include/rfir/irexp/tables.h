/* rfir-ir-experiments: the experiments of thesis chapter 5 (section 5.4,
 * tables 5.2 and 5.3) and our own checks, each rendered as markdown. */
#pragma once

#include <rfir/irexp/runs.h>

#include <string>
#include <vector>

namespace rfir::irexp {
struct TOptions {
    int seeds = 5;               //!< seeds per table row
    int sweepSeeds = 20;         //!< seeds per point of the particle-count sweep
    bool quick = false;          //!< fewer rows and seeds (a smoke test)
    std::string imgDir;          //!< figures (docs/img)
    std::string imgRel = "img";  //!< figure folder relative to the markdown
};

/** Markdown helpers (mm and rad, as the thesis' tables). */
std::string tableHeader(const std::string& first);
std::string statsRow(const std::string& label, const rfir::eval::TErrorStats& s);
std::string fmt(double v, int decimals);

// Each returns a markdown section; figures go to opt.imgDir.
std::string expConfigurations(const TExperimentRun& s, const TOptions& opt);  // 5.4.1-2
std::string expRotation(const TExperimentRun& s, const TOptions& opt);        // 5.4.3
std::string expSpeeds(const TExperimentRun& s, const TOptions& opt);          // 5.4.4
std::string expFailures(const TExperimentRun& s, const TOptions& opt);        // 5.4.5
std::string expHeights(const TExperimentRun& s, const TOptions& opt);         // table 5.3
std::string expAssociation(const TExperimentRun& s, const TOptions& opt);     // ours
std::string expParticles(const TExperimentRun& s, const TOptions& opt);       // ours: M
std::string expRawAndDecoder(const TExperimentRun& s, const TOptions& opt);   // ours

}  // namespace rfir::irexp
