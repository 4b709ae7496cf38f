/* rfir-plain-ps: a strict reader of the RFID part of textlog 1, in one pass
 * over the file held in memory (the tag IDs stay views into it). */
#include <rfir/bench/plain_textlog.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace rfir::bench {
namespace {
using Tokens = std::vector<std::string_view>;

struct TParser {
    const std::string& path;
    size_t line = 0;
    TPlainLog& log;
    std::map<std::string_view, TPlainArea> readers;
    bool seenFormat = false, seenTimed = false, hasStart = false, hasOdom = false;
    double lastT = 0, odo[3] = {0, 0, 0};
    size_t odomInstant = 0;  //!< 1 + the instant of the last odom record

    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error(path + ":" + std::to_string(line) + ": " + what);
    }
    double number(std::string_view s, const char* what) const {
        double v = 0;
        const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
        if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v))
            fail(std::string(what) + " '" + std::string(s) + "' is not a finite number");
        return v;
    }
    void id(std::string_view s) const {
        if (s.empty() || s.size() > 64)
            fail("ID '" + std::string(s) + "' is not 1-64 characters");
        for (char c : s)
            if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ||
                  c == ':' || c == '-'))
                fail("ID '" + std::string(s) +
                     "' has a character outside [A-Za-z0-9_.:-]");
    }
    void count(const Tokens& t, size_t n, const char* form) const {
        if (t.size() != n) fail(std::string("expected '") + form + "'");
    }
    void header(const Tokens& t);
    void timed(const Tokens& t);
    void record(const Tokens& t);
};

void TParser::header(const Tokens& t) {
    if (seenTimed) fail("header record '" + std::string(t[0]) + "' after a timed record");
    if (t[0] == "reader") {
        count(t, 6, "reader <reader_id> <x> <y> <half_x> <half_y>");
        id(t[1]);
        const TPlainArea a{number(t[2], "x"), number(t[3], "y"), number(t[4], "half_x"),
                           number(t[5], "half_y")};
        if (a.hx <= 0 || a.hy <= 0) fail("reader half sizes must be > 0");
        if (!readers.emplace(t[1], a).second)
            fail("reader '" + std::string(t[1]) + "' declared twice");
    } else {
        count(t, 4, "start <x> <y> <phi>");
        for (int k = 0; k < 3; k++) log.start[k] = number(t[1 + k], "start pose value");
        hasStart = true;
    }
}

void TParser::timed(const Tokens& t) {
    if (t.size() < 3) fail("timed record '" + std::string(t[0]) + "' has too few fields");
    const double time = number(t[1], "time");
    if (seenTimed && time < lastT) fail("time goes backwards");
    if (!seenTimed || time != lastT) {
        log.instants.push_back({});
        log.instants.back().t = time;
        log.instants.back().firstRead = log.reads.size();
    }
    seenTimed = true, lastT = time;
    auto& in = log.instants.back();
    if (t[0] == "odom") {
        count(t, 5, "odom <t> <x> <y> <phi>");
        const double p[3] = {number(t[2], "x"), number(t[3], "y"), number(t[4], "phi")};
        if (odomInstant == log.instants.size()) fail("two odom records at one instant");
        odomInstant = log.instants.size();
        if (hasOdom) {
            // u = previous (-) current: the increment in the previous pose's frame.
            const double c = std::cos(odo[2]), s = std::sin(odo[2]);
            const double dx = p[0] - odo[0], dy = p[1] - odo[1];
            in.u[0] = c * dx + s * dy, in.u[1] = -s * dx + c * dy;
            in.u[2] = std::remainder(p[2] - odo[2], 2 * M_PI);
            in.hasU = true;
        } else if (!hasStart) {
            for (int k = 0; k < 3; k++) log.start[k] = p[k];  // rfir-slam's rule
        }
        for (int k = 0; k < 3; k++) odo[k] = p[k];
        hasOdom = true;
        return;
    }
    const auto r = readers.find(t[2]);
    if (r == readers.end()) fail("reader '" + std::string(t[2]) + "' was not declared");
    for (size_t k = 3; k < t.size(); k++) {
        id(t[k]);
        log.reads.push_back({r->second, t[k]});
        in.nReads++;
    }
}

void TParser::record(const Tokens& t) {
    if (!seenFormat) {
        if (t.size() != 3 || t[0] != "format" || t[1] != "textlog" || t[2] != "1")
            fail("the first record must be 'format textlog 1'");
        seenFormat = true;
    } else if (t[0] == "reader" || t[0] == "start") {
        header(t);
    } else if (t[0] == "odom" || t[0] == "rfid") {
        timed(t);
    } else if (t[0] == "receiver" || t[0] == "rb_sensor" || t[0] == "ir" ||
               t[0] == "ir_raw" || t[0] == "rb") {
        fail("record '" + std::string(t[0]) +
             "' is not read by the plain reference (RFID logs only)");
    } else {
        fail("unknown record '" + std::string(t[0]) + "'");
    }
}
}  // namespace

TPlainLog loadPlainTextLog(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream ss;
    if (!f || !(ss << f.rdbuf())) throw std::runtime_error(path + ": cannot read");
    return parsePlainTextLog(ss.str(), path);
}

TPlainLog parsePlainTextLog(std::string text, const std::string& path) {
    TPlainLog log;
    log.text = std::make_shared<const std::string>(std::move(text));
    TParser p{path, 0, log, {}};
    Tokens tok;
    const std::string_view all(*log.text);
    for (size_t at = 0; at < all.size();) {
        size_t end = all.find('\n', at);
        if (end == std::string_view::npos) end = all.size();
        std::string_view l = all.substr(at, end - at);
        at = end + 1;
        p.line++;
        l = l.substr(0, l.find('#'));
        tok.clear();
        for (size_t i = 0; i < l.size();) {
            while (i < l.size() && (l[i] == ' ' || l[i] == '\t' || l[i] == '\r')) i++;
            size_t j = i;
            while (j < l.size() && l[j] != ' ' && l[j] != '\t' && l[j] != '\r') j++;
            if (j > i) tok.push_back(l.substr(i, j - i));
            i = j;
        }
        if (!tok.empty()) p.record(tok);
    }
    if (!p.seenFormat) throw std::runtime_error(path + ": empty, no 'format textlog 1'");
    if (log.instants.empty()) throw std::runtime_error(path + ": no timed record");
    return log;
}

}  // namespace rfir::bench
