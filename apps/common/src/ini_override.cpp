#include <rfir/common/ini_override.h>

#include <stdexcept>

namespace rfir::common {
void applyIniOverride(mrpt::config::CConfigFileBase& ini, const std::string& edit) {
    const auto eq = edit.find('=');
    const auto dot = eq == std::string::npos ? std::string::npos : edit.rfind('.', eq);
    if (eq == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 >= eq)
        throw std::runtime_error("INI edit (--set) '" + edit + "': expected section.key=value");
    ini.write(edit.substr(0, dot), edit.substr(dot + 1, eq - dot - 1), edit.substr(eq + 1));
}

void applyIniOverrides(mrpt::config::CConfigFileBase& ini,
                       const std::vector<std::string>& edits) {
    for (const auto& e : edits) applyIniOverride(ini, e);
}
}  // namespace rfir::common
