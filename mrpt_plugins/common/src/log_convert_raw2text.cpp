/* rfir: rawlog -> text log, the inverse of the import. Every observation is
 * turned into records, rebuilt from them exactly as the import would, and
 * compared byte for byte with the original: what the text cannot carry is an
 * error (or, with `lossy`, counted), never dropped silently. */
#include <rfir/common/atomic_file.h>
#include <rfir/common/log_convert.h>
#include <rfir/common/rawlog_io.h>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <map>
#include <ostream>
#include <sstream>

namespace rfir::common {
using namespace rfir::obs;
using mrpt::obs::CObservation;
using mrpt::obs::CObservationBearingRange;
using mrpt::obs::CObservationOdometry;

namespace {
/** An angle as the text wants it, in (-pi, pi]. */
template <class T>
T textAngle(T a) {
    // Compared as doubles: float(pi) is above pi and the parser refuses it.
    if (double(a) > -M_PI && double(a) <= M_PI) return a;
    a = mrpt::math::wrapToPi(a);
    if (!(double(a) > -M_PI)) a = std::nextafter(T(M_PI), T(0));
    while (!(double(a) <= M_PI)) a = std::nextafter(a, T(0));
    return a;
}

class CRawToText {
  public:
    CRawToText(const std::string& in, const std::string& out, const TConvertOptions& o)
        : in_(in), opts_(o), vp_(out + " (as written)") {}
    TConvertReport run(std::ostream& out, size_t expectedInstants);

  private:
    void lossy(const std::string& what);
    std::string validLine(const TTimedRecord& r);
    void timeOf(const CObservation& o, double& t);
    void convertFrame(std::ostream& out, const TRawlogStep& st);
    std::vector<TTimedRecord> recordsOf(const CObservation& o, double t);
    void recordsOfIR(const CObservationIRSignals& o, TTimedRecord& r,
                     std::vector<TTimedRecord>& v);
    void checkDarkReadings(const CObservationIRSignals& o);
    void recordsOfRB(const CObservationBearingRange& o, TTimedRecord& r,
                     std::vector<TTimedRecord>& v);
    void checkRebuilt(const CObservation& o, const std::vector<TTimedRecord>& recs);

