/* rfir: text log (version 1) <-> rawlog in the project's layout
 * (docs/rawlog-layout.md, docs/import.md). */
#pragma once

#include <rfir/common/textlog.h>
#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/ir_decoder.h>

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose2D.h>

#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace rfir::common {
struct TConvertOptions {
    /** rawlog -> text only: write what textlog 1 can hold and count, in the
     * report, what it cannot (instead of failing on the first such item). */
    bool lossy = false;
    /** Decoder of `ir_raw` windows. */
    rfir::ir::TDecoderParams decoder;
    /** Progress lines for big inputs (nullptr: quiet). */
    std::ostream* progress = nullptr;
};

struct TConvertReport {
    size_t timedRecords = 0;  //!< text records read or written
    size_t instants = 0;      //!< rawlog sensing instants written or read
    /** lossy mode: what could not be written, and how many times. */
    std::map<std::string, size_t> dropped;
};

enum class TLogFileKind { Text, Rawlog, Other };
/** By extension: ".txt" text log, ".rawlog" rawlog (case-insensitive). */
TLogFileKind logFileKind(const std::string& path);

/** Checks the whole text log, then writes the rawlog (whole or not at all).
 * Throws TextLogError ("FILE:LINE: ...") or std::runtime_error. */
TConvertReport convertTextLogToRawlog(const std::string& in, const std::string& out,
                                      const TConvertOptions& opts = {});
/** Reads the whole rawlog once to check it can be written exactly, then
 * writes the text log (whole or not at all). Throws std::runtime_error naming
 * the file and instant. */
TConvertReport convertRawlogToTextLog(const std::string& in, const std::string& out,
                                      const TConvertOptions& opts = {});

// ---- building blocks (shared by both directions, and by the tests) ----

/** The MRPT timestamp of a text `t`; nullopt when t cannot be one (t < 0 or
 * t >= 1e11 s). MRPT timestamps have a 100 ns resolution. */
std::optional<mrpt::Clock::time_point> timestampFromT(double t);
/** The shortest decimal t whose timestampFromT() is exactly `ts`; nullopt if
 * no decimal maps to it (a timestamp not made from a double). */
std::optional<std::string> formatTimestamp(mrpt::Clock::time_point ts);

/** CPose2D's constructor wraps phi through (phi + pi) mod 2 pi - pi, which
 * changes the last bits of most angles (0.01 becomes 0.0099999999999997868)
 * and turns pi into -pi: this keeps phi exactly as given. */
mrpt::poses::CPose2D exactPose(double x, double y, double phi);

/** Header observation of a text header; landmark names index the rb IDs. Its
 * timestamp is that of the first instant (t0), so that viewers place it on the
 * log's time line (and the same input always gives the same bytes). */
rfir::obs::CObservationLogHeader toLogHeader(const TTextLogHeader& h,
                                             const std::vector<std::string>& landmarks,
                                             double t0);
TTextLogHeader fromLogHeader(const rfir::obs::CObservationLogHeader& h);

/** The import's reading of the IR records of one instant: every receiver of
 * the header that no reading names saw nothing and gets a reading with no
 * code, 0 V and no raw window, appended in header order (docs/import.md). */
void addDarkReceivers(const rfir::obs::CObservationLogHeader& hdr,
                      rfir::obs::CObservationIRSignals& ir);

/** Builds the observations of one sensing instant from its records. */
class CInstantBuilder {
  public:
    CInstantBuilder(const rfir::obs::CObservationLogHeader& hdr,
                    const rfir::ir::TDecoderParams& decoder);
    /** All records share one t. Observations in the layout's order: RFID, IR,
     * RB (labels RFID, IR, RB), timestamps set. */
    void build(const std::vector<TTimedRecord>& recs,
               std::optional<mrpt::poses::CPose2D>& odometry,
               std::vector<mrpt::obs::CObservation::Ptr>& obs) const;
    const rfir::obs::CObservationLogHeader& header() const { return hdr_; }

  private:
    /** Landmark ID of a name; -1 if not in the header's table. */
    int32_t landmarkId(const std::string& name) const;
    rfir::obs::CObservationLogHeader hdr_;
    rfir::ir::TDecoderParams decoder_;
    std::unordered_map<std::string, int32_t> landmarkIds_;
};

/** Byte-exact comparison of two serializable objects (every field). */
bool sameSerialization(const mrpt::serialization::CSerializable& a,
                       const mrpt::serialization::CSerializable& b);

}  // namespace rfir::common
