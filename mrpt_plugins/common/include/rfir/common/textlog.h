/* rfir: the plain-text sensor log, version 1 (docs/import.md describes the
 * format and its rules). A strict line parser and a canonical writer. */
#pragma once

#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rfir::common {
/** A malformed text log: what() is "FILE:LINE: what is wrong". */
class TextLogError : public std::runtime_error {
  public:
    TextLogError(const std::string& file, size_t line, const std::string& msg)
        : std::runtime_error(file + ":" + std::to_string(line) + ": " + msg),
          file_(file),
          line_(line),
          msg_(msg) {}
    const std::string& file() const { return file_; }
    size_t line() const { return line_; }
    const std::string& message() const { return msg_; }

  private:
    std::string file_;
    size_t line_;
    std::string msg_;
};

/** The header records: `reader`, `receiver`, `rb_sensor`, `start`. */
struct TTextLogHeader {
    std::vector<rfir::obs::TRFIDReader> readers;
    std::vector<rfir::obs::TIRReceiver> receivers;
    std::optional<rfir::obs::TRBSensor> rbSensor;
    struct TStart {
        double x = 0, y = 0, phi = 0;
        bool operator==(const TStart& o) const {
            return x == o.x && y == o.y && phi == o.phi;
        }
    };
    std::optional<TStart> start;

    const rfir::obs::TRFIDReader* findReader(const std::string& id) const;
    const rfir::obs::TIRReceiver* findReceiver(const std::string& id) const;
    bool operator==(const TTextLogHeader& o) const;
};

/** One timed record. Only the fields of its kind are meaningful. */
struct TTimedRecord {
    enum class Kind { Odom, Rfid, Ir, IrRaw, Rb };
    Kind kind = Kind::Odom;
    double t = 0;
    size_t line = 0;                //!< source line (0 when built in memory)
    std::string id;                 //!< reader, receiver or landmark ID (not for odom)
    double x = 0, y = 0, phi = 0;   //!< odom
    std::vector<std::string> tags;  //!< rfid
    std::vector<uint8_t> codes;     //!< ir
    double volts = 0;               //!< ir
    double rateHz = 0;              //!< ir_raw
    std::vector<float> samples;     //!< ir_raw
    /** rb: floats, as CObservationBearingRange stores them; a bearing within
     * float rounding of +-pi is rounded into (-pi, pi]. */
    float range = 0, bearing = 0;

    /** Same content (the source line is not compared). */
    bool operator==(const TTimedRecord& o) const;
};
const char* kindName(TTimedRecord::Kind k);

/** A whole text log in memory. */
struct TTextLog {
    TTextLogHeader header;
    std::vector<TTimedRecord> records;
};

/** Parses a text log line by line, checking every rule of the format, and
 * throws TextLogError on the first malformed line. Keeps only the header and
 * the last time, so a huge log can be checked while streaming. */
class CTextLogParser {
  public:
    explicit CTextLogParser(std::string fileName) : file_(std::move(fileName)) {}

    /** Parses line number `lineNo` (1-based). Returns true and fills `rec` for
     * a timed record; false for the format line, a header record, a comment or
     * a blank line. */
    bool parseLine(const std::string& line, size_t lineNo, TTimedRecord& rec);
    /** Call after the last line: an empty log (no format line) is an error. */
    void finish(size_t lastLineNo) const;

    const TTextLogHeader& header() const { return header_; }

  private:
    [[noreturn]] void fail(const std::string& msg) const;
    void parseHeader(const std::vector<std::string>& tok);
    void parseTimed(const std::vector<std::string>& tok, TTimedRecord& rec);
    void parseIr(const std::vector<std::string>& tok, TTimedRecord& rec);
    void checkTime(const std::string& tokT, const TTimedRecord& rec);
    void checkFieldCount(const std::vector<std::string>& tok, size_t n,
                         const char* fields) const;
    double number(const std::string& tok, const char* what) const;
    double positive(const std::string& tok, const char* what) const;
    double angle(const std::string& tok, const char* what) const;
    float floatField(const std::string& tok, const char* what, bool isAngle) const;
    std::string id(const std::string& tok, const char* what) const;

    std::string file_;
    size_t line_ = 0;
    bool sawFormat_ = false;
    size_t firstTimedLine_ = 0;
    double lastT_ = 0;
    size_t lastTLine_ = 0, odomLineAtT_ = 0;
    TTextLogHeader header_;
    std::map<std::string, size_t> readerLines_, receiverLines_;
    size_t rbSensorLine_ = 0, startLine_ = 0;
};

/** Reads a whole text log (throws TextLogError or std::runtime_error). */
TTextLog readTextLog(const std::string& path);
/** Same from a stream; `name` is used in messages. */
TTextLog readTextLog(std::istream& in, const std::string& name);

/** Shortest decimal text that reads back as exactly the same double / float. */
std::string formatNumber(double v);
std::string formatNumber(float v);
/** Parses a finite decimal number; nullopt on anything else. */
std::optional<double> parseDecimal(const std::string& tok);
std::optional<float> parseDecimalFloat(const std::string& tok);

/** Writers of the canonical form: one space between fields, numbers in their
 * shortest exact form. */
void writeTextLogHeader(std::ostream& o, const TTextLogHeader& h);
void writeTimedRecord(std::ostream& o, const TTimedRecord& r);
void writeTextLog(std::ostream& o, const TTextLog& log);

/** Stable-sorts the records of each sensing instant (same t) into the order a
 * rawlog stores them: odom, rfid, ir and ir_raw, rb. */
void canonicalizeRecordOrder(TTextLog& log);

}  // namespace rfir::common
