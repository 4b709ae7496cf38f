/* rfir: strict parser of the plain-text sensor log, version 1. Every rule of
 * the format is checked here; a malformed line is never skipped. */
#include <rfir/common/map_io.h>
#include <rfir/common/text_input.h>
#include <rfir/common/textlog.h>
#include <rfir/models/printable.h>
#include <rfir/obs/ir_codes.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace rfir::common {
namespace {
std::vector<std::string> tokenize(const std::string& line) {
    std::vector<std::string> tok;
    const size_t end = std::min(line.find('#'), line.size());
    size_t i = 0;
    while (i < end) {
        while (i < end && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) i++;
        size_t j = i;
        while (j < end && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') j++;
        if (j > i) tok.push_back(line.substr(i, j - i));
        i = j;
    }
    return tok;
}

bool isHeaderKind(const std::string& k) {
    return k == "reader" || k == "receiver" || k == "rb_sensor" || k == "start";
}

std::string quoted(const std::string& s) {
    return "'" + printable(s.size() > 80 ? s.substr(0, 77) + "..." : s) + "'";
}
}  // namespace

void CTextLogParser::fail(const std::string& msg) const {
    throw TextLogError(file_, line_, msg);
}

void CTextLogParser::checkFieldCount(const std::vector<std::string>& tok, size_t n,
                                     const char* fields) const {
    if (tok.size() != n + 1)
        fail(quoted(tok[0]) + " takes " + std::to_string(n) + " fields (" + fields +
             "), got " + std::to_string(tok.size() - 1));
}

double CTextLogParser::number(const std::string& tok, const char* what) const {
    if (const auto v = parseDecimal(tok)) return *v;
    std::string low;
    for (char c : tok) low += char(std::tolower(static_cast<unsigned char>(c)));
    if (low.find("nan") != std::string::npos || low.find("inf") != std::string::npos)
        fail(std::string(what) + " " + quoted(tok) +
             " is not a finite number (nan and inf are not allowed)");
    fail(std::string(what) + " " + quoted(tok) + " is not a finite decimal number");
}

double CTextLogParser::positive(const std::string& tok, const char* what) const {
    const double v = number(tok, what);
    if (!(v > 0)) fail(std::string(what) + " must be > 0, got " + tok);
    return v;
}

double CTextLogParser::angle(const std::string& tok, const char* what) const {
    const double v = number(tok, what);
    if (!(v > -M_PI && v <= M_PI))
        fail(std::string(what) + " must be an angle in (-pi, pi] radians, got " + tok);
    return v;
}

float CTextLogParser::floatField(const std::string& tok, const char* what,
                                 bool isAngle) const {
    // The range check is on the written value; the stored float is the
    // decimal's own nearest float (not a double rounded twice).
    isAngle ? angle(tok, what) : positive(tok, what);
    const auto f = parseDecimalFloat(tok);
    if (!f || (!isAngle && *f == 0))
        fail(std::string(what) + " " + quoted(tok) + " is outside the range of a float");
    float v = *f;
    if (isAngle && !(double(v) > -M_PI && double(v) <= M_PI)) v = std::nextafter(v, 0.f);
    return v;
}

std::string CTextLogParser::id(const std::string& tok, const char* what) const {
    if (tok.size() > 64)
        fail(std::string(what) + " " + quoted(tok) + " is longer than 64 characters");
    if (!isValidId(tok))
        fail(std::string(what) + " " + quoted(tok) +
             " has a character outside [A-Za-z0-9_.:-]");
    return tok;
}

bool CTextLogParser::parseLine(const std::string& line, size_t lineNo,
                               TTimedRecord& rec) {
    line_ = lineNo;
    const auto tok = tokenize(line);
    if (tok.empty()) return false;
    if (!sawFormat_) {
        if (tok[0].rfind("\xEF\xBB\xBF", 0) == 0)
            fail("the file starts with a UTF-8 byte order mark: save it without one");
        if (tok[0] != "format" || tok.size() < 2 || tok[1] != "textlog")
            fail("the first record must be 'format textlog 1', got " +
                 quoted(tok[0] + (tok.size() > 1 ? " " + tok[1] : "")));
        if (tok.size() != 3 || tok[2] != "1")
            fail("unsupported format line " + quoted(line) +
                 " (this program reads 'format textlog 1')");
        sawFormat_ = true;
        return false;
    }
    if (tok[0] == "format") fail("'format' may appear only once, as the first record");
    if (isHeaderKind(tok[0])) {
        if (firstTimedLine_)
            fail("header record '" + tok[0] + "' after the first timed record (line " +
                 std::to_string(firstTimedLine_) + "): header records come first");
        parseHeader(tok);
        return false;
    }
    if (tok[0] == "odom" || tok[0] == "rfid" || tok[0] == "ir" || tok[0] == "ir_raw" ||
        tok[0] == "rb") {
        parseTimed(tok, rec);
        return true;
    }
    fail("unknown record " + quoted(tok[0]) +
         " (expected reader, receiver, rb_sensor, start, odom, rfid, ir, ir_raw or rb)");
}

void CTextLogParser::parseHeader(const std::vector<std::string>& tok) {
    using rfir::obs::TIRReceiver;
    using rfir::obs::TRFIDReader;
    const auto dup = [&](const std::string& what, size_t first) {
        fail("duplicate " + what + " (first declared at line " + std::to_string(first) +
             ")");
    };
    if (tok[0] == "reader") {
        checkFieldCount(tok, 5, "<reader_id> <x> <y> <half_x> <half_y>");
        TRFIDReader r;
        r.id = id(tok[1], "reader_id");
        r.x = number(tok[2], "x");
        r.y = number(tok[3], "y");
        r.halfX = positive(tok[4], "half_x");
        r.halfY = positive(tok[5], "half_y");
        if (auto it = readerLines_.find(r.id); it != readerLines_.end())
            dup("reader ID '" + r.id + "'", it->second);
        readerLines_[r.id] = line_;
        header_.readers.push_back(r);
    } else if (tok[0] == "receiver") {
        checkFieldCount(tok, 4, "<receiver_id> <x> <y> <z>");
        TIRReceiver r;
        r.id = id(tok[1], "receiver_id");
        r.x = number(tok[2], "x");
        r.y = number(tok[3], "y");
        r.z = number(tok[4], "z");
        if (auto it = receiverLines_.find(r.id); it != receiverLines_.end())
            dup("receiver ID '" + r.id + "'", it->second);
        receiverLines_[r.id] = line_;
        header_.receivers.push_back(r);
    } else if (tok[0] == "rb_sensor") {
        checkFieldCount(tok, 5, "<x> <y> <yaw> <max_range> <fov>");
        rfir::obs::TRBSensor s;
        s.x = number(tok[1], "x");
        s.y = number(tok[2], "y");
        s.yaw = angle(tok[3], "yaw");
        s.maxRange = positive(tok[4], "max_range");
        s.fov = positive(tok[5], "fov");
        // fov is a full angle: a sensor sees at most all around.
        if (s.fov > 2 * M_PI) fail("fov must be in (0, 2 pi] radians, got " + tok[5]);
        if (rbSensorLine_) dup("'rb_sensor' record", rbSensorLine_);
        rbSensorLine_ = line_;
        header_.rbSensor = s;
    } else  // start
    {
        checkFieldCount(tok, 3, "<x> <y> <phi>");
        TTextLogHeader::TStart s;
        s.x = number(tok[1], "x");
        s.y = number(tok[2], "y");
        s.phi = angle(tok[3], "phi");
        if (startLine_) dup("'start' record", startLine_);
        startLine_ = line_;
        header_.start = s;
    }
}

void CTextLogParser::parseTimed(const std::vector<std::string>& tok, TTimedRecord& r) {
    using K = TTimedRecord::Kind;
    r = TTimedRecord();
    r.line = line_;
    const std::string& k = tok[0];
    if (k == "odom")
        checkFieldCount(tok, 4, "<t> <x> <y> <phi>");
    else if (k == "rfid") {
        if (tok.size() < 3)
            fail("'rfid' takes at least 2 fields (<t> <reader_id> [<tag_id> ...]), got " +
                 std::to_string(tok.size() - 1));
    } else if (k == "ir")
        checkFieldCount(tok, 4, "<t> <receiver_id> <codes> <volts>");
    else if (k == "ir_raw")
        checkFieldCount(tok, 4, "<t> <receiver_id> <rate_hz> <v1,v2,...>");
    else
        checkFieldCount(tok, 4, "<t> <landmark_id> <range> <bearing>");
    r.t = number(tok[1], "t");
    if (k == "odom") {
        r.kind = K::Odom;
        r.x = number(tok[2], "x");
        r.y = number(tok[3], "y");
        r.phi = angle(tok[4], "phi");
    } else if (k == "rfid") {
        r.kind = K::Rfid;
        r.id = id(tok[2], "reader_id");
        if (!header_.findReader(r.id))
            fail("rfid names reader '" + r.id +
                 "', which no 'reader' header record declares");
        for (size_t i = 3; i < tok.size(); i++) r.tags.push_back(id(tok[i], "tag_id"));
    } else if (k == "ir" || k == "ir_raw")
        parseIr(tok, r);
    else {
        r.kind = K::Rb;
        if (!header_.rbSensor) fail("'rb' record without an 'rb_sensor' header record");
        r.id = id(tok[2], "landmark_id");
        r.range = floatField(tok[3], "range", false);
        r.bearing = floatField(tok[4], "bearing", true);
    }
    checkTime(tok[1], r);
}

void CTextLogParser::parseIr(const std::vector<std::string>& tok, TTimedRecord& r) {
    const std::string& k = tok[0];
    r.id = id(tok[2], "receiver_id");
    if (!header_.findReceiver(r.id))
        fail(k + " names receiver '" + r.id +
             "', which no 'receiver' header record declares");
    if (k == "ir") {
        r.kind = TTimedRecord::Kind::Ir;
        const auto c = rfir::ir::parseCodeList(tok[3]);
        if (!c)
            fail("codes " + quoted(tok[3]) +
                 " is not a comma-separated ascending list of codes 1..9");
        r.codes = *c;
        r.volts = number(tok[4], "volts");
        return;
    }
    r.kind = TTimedRecord::Kind::IrRaw;
    r.rateHz = positive(tok[3], "rate_hz");
    const std::string& s = tok[4];
    size_t i = 0;
    for (size_t n = 1;; n++) {
        const size_t j = std::min(s.find(',', i), s.size());
        const auto v = parseDecimalFloat(s.substr(i, j - i));
        if (!v)
            fail("sample " + std::to_string(n) + " " + quoted(s.substr(i, j - i)) +
                 " of the ir_raw window is not a finite decimal number");
        r.samples.push_back(*v);
        if (j == s.size()) break;
        i = j + 1;
    }
}

void CTextLogParser::checkTime(const std::string& tokT, const TTimedRecord& r) {
    if (firstTimedLine_ && r.t < lastT_)
        fail("t " + tokT + " is earlier than the previous record's t " +
             formatNumber(lastT_) + " (line " + std::to_string(lastTLine_) +
             "): timed records must be in non-decreasing time");
    if (!firstTimedLine_ || r.t != lastT_) odomLineAtT_ = 0;
    if (r.kind == TTimedRecord::Kind::Odom) {
        if (odomLineAtT_)
            fail("second odom record at t " + tokT + " (first at line " +
                 std::to_string(odomLineAtT_) + "): one sensing instant has one pose");
        odomLineAtT_ = line_;
    }
    if (!firstTimedLine_) firstTimedLine_ = line_;
    lastT_ = r.t;
    lastTLine_ = line_;
}

void CTextLogParser::finish(size_t lastLineNo) const {
    if (!sawFormat_)
        throw TextLogError(file_, std::max<size_t>(lastLineNo, 1),
                           "empty text log: the first record must be 'format textlog 1'");
}

TTextLog readTextLog(std::istream& in, const std::string& name) {
    CTextLogParser p(name);
    TTextLog log;
    std::string line;
    size_t n = 0;
    TTimedRecord rec;
    while (getBoundedLine(in, line, name, n + 1))
        if (p.parseLine(line, ++n, rec)) log.records.push_back(std::move(rec));
    if (in.bad()) throw std::runtime_error(name + ": read error");
    p.finish(n);
    log.header = p.header();
    return log;
}

TTextLog readTextLog(const std::string& path) {
    std::ifstream f;
    openTextInput(f, path, "text log");
    return readTextLog(f, path);
}

}  // namespace rfir::common
