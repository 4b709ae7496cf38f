/* rfir: text log -> rawlog. Two passes over the text: the first checks every
 * line (and collects the range-bearing landmark names the header needs), the
 * second writes; a malformed log therefore leaves no output at all. */
#include <rfir/common/log_convert.h>
#include <rfir/common/progress.h>
#include <rfir/common/rawlog_io.h>
#include <rfir/common/text_input.h>

#include <fstream>
#include <ostream>
#include <unordered_map>

namespace rfir::common {
namespace {
/** Reads the text log line by line through a fresh parser. */
template <class OnRecord>
void forEachRecord(const std::string& path, const TConvertOptions& opts,
                   const std::string& what, CTextLogParser& p, OnRecord&& onRecord) {
    std::ifstream f;
    openTextInput(f, path, "text log");
    f.seekg(0, std::ios::end);
    const auto size = uint64_t(f.tellg());
    f.seekg(0);
    // Progress only for inputs over 1 MB (bytes read of the file's size).
    CProgress prog(what + " " + path, size, size > (1u << 20) ? opts.progress : nullptr);
    std::string line;
    size_t n = 0;
    uint64_t done = 0;
    TTimedRecord rec;
    while (getBoundedLine(f, line, path, n + 1)) {
        if (p.parseLine(line, ++n, rec)) onRecord(rec);
        done += line.size() + 1;
        prog.update(done - 1);
    }
    if (f.bad()) throw std::runtime_error(path + ": read error");
    p.finish(n);
    if (size) prog.update(size - 1);
    prog.finish();
}

/** What the first pass learns. */
struct TChecked {
    TTextLogHeader header;
    std::vector<std::string> landmarks;  //!< rb IDs, in order of first use
    size_t records = 0, instants = 0;
    double firstT = 0;
};

/** Rules of the rawlog on top of the text format's own. */
TChecked checkForRawlog(const std::string& path, const TConvertOptions& opts) {
    CTextLogParser p(path);
    TChecked c;
    std::unordered_map<std::string, size_t> seen, atThisT;
    std::optional<double> prevT;
    mrpt::Clock::time_point prevTs;
    size_t prevLine = 0;
    forEachRecord(path, opts, "checking", p, [&](const TTimedRecord& r) {
        const auto fail = [&](const std::string& m) {
            throw TextLogError(path, r.line, m);
        };
        const auto ts = timestampFromT(r.t);
        if (!ts)
            fail("t " + formatNumber(r.t) +
                 " cannot be an MRPT timestamp (t must be in [0, 1e11) seconds)");
        if (!prevT || r.t != *prevT) {
            if (prevT && *ts == prevTs)
                fail("t " + formatNumber(r.t) + " and the previous instant's t " +
                     formatNumber(*prevT) + " (line " + std::to_string(prevLine) +
                     ") differ by less than the 100 ns resolution of MRPT timestamps");
            if (!c.instants++) c.firstT = r.t;
            atThisT.clear();
            prevT = r.t;
            prevTs = *ts;
            prevLine = r.line;
        }
        if (r.kind == TTimedRecord::Kind::IrRaw && r.samples.size() < 16)
            fail("ir_raw window of " + std::to_string(r.samples.size()) +
                 " samples is too short to decode (at least 16)");
        if (r.kind == TTimedRecord::Kind::Rb) {
            // MRPT refuses to serialize two measurements of one landmark in
            // one CObservationBearingRange.
            if (auto [it, isNew] = atThisT.emplace(r.id, r.line); !isNew)
                fail("landmark '" + r.id + "' is measured twice at t " +
                     formatNumber(r.t) + " (first at line " + std::to_string(it->second) +
                     "): an MRPT range-bearing observation holds one measurement per "
                     "landmark");
            if (seen.emplace(r.id, seen.size()).second) c.landmarks.push_back(r.id);
        }
        c.records++;
    });
    c.header = p.header();
    return c;
}
}  // namespace

TConvertReport convertTextLogToRawlog(const std::string& in, const std::string& out,
                                      const TConvertOptions& opts) {
    const TChecked c = checkForRawlog(in, opts);
    const auto hdr = toLogHeader(c.header, c.landmarks, c.firstT);
    const CInstantBuilder builder(hdr, opts.decoder);
    CRawlogWriter w(out, hdr);
    std::vector<TTimedRecord> instant;
    std::optional<mrpt::poses::CPose2D> odom;
    std::vector<mrpt::obs::CObservation::Ptr> obs;
    const auto flush = [&]() {
        if (instant.empty()) return;
        try {
            builder.build(instant, odom, obs);
        } catch (const std::exception& e) {
            throw TextLogError(in, instant.front().line, e.what());
        }
        w.writeStep(instant.front().t, odom, obs);
        instant.clear();
    };
    CTextLogParser p(in);
    forEachRecord(in, opts, "converting", p, [&](const TTimedRecord& r) {
        if (!instant.empty() && r.t != instant.front().t) flush();
        instant.push_back(r);
    });
    flush();
    w.close();
    TConvertReport rep;
    rep.timedRecords = c.records;
    rep.instants = w.stepsWritten();
    return rep;
}

}  // namespace rfir::common
