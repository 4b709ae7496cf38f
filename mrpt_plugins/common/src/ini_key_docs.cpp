/* rfir: the INI key table's lookup, settings.ini comments and --help-keys. */
#include <rfir/common/ini_key_docs.h>

#include "ini_key_docs_tables.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <fnmatch.h>

#include <sstream>

namespace rfir::common {
const char* const kHelpKeysHelp =
    "list every INI key of the chosen configuration (with --config, --set) with its "
    "value, unit, type, default, range and meaning, and exit";

namespace {
void append(std::vector<TKeyDoc>& out, const char* program,
            const std::vector<detail::TKeyRow>& rows) {
    for (const auto& r : rows)
        out.push_back({program, r.section, r.key, r.unit, r.meaning});
}

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return {};
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

/** Words of `text` in lines of at most `width` characters, each led by `lead`. */
std::string wrapped(const std::string& text, const std::string& lead, size_t width) {
    std::istringstream in(text);
    std::string word, line, out;
    while (in >> word) {
        if (!line.empty() && lead.size() + line.size() + 1 + word.size() > width) {
            out += lead + line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty()) out += lead + line + "\n";
    return out;
}

std::string withUnit(const TKeyDoc& d) {
    return d.unit == "-" ? d.meaning : d.meaning + " [" + d.unit + "]";
}
}  // namespace

const std::vector<TKeyDoc>& iniKeyDocs() {
    static const std::vector<TKeyDoc> docs = [] {
        std::vector<TKeyDoc> v;
        append(v, "rfir-localize", detail::localizeKeyRows());
        append(v, "rfir-sim", detail::simKeyRows());
        append(v, "rfir-slam", detail::slamKeyRows());
        return v;
    }();
    return docs;
}

const TKeyDoc* findKeyDoc(const std::string& program, const std::string& section,
                          const std::string& key) {
    for (const auto& d : iniKeyDocs())
        if (d.program == program && d.key == key &&
            fnmatch(d.section.c_str(), section.c_str(), 0) == 0)
            return &d;
    return nullptr;
}

std::string annotateIni(const std::string& iniText, const std::string& program) {
    std::istringstream in(iniText);
    std::string line, section, out;
    while (std::getline(in, line)) {
        const std::string t = trim(line);
        const auto eq = t.find('=');
        if (!t.empty() && t.front() == '[' && t.back() == ']') {
            section = trim(t.substr(1, t.size() - 2));
        } else if (eq != std::string::npos && t[0] != '#' && t[0] != ';' &&
                   t.rfind("//", 0) != 0) {
            if (const auto* d = findKeyDoc(program, section, trim(t.substr(0, eq))))
                out += wrapped(withUnit(*d), "# ", 80);
        }
        out += line + "\n";
    }
    return out;
}

std::string describeKeys(const std::string& program,
                         const std::function<std::string()>& load) {
    rfir::ini::setRecording(true, program);
    std::string effective;
    try {
        effective = load();
    } catch (...) {
        rfir::ini::setRecording(false);
        throw;
    }
    rfir::ini::setRecording(false);
    const mrpt::config::CConfigFileMemory values(effective);
    std::ostringstream o;
    std::string section;
    for (const auto& k : rfir::ini::recordedKeys()) {
        if (k.program != program) continue;
        if (k.section != section)
            o << (section.empty() ? "" : "\n") << "[" << k.section << "]\n";
        section = k.section;
        const TKeyDoc* d = findKeyDoc(program, k.section, k.key);
        std::string v = trim(values.read_string(k.section, k.key, "", false));
        if (v.empty()) v = k.def;
        o << k.key << " = " << v << "\n"
          << wrapped((d ? withUnit(*d) : "(no description)"), "    ", 90) << "    "
          << k.type << ", default " << k.def << ", range " << k.range << "\n";
    }
    return o.str();
}
}  // namespace rfir::common