    std::string in_;
    TConvertOptions opts_;
    CTextLogParser vp_;  //!< validates every line written
    size_t line_ = 0, instant_ = 0;
    std::string tText_;
    std::unique_ptr<CInstantBuilder> builder_;
    std::map<std::string, int32_t> firstSeen_;
    TConvertReport rep_;
    size_t flagged_ = 0;
};

void CRawToText::lossy(const std::string& what) {
    if (!opts_.lossy)
        throw std::runtime_error(in_ + ": instant " + std::to_string(instant_) + " (t " +
                                 tText_ + "): " + what +
                                 ": textlog 1 cannot hold it (--lossy writes the rest "
                                 "and counts what is left out)");
    rep_.dropped[what]++;
    flagged_++;
}

std::string CRawToText::validLine(const TTimedRecord& r) {
    std::ostringstream s;
    writeTimedRecord(s, r);
    std::string line = s.str();
    TTimedRecord back;
    try {
        vp_.parseLine(line.substr(0, line.size() - 1), ++line_, back);
    } catch (const TextLogError& e) {
        throw std::runtime_error(
            in_ + ": instant " + std::to_string(instant_) +
            ": would write an invalid text log line: " + e.message());
    }
    rep_.timedRecords++;
    return line;
}

void CRawToText::timeOf(const CObservation& o, double& t) {
    const auto s = formatTimestamp(o.timestamp);
    tText_ = s ? *s : formatNumber(mrpt::Clock::toDouble(o.timestamp));
    if (!s)
        lossy(
            o.timestamp == mrpt::Clock::time_point()
                ? "observation without a timestamp"
                : "timestamp that no decimal t maps to exactly (not made from a double)");
    t = *parseDecimal(tText_);
}

void CRawToText::recordsOfIR(const CObservationIRSignals& o, TTimedRecord& r,
                             std::vector<TTimedRecord>& v) {
    if (o.readings.empty()) lossy("IR observation with no receiver");
    checkDarkReadings(o);
    for (const auto& rd : o.readings) {
        r.id = rd.receiver.id;
        if (rd.hasRaw()) {
            r.kind = TTimedRecord::Kind::IrRaw;
            r.rateHz = rd.rateHz;
            r.samples = rd.raw;
            const auto dec = rfir::ir::decodeIRWindow(rd.raw, rd.rateHz, opts_.decoder);
            if (dec.codes != rd.codes || dec.volts != rd.volts)
                lossy(
                    "ir_raw reading whose stored codes/volts differ from its decoded "
                    "window");
        } else if (!rd.codes.empty()) {
            r.kind = TTimedRecord::Kind::Ir;
            r.codes = rd.codes;
            r.volts = rd.volts;
        } else
            continue;  // nothing in view: no record (checkDarkReadings)
        v.push_back(r);
    }
}

void CRawToText::checkDarkReadings(const CObservationIRSignals& o) {
    // The import adds a reading with nothing in view for each declared
    // receiver without a record: the stored ones must be exactly those.
    CObservationIRSignals seen;
    for (const auto& rd : o.readings)
        if (rd.hasRaw() || !rd.codes.empty()) seen.readings.push_back(rd);
    if (seen.readings.size() == o.readings.size()) return;
    if (seen.readings.empty()) {
        lossy("IR observation in which no receiver sees anything");
        return;
    }
    auto expected = seen;
    addDarkReceivers(builder_->header(), expected);
    if (expected.readings != o.readings)
        lossy(
            "IR readings with nothing in view other than one per declared receiver "
            "without a reading, after the others, in header order");
}

void CRawToText::recordsOfRB(const CObservationBearingRange& o, TTimedRecord& r,
                             std::vector<TTimedRecord>& v) {
    const auto& names = builder_->header().rbLandmarkNames;
    if (o.sensedData.empty()) lossy("range-bearing observation with no measurement");
    for (const auto& m : o.sensedData) {
        r.kind = TTimedRecord::Kind::Rb;
        if (m.landmarkID < 0 || size_t(m.landmarkID) >= names.size())
            lossy("range-bearing landmark ID outside the header's name table");
        r.id = builder_->header().landmarkName(m.landmarkID);
        r.range = m.range;
        r.bearing = textAngle(m.yaw);
        const auto it = firstSeen_.emplace(r.id, int32_t(firstSeen_.size())).first;
        if (it->second != m.landmarkID)
            lossy("landmark IDs not numbered in order of first observation");
        v.push_back(r);
    }
}

std::vector<TTimedRecord> CRawToText::recordsOf(const CObservation& o, double t) {
    std::vector<TTimedRecord> v;
    TTimedRecord r;
    r.t = t;
    if (auto od = dynamic_cast<const CObservationOdometry*>(&o)) {
        r.kind = TTimedRecord::Kind::Odom;
        r.x = od->odometry.x();
        r.y = od->odometry.y();
        r.phi = textAngle(od->odometry.phi());
        v.push_back(r);
    } else if (auto rf = dynamic_cast<const CObservationRFIDReaders*>(&o)) {
        if (rf->readings.empty()) lossy("RFID observation with no reader");
        for (const auto& rd : rf->readings) {
            r.kind = TTimedRecord::Kind::Rfid;
            r.id = rd.reader.id;
            r.tags = rd.tags;
            v.push_back(r);
        }
    } else if (auto ir = dynamic_cast<const CObservationIRSignals*>(&o))
        recordsOfIR(*ir, r, v);
    else if (auto rb = dynamic_cast<const CObservationBearingRange*>(&o))
        recordsOfRB(*rb, r, v);
    else
        lossy("observation of class " + std::string(o.GetRuntimeClass()->className));
    return v;
}

void CRawToText::checkRebuilt(const CObservation& o,
                              const std::vector<TTimedRecord>& recs) {
    std::optional<mrpt::poses::CPose2D> odom;
    std::vector<CObservation::Ptr> obs;
    if (recs.empty()) return;
    try {
        builder_->build(recs, odom, obs);
    } catch (const std::exception& e) {
        lossy(std::string(o.GetRuntimeClass()->className) + " that cannot be rebuilt (" +
              e.what() + ")");
        return;
    }
    CObservation::Ptr re = obs.empty() ? nullptr : obs.front();
    if (odom) {
        auto od = CObservationOdometry::Create();
        od->sensorLabel = "ODOMETRY";
        od->timestamp = *timestampFromT(recs.front().t);
        od->odometry = *odom;
        re = od;
    }
    if (!re || !sameSerialization(o, *re))
        lossy(std::string(o.GetRuntimeClass()->className) +
              " with fields textlog 1 does not carry (sensor label, geometry differing "
              "from the header, noise parameters, pitch, an angle outside (-pi, pi])");
}

void CRawToText::convertFrame(std::ostream& out, const TRawlogStep& st) {
    std::map<std::string, int> perClass;
    if (st.sf->size() == 0)
        lossy(st.action && st.action->getBestMovementEstimation()
                  ? "odometry increment without an odometry pose"
                  : "empty sensing instant");
    for (const auto& o : *st.sf) {
        const std::string cls = o->GetRuntimeClass()->className;
        if (++perClass[cls] == 2) lossy("several " + cls + " in one instant");
        const size_t flagged = flagged_;
        double t = 0;
        timeOf(*o, t);
        const auto recs = recordsOf(*o, t);
        // One reason per observation is enough: the generic one only when no
        // specific one was found.
        std::string text;
        for (const auto& r : recs) text += validLine(r);
        if (flagged_ == flagged) checkRebuilt(*o, recs);
        out << text;
    }
}

TConvertReport CRawToText::run(std::ostream& out, size_t expected) {
    CRawlogReader rd(in_);
    const auto& hdr = rd.header();
    const TTextLogHeader th = fromLogHeader(hdr);
    // The header's timestamp carries no data (the import sets it to the
    // first instant's); everything else must come back exactly.
    auto rebuilt = toLogHeader(th, hdr.rbLandmarkNames, 0);
    rebuilt.timestamp = hdr.timestamp;
    // A start heading of -pi comes back as pi, the same heading (fromLogHeader).
    auto canonical = hdr;
    if (canonical.startPose && canonical.startPose->phi() == -M_PI)
        canonical.startPose->phi(M_PI);
    if (!sameSerialization(canonical, rebuilt))
        lossy("log header sensor label (or no rfir log header)");
    std::ostringstream hs;
    writeTextLogHeader(hs, th);
    std::istringstream hl(hs.str());
    TTimedRecord dummy;
    for (std::string l; std::getline(hl, l);) {
        try {
            vp_.parseLine(l, ++line_, dummy);
        } catch (const TextLogError& e) {
            throw std::runtime_error(in_ +
                                     ": log header: would write an invalid text log "
                                     "line: " +
                                     e.message());
        }
    }
    out << hs.str();
    builder_ = std::make_unique<CInstantBuilder>(hdr, opts_.decoder);
    TRawlogStep st;
    for (instant_ = 1; rd.next(st); instant_++) {
        convertFrame(out, st);
        rep_.instants++;
        if (opts_.progress && expected > 20000 && instant_ % (expected / 10) == 0)
            *opts_.progress << "writing " << in_ << ": " << 100 * instant_ / expected
                            << " %" << std::endl;
    }
    instant_ = 0;
    if (firstSeen_.size() < hdr.rbLandmarkNames.size())
        lossy("landmark names in the header that no observation uses");
    return rep_;
}
}  // namespace

TConvertReport convertRawlogToTextLog(const std::string& in, const std::string& out,
                                      const TConvertOptions& opts) {
    // First pass: everything is checked and nothing is written.
    std::ostream nowhere(nullptr);
    const size_t n = CRawToText(in, out, opts).run(nowhere, 0).instants;
    TConvertReport rep;
    writeFileAtomically(
        out, [&](std::ostream& o) { rep = CRawToText(in, out, opts).run(o, n); });
    return rep;
}

}  // namespace rfir::common
