/* rfir: the [tagmap] and [tagmap_likelihood] INI sections of PF-SLAM and
 * PS-SLAM (tagmap_engine.h). */
#include <rfir/models/ini_reader.h>
#include <rfir/slam/tagmap_engine.h>

#include "tagmap_settings.h"

#include <sstream>

namespace rfir::slam {
std::set<std::string> tagMapSections() {
    return {"tagmap", "tagmap_likelihood"};
}

std::shared_ptr<TTagMapSettings> loadTagMapOptions(
    const mrpt::config::CConfigFileBase& ini, TMethod method) {
    auto s = std::make_shared<TTagMapSettings>();
    // The estimator follows the method (per-tag filters for pf, smoothers for
    // ps) and the map's draws the run's --seed: keys saying otherwise are
    // refused rather than silently overridden.
    const std::string kind = method == TMethod::PS ? rfir::models::kFixedLagSmootherName
                                                   : rfir::models::kParticleFilterName;
    if (ini.sectionExists("tagmap") && ini.keyExists("tagmap", "seed"))
        rfir::ini::fail(ini, "tagmap", "seed",
                        "the run's --seed seeds the tag map; remove this key");
    s->insertion.estimator = kind;
    s->insertion.loadFromConfigFile(ini, "tagmap");
    if (s->insertion.estimator != kind)
        rfir::ini::fail(ini, "tagmap", "estimator",
                        "contradicts the method '" + methodName(method) +
                            "', which sets it (pf, fastslam, odometry: "
                            "particle_filter; ps: fixed_lag_smoother); remove the key "
                            "or make it agree");
    s->likelihood.loadFromConfigFile(ini, "tagmap_likelihood");
    return s;
}

std::string dumpTagMapOptions(const std::shared_ptr<TTagMapSettings>& s, uint64_t seed) {
    if (!s) return {};
    auto ins = s->insertion;
    ins.seed = seed;  // the map's draws follow the run's --seed
    std::ostringstream ins_o;
    ins.dumpToTextStream(ins_o);
    // The seed is --seed's (a seed key in [tagmap] is refused): a comment, so
    // that the dump stays a valid --config.
    std::istringstream lines(ins_o.str());
    std::ostringstream o;
    o << "[tagmap]\n";
    for (std::string l; std::getline(lines, l);)
        o << (l.rfind("seed ", 0) == 0 ? "# " + l + " (--seed)" : l) << "\n";
    o << "\n[tagmap_likelihood]\n";
    s->likelihood.dumpToTextStream(o);
    return o.str();
}

}  // namespace rfir::slam
