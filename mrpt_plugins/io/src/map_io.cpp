#include <rfir/common/atomic_file.h>
#include <rfir/common/map_io.h>
#include <rfir/common/text_input.h>
#include <rfir/models/printable.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rfir::common {
namespace {
const char* kindName(TMapEntry::Kind k) {
    switch (k) {
        case TMapEntry::Kind::Tag:
            return "tag";
        case TMapEntry::Kind::Emitter:
            return "emitter";
        default:
            return "landmark";
    }
}
}  // namespace

bool isValidId(const std::string& id) {
    if (id.empty() || id.size() > 64) return false;
    for (char c : id)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ||
              c == ':' || c == '-'))
            return false;
    return true;
}

void saveMapFile(const std::string& path, const TMapFile& m, const std::string& hdr) {
    writeFileAtomically(path, [&](std::ostream& o) {
        if (!hdr.empty()) o << "# " << hdr << "\n";
        o << std::fixed << std::setprecision(6);
        for (const auto& e : m) {
            o << kindName(e.kind) << " " << e.id << " " << e.x << " " << e.y;
            if (e.kind == TMapEntry::Kind::Emitter) o << " " << e.z;
            if (e.sx && e.sy) o << " " << *e.sx << " " << *e.sy;
            if (e.sx && e.sy && e.reads && e.contradicted)
                o << " " << *e.reads << " " << *e.contradicted;
            o << "\n";
        }
    });
}

namespace {
/** A read count: a non-negative decimal integer. */
uint64_t count(const std::string& tok, const std::string& where, const char* what) {
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(tok.c_str(), &end, 10);
    if (tok.empty() || tok[0] == '-' || tok[0] == '+' || *end || errno == ERANGE)
        throw std::runtime_error(where + ": " + what + " '" + printable(tok) +
                                 "' is not a non-negative integer");
    return v;
}

double num(const std::string& tok, const std::string& where, const char* what) {
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if (tok.empty() || *end || !std::isfinite(v))
        throw std::runtime_error(where + ": " + what + " '" + printable(tok) +
                                 "' is not a finite number");
    return v;
}
}  // namespace

TMapFile loadMapFile(const std::string& path) {
    std::ifstream f;
    openTextInput(f, path, "map file");
    return loadMapFile(f, path);
}

TMapFile loadMapFile(std::istream& f, const std::string& path) {
    TMapFile out;
    std::set<std::pair<int, std::string>> seen;
    std::string line;
    for (int ln = 1; getBoundedLine(f, line, path, size_t(ln)); ln++) {
        const std::string where = path + ":" + std::to_string(ln);
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        std::istringstream s(line);
        std::vector<std::string> t;
        for (std::string w; s >> w;) t.push_back(w);
        if (t.empty()) continue;
        TMapEntry e;
        size_t nCoords = 2;
        if (t[0] == "tag")
            e.kind = TMapEntry::Kind::Tag;
        else if (t[0] == "landmark")
            e.kind = TMapEntry::Kind::Landmark;
        else if (t[0] == "emitter") {
            e.kind = TMapEntry::Kind::Emitter;
            nCoords = 3;
        } else
            throw std::runtime_error(where + ": unknown record '" + printable(t[0]) +
                                     "' (expected tag, emitter or landmark)");
        if (t.size() != 2 + nCoords && t.size() != 4 + nCoords && t.size() != 6 + nCoords)
            throw std::runtime_error(
                where + ": '" + printable(t[0]) + "' takes " +
                std::to_string(1 + nCoords) + " fields (id and " +
                (nCoords == 3 ? "x y z" : "x y") +
                "), optionally followed by sx sy and then reads contradicted; got " +
                std::to_string(t.size() - 1));
        if (!isValidId(t[1]))
            throw std::runtime_error(where + ": invalid ID '" + printable(t[1]) +
                                     "' (1-64 characters of [A-Za-z0-9_.:-])");
        e.id = t[1];
        e.x = num(t[2], where, "x");
        e.y = num(t[3], where, "y");
        if (nCoords == 3) e.z = num(t[4], where, "z");
        if (t.size() >= 4 + nCoords) {
            e.sx = num(t[2 + nCoords], where, "sx");
            e.sy = num(t[3 + nCoords], where, "sy");
            if (*e.sx < 0 || *e.sy < 0)
                throw std::runtime_error(where + ": standard deviations must be >= 0");
        }
        if (t.size() == 6 + nCoords) {
            e.reads = count(t[4 + nCoords], where, "reads");
            e.contradicted = count(t[5 + nCoords], where, "contradicted");
            if (*e.contradicted > *e.reads)
                throw std::runtime_error(where + ": contradicted " +
                                         std::to_string(*e.contradicted) +
                                         " exceeds reads " + std::to_string(*e.reads));
        }
        e.line = ln;
        // A single-code emitter (ID 1..9) is a repeated-ID emitter: the same ID
        // is installed at many places (textlog.md), so it may recur.
        const bool repeatedEmitter = e.kind == TMapEntry::Kind::Emitter &&
                                     e.id.size() == 1 && e.id[0] >= '1' && e.id[0] <= '9';
        if (!repeatedEmitter && !seen.insert({int(e.kind), e.id}).second)
            throw std::runtime_error(where + ": duplicate " + std::string(t[0]) +
                                     " ID '" + e.id + "'");
        out.push_back(e);
    }
    if (f.bad()) throw std::runtime_error(path + ": read error");
    return out;
}

TMapFile emitterEntries(const std::vector<rfir::ir::TEmitter>& emitters) {
    TMapFile f;
    for (const auto& e : emitters) {
        TMapEntry m;
        m.kind = TMapEntry::Kind::Emitter;
        m.id = e.id;
        m.x = e.x;
        m.y = e.y;
        m.z = e.z;
        f.push_back(m);
    }
    return f;
}

}  // namespace rfir::common
