#include <rfir/common/ini_override.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace rfir::common {
TIniEdit parseIniEdit(const std::string& edit) {
    const auto eq = edit.find('=');
    const auto dot = eq == std::string::npos ? std::string::npos : edit.rfind('.', eq);
    if (eq == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 >= eq)
        throw CUsageError("--set " + edit + ": expected section.key=value");
    return {edit.substr(0, dot), edit.substr(dot + 1, eq - dot - 1), edit.substr(eq + 1)};
}

namespace {
void applyIniOverride(mrpt::config::CConfigFileBase& ini, const std::string& edit) {
    const TIniEdit e = parseIniEdit(edit);
    ini.write(e.section, e.key, e.value);
}
}  // namespace

void applyIniOverrides(mrpt::config::CConfigFileBase& ini,
                       const std::vector<std::string>& edits) {
    for (const auto& e : edits) applyIniOverride(ini, e);
}

namespace {
/** A loader's message about the edit `e`, without the INI's file name before
 * "[section]" (the value is not the file's). */
std::string withoutFileName(const std::string& msg, const TIniEdit& e) {
    const auto at = msg.find(": [" + e.section + "]");
    return at == std::string::npos ? msg : msg.substr(at + 2);
}
}  // namespace

void loadWithIniEdits(const std::vector<std::string>& edits,
                      const std::function<void(const std::vector<std::string>&)>& load) {
    for (const auto& e : edits) parseIniEdit(e);
    try {
        load(edits);
        return;
    } catch (const CUsageError&) {
        throw;
    } catch (const std::exception&) {
        if (edits.empty()) throw;
    }
    load({});  // throws the INI's own error, naming the file
    // The INI alone loads: the edits are to blame, the first that breaks it.
    std::vector<std::string> some;
    for (const auto& e : edits) {
        some.push_back(e);
        try {
            load(some);
        } catch (const CUsageError&) {
            throw;
        } catch (const std::exception& x) {
            throw CUsageError("--set " + e + ": " +
                              withoutFileName(x.what(), parseIniEdit(e)));
        }
    }
}

namespace {
bool knows(const TIniKind& k, const std::string& section) {
    return std::find(k.sections.begin(), k.sections.end(), section) != k.sections.end();
}

std::string listOf(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

/** "simulation INIs (sim:): simulation, robot, ...; SLAM INIs (slam:): ..." */
std::string sectionsHelp(const std::vector<TIniKind>& kinds) {
    std::string s;
    for (const auto& k : kinds)
        s += (s.empty() ? "" : "; ") + k.description + " (" + k.name +
             ":): " + listOf(k.sections);
    return s;
}

/** The kind an edit goes to; `edit` loses its "KIND:" prefix. */
size_t kindOf(const std::vector<TIniKind>& kinds, std::string& edit) {
    const std::string given = edit;
    const auto colon = edit.find(':');
    std::optional<size_t> named;
    if (colon != std::string::npos && colon < edit.find_first_of(".=")) {
        const std::string name = edit.substr(0, colon);
        for (size_t i = 0; i < kinds.size(); i++)
            if (kinds[i].name == name) named = i;
        if (!named)
            throw CUsageError("--set " + given + ": no INI kind '" + name + ":' (" +
                              sectionsHelp(kinds) + ")");
        edit = edit.substr(colon + 1);
    }
    const std::string section = parseIniEdit(edit).section;
    if (named) {
        if (knows(kinds[*named], section)) return *named;
        throw CUsageError("--set " + given + ": [" + section +
                          "]: unknown section in the " + kinds[*named].description +
                          " (known: " + listOf(kinds[*named].sections) + ")");
    }
    std::vector<size_t> found;
    for (size_t i = 0; i < kinds.size(); i++)
        if (knows(kinds[i], section)) found.push_back(i);
    if (found.size() == 1) return found.front();
    if (found.empty())
        throw CUsageError("--set " + given + ": [" + section + "]: unknown section (" +
                          sectionsHelp(kinds) + ")");
    std::string both;
    for (size_t i : found)
        both += (both.empty() ? "" : " or ") + kinds[i].name + ":" + edit;
    throw CUsageError("--set " + given + ": [" + section +
                      "] is a section of several kinds of INI: write " + both);
}
}  // namespace

std::vector<std::vector<std::string>> routeIniEdits(
    const std::vector<TIniKind>& kinds, const std::vector<std::string>& edits) {
    std::vector<std::vector<std::string>> out(kinds.size());
    for (std::string e : edits) {
        const size_t k = kindOf(kinds, e);
        out[k].push_back(e);
    }
    return out;
}
}  // namespace rfir::common
