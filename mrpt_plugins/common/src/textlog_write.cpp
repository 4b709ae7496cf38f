/* rfir: numbers, comparisons and the canonical writer of the text log. */
#include <rfir/common/textlog.h>
#include <rfir/obs/ir_codes.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <ostream>

namespace rfir::common {
namespace {
/** A finite decimal: [+-]? (digits [. digits?] | . digits) ([eE] [+-]? digits)?
 * Hex floats, nan and inf, which from_chars would accept, are refused. */
bool isDecimalSyntax(const std::string& s) {
    size_t i = 0, n = s.size();
    const auto digits = [&]() {
        const size_t b = i;
        while (i < n && s[i] >= '0' && s[i] <= '9') i++;
        return i - b;
    };
    if (i < n && (s[i] == '+' || s[i] == '-')) i++;
    size_t mant = digits();
    if (i < n && s[i] == '.') {
        i++;
        mant += digits();
    }
    if (mant == 0) return false;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-')) i++;
        if (digits() == 0) return false;
    }
    return i == n;
}

template <class T>
std::optional<T> parseAs(const std::string& tok) {
    if (!isDecimalSyntax(tok)) return std::nullopt;
    // from_chars takes no leading '+'; it is locale-independent and exact.
    const char* b = tok.data() + (tok[0] == '+' ? 1 : 0);
    const char* e = tok.data() + tok.size();
    T v{};
    const auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v)) return std::nullopt;
    return v;
}

template <class T>
std::string shortest(T v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    return std::string(buf, r.ptr);
}

int kindRank(TTimedRecord::Kind k) {
    using K = TTimedRecord::Kind;
    switch (k) {
        case K::Odom:
            return 0;
        case K::Rfid:
            return 1;
        case K::Ir:
        case K::IrRaw:
            return 2;
        default:
            return 3;
    }
}
}  // namespace

std::optional<double> parseDecimal(const std::string& tok) {
    return parseAs<double>(tok);
}
std::optional<float> parseDecimalFloat(const std::string& tok) {
    return parseAs<float>(tok);
}
std::string formatNumber(double v) {
    return shortest(v);
}
std::string formatNumber(float v) {
    return shortest(v);
}

const char* kindName(TTimedRecord::Kind k) {
    using K = TTimedRecord::Kind;
    switch (k) {
        case K::Odom:
            return "odom";
        case K::Rfid:
            return "rfid";
        case K::Ir:
            return "ir";
        case K::IrRaw:
            return "ir_raw";
        default:
            return "rb";
    }
}

const rfir::obs::TRFIDReader* TTextLogHeader::findReader(const std::string& id) const {
    for (const auto& r : readers)
        if (r.id == id) return &r;
    return nullptr;
}

const rfir::obs::TIRReceiver* TTextLogHeader::findReceiver(const std::string& id) const {
    for (const auto& r : receivers)
        if (r.id == id) return &r;
    return nullptr;
}

bool TTextLogHeader::operator==(const TTextLogHeader& o) const {
    return readers == o.readers && receivers == o.receivers && rbSensor == o.rbSensor &&
           start == o.start;
}

bool TTimedRecord::operator==(const TTimedRecord& o) const {
    return kind == o.kind && t == o.t && id == o.id && x == o.x && y == o.y &&
           phi == o.phi && tags == o.tags && codes == o.codes && volts == o.volts &&
           rateHz == o.rateHz && samples == o.samples && range == o.range &&
           bearing == o.bearing;
}

void writeTextLogHeader(std::ostream& o, const TTextLogHeader& h) {
    const auto n = [](double v) { return formatNumber(v); };
    o << "format textlog 1\n";
    for (const auto& r : h.readers)
        o << "reader " << r.id << " " << n(r.x) << " " << n(r.y) << " " << n(r.halfX)
          << " " << n(r.halfY) << "\n";
    for (const auto& r : h.receivers)
        o << "receiver " << r.id << " " << n(r.x) << " " << n(r.y) << " " << n(r.z)
          << "\n";
    if (const auto& s = h.rbSensor)
        o << "rb_sensor " << n(s->x) << " " << n(s->y) << " " << n(s->yaw) << " "
          << n(s->maxRange) << " " << n(s->fov) << "\n";
    if (const auto& s = h.start)
        o << "start " << n(s->x) << " " << n(s->y) << " " << n(s->phi) << "\n";
}

void writeTimedRecord(std::ostream& o, const TTimedRecord& r) {
    using K = TTimedRecord::Kind;
    const auto n = [](double v) { return formatNumber(v); };
    o << kindName(r.kind) << " " << n(r.t);
    switch (r.kind) {
        case K::Odom:
            o << " " << n(r.x) << " " << n(r.y) << " " << n(r.phi);
            break;
        case K::Rfid:
            o << " " << r.id;
            for (const auto& t : r.tags) o << " " << t;
            break;
        case K::Ir:
            o << " " << r.id << " " << rfir::ir::formatCodeList(r.codes) << " "
              << n(r.volts);
            break;
        case K::IrRaw:
            o << " " << r.id << " " << n(r.rateHz) << " ";
            for (size_t i = 0; i < r.samples.size(); i++)
                o << (i ? "," : "") << formatNumber(r.samples[i]);
            break;
        case K::Rb:
            o << " " << r.id << " " << formatNumber(r.range) << " "
              << formatNumber(r.bearing);
            break;
    }
    o << "\n";
}

void writeTextLog(std::ostream& o, const TTextLog& log) {
    writeTextLogHeader(o, log.header);
    for (const auto& r : log.records) writeTimedRecord(o, r);
}

void canonicalizeRecordOrder(TTextLog& log) {
    // Records of one instant are contiguous (time is non-decreasing).
    std::stable_sort(log.records.begin(), log.records.end(),
                     [](const TTimedRecord& a, const TTimedRecord& b) {
                         if (a.t != b.t) return a.t < b.t;
                         return kindRank(a.kind) < kindRank(b.kind);
                     });
}

}  // namespace rfir::common
