/* rfir tests: the stock INIs through every loader. */
#include "ini_keys.h"

#include <rfir/common/ini_file.h>
#include <rfir/common/ini_key_docs.h>
#include <rfir/models/ini_reader.h>
#include <rfir/sim/simulator.h>
#include <rfir/slam/slam_config.h>

#include <rfir/localize/localize_config.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/vector_loadsave.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace rfir_test {
namespace fs = std::filesystem;

std::vector<TStockIni> stockInis() {
    std::vector<TStockIni> out;
    for (const auto& e :
         fs::directory_iterator(std::string(RFIR_SOURCE_DIR) + "/config_ini")) {
        const std::string n = e.path().filename().string();
        // mrpt_*.ini are MRPT programs' INIs (test_mrpt_apps runs them).
        if (e.path().extension() != ".ini" || n.rfind("mrpt_", 0) == 0) continue;
        const auto kind = n.rfind("slam_", 0) == 0 ? TStockIni::Kind::Slam
                          : n == "ir_localize.ini" ? TStockIni::Kind::Localize
                                                   : TStockIni::Kind::Sim;
        out.push_back({e.path().string(), kind});
    }
    std::sort(out.begin(), out.end(),
              [](const TStockIni& a, const TStockIni& b) { return a.file < b.file; });
    return out;
}

void loadWith(const TStockIni& ini, const std::string& section, const std::string& key,
              const std::string& value) {
    const std::string set = section.empty() ? "" : section + "." + key + "=" + value;
    switch (ini.kind) {
        case TStockIni::Kind::Slam: {
            auto m = rfir::common::readIniFile(ini.file);
            if (!section.empty()) m.write(section, key, value);
            rfir::slam::loadSlamConfig(m);
            return;
        }
        case TStockIni::Kind::Sim:
            rfir::sim::loadSimConfig(ini.file, set.empty()
                                                   ? std::vector<std::string>{}
                                                   : std::vector<std::string>{set});
            return;
        case TStockIni::Kind::Localize: {
            rfir::localize::TConfig c;
            c.iniPath = ini.file;
            if (!set.empty()) c.overrides.push_back(set);
            rfir::localize::loadConfig(
                c, std::string(RFIR_SOURCE_DIR) + "/datasets/ir_raw_15s.gt_map.txt");
            return;
        }
    }
}

std::vector<std::pair<std::string, std::string>> keysOf(const std::string& file) {
    mrpt::config::CConfigFileMemory m;
    m.setContent(mrpt::io::file_get_contents(file));
    std::vector<std::string> secs;
    m.getAllSections(secs);
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& s : secs) {
        std::vector<std::string> keys;
        m.getAllKeys(s, keys);
        for (const auto& k : keys) out.emplace_back(s, k);
    }
    return out;
}

std::vector<rfir::ini::TKeySpec> recordAllKeys() {
    const char* names[] = {"rfir-slam", "rfir-sim", "rfir-localize"};
    for (const auto& ini : stockInis()) {
        rfir::ini::setRecording(true, names[int(ini.kind)]);
        loadWith(ini, "", "", "");
    }
    // The slam loaders on an empty INI record the built-in defaults.
    rfir::ini::setRecording(true, "rfir-slam");
    mrpt::config::CConfigFileMemory empty;
    rfir::slam::loadSlamConfig(empty);
    rfir::ini::setRecording(false);
    return rfir::ini::recordedKeys();
}

namespace {
/** A table cell: '|' would end it, '<' start an HTML tag. */
std::string cell(const std::string& s) {
    std::string o;
    for (char c : s)
        o += c == '|' ? "\\|" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : std::string(1, c);
    return o;
}
}  // namespace

std::string referenceTable() {
    std::ostringstream o;
    o << "| program | section | key | meaning | unit | type | default | range |\n"
      << "|---|---|---|---|---|---|---|---|\n";
    for (const auto& k : recordAllKeys()) {
        const auto* d = rfir::common::findKeyDoc(k.program, k.section, k.key);
        o << "| " << k.program << " | " << k.section << " | " << k.key << " | "
          << cell(d ? d->meaning : "(none)") << " | " << cell(d ? d->unit : "") << " | "
          << k.type << " | " << k.def << " | " << k.range << " |\n";
    }
    return o.str();
}
}  // namespace rfir_test
