#include <rfir/common/rawlog_io.h>
#include <rfir/models/printable.h>
#include <rfir/obs/bounded_read.h>
#include <rfir/obs/mrpt_guards.h>
#include <rfir/obs/registerAllClasses.h>

#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRFID.h>
#include <mrpt/serialization/CArchive.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <utility>

namespace rfir::common {
using namespace mrpt::obs;

namespace {
/** A gz stream only reports EOF after a read has failed, so the reader takes
 * one byte to tell "no more objects" from "object cut short", then hands that
 * byte back to the archive through this wrapper. */
class CPushbackStream : public mrpt::io::CStream, public rfir::obs::IBytesLeft {
  public:
    CPushbackStream(CGzInputStream& s, uint8_t first) : s_(s), first_(first) {}
    size_t Read(void* buf, size_t n) override {
        if (n == 0) return 0;
        size_t k = 0;
        if (pending_) {
            *static_cast<uint8_t*>(buf) = first_;
            pending_ = false;
            k = 1;
        }
        return k + s_.Read(static_cast<uint8_t*>(buf) + k, n - k);
    }
    size_t Write(const void*, size_t) override { return 0; }
    uint64_t Seek(int64_t, mrpt::io::CStream::TSeekOrigin) override {
        throw std::logic_error("CPushbackStream: no seek");
    }
    uint64_t getTotalBytesCount() const override { return s_.getTotalBytesCount(); }
    uint64_t getPosition() const override {
        return s_.getPosition() - (pending_ ? 1 : 0);
    }
    std::string getStreamDescription() const override {
        return s_.getStreamDescription();
    }
    std::optional<uint64_t> bytesLeft() const override {
        return *s_.bytesLeft() + (pending_ ? 1 : 0);
    }

  private:
    CGzInputStream& s_;
    uint8_t first_;
    bool pending_ = true;
};
/** MRPT wraps an error once per nesting level ("==== MRPT exception ====",
 * "Message: ...", "Original exception: ..."); the innermost one says what is
 * wrong, so that is the one reported. */
std::string innermostError(std::string msg) {
    const std::string orig = "Original exception:";
    if (const auto k = msg.rfind(orig); k != std::string::npos)
        msg = msg.substr(k + orig.size());
    const std::string head = "Message:";
    if (msg.find("==== MRPT exception ====") != std::string::npos)
        if (const auto k = msg.find(head); k != std::string::npos)
            msg = msg.substr(k + head.size());
    const auto b = msg.find_first_not_of(" \t\n");
    msg = b == std::string::npos ? std::string() : msg.substr(b);
    return msg.substr(0, msg.find('\n'));
}

}  // namespace

CRawlogWriter::CRawlogWriter(const std::string& path,
                             const rfir::obs::CObservationLogHeader& hdr,
                             const CActionRobotMovement2D::TMotionModelOptions& motion)
    : path_(path), tmp_(path + ".tmp." + std::to_string(::getpid())), motion_(motion) {
    rfir::obs::registerAllClasses();
    out_ = std::make_unique<mrpt::io::CFileGZOutputStream>();
    if (!out_->open(tmp_))
        throw std::runtime_error("cannot open '" + path + "' for writing");
    auto ar = mrpt::serialization::archiveFrom(*out_);
    // A zero movement, not an empty collection: rbpf-slam asserts a movement
    // in every action and RawLogViewer's odometry map needs one per step.
    CActionCollection acts;
    acts.insert(zeroMovement(hdr.timestamp));
    CSensoryFrame sf;
    auto h = std::make_shared<rfir::obs::CObservationLogHeader>(hdr);
    if (h->sensorLabel.empty()) h->sensorLabel = "HEADER";
    sf.insert(h);
    ar << acts << sf;
}

CActionRobotMovement2D CRawlogWriter::zeroMovement(mrpt::Clock::time_point ts) const {
    CActionRobotMovement2D mv;
    mv.timestamp = ts;
    mv.computeFromOdometry(mrpt::poses::CPose2D(), motion_);
    return mv;
}

CRawlogWriter::~CRawlogWriter() {
    if (out_) {
        out_->close();
        std::remove(tmp_.c_str());
    }
}

void CRawlogWriter::writeStep(double t, const std::optional<mrpt::poses::CPose2D>& odom,
                              const std::vector<CObservation::Ptr>& obs) {
    if (!out_) throw std::logic_error("CRawlogWriter: write after close");
    const auto ts = mrpt::Clock::fromDouble(t);
    CActionCollection acts;
    CSensoryFrame sf;
    // Without odometry the robot is taken as not moved: a zero movement,
    // which the reader tells from a real one by the missing odometry record.
    if (!odom) acts.insert(zeroMovement(ts));
    if (odom) {
        CActionRobotMovement2D mv;
        mv.timestamp = ts;
        // The first odometry record only anchors the odometry frame.
        mv.computeFromOdometry(lastOdom_ ? (*odom - *lastOdom_) : mrpt::poses::CPose2D(),
                               motion_);
        acts.insert(mv);
        auto o = CObservationOdometry::Create();
        o->timestamp = ts;
        o->sensorLabel = "ODOMETRY";
        o->odometry = *odom;
        sf.insert(o);
        lastOdom_ = odom;
    }
    for (const auto& o : obs) {
        o->timestamp = ts;
        sf.insert(o);
    }
    auto ar = mrpt::serialization::archiveFrom(*out_);
    ar << acts << sf;
    steps_++;
}

void CRawlogWriter::close() {
    if (!out_) return;
    out_->close();
    out_.reset();
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
        std::remove(tmp_.c_str());
        throw std::runtime_error("cannot write '" + path_ + "' (rename failed)");
    }
}

CRawlogReader::CRawlogReader(const std::string& path) : path_(path) {
    rfir::obs::registerAllClasses();
    in_.open(path);  // throws "PATH: is a directory" / "no such file" / ...
    auto a = readObject();
    if (auto o = std::dynamic_pointer_cast<CObservation>(a)) {
        // MRPT's observation-only layout: a flat sequence of observations.
        obsOnly_ = true;
        if (auto h = std::dynamic_pointer_cast<rfir::obs::CObservationLogHeader>(o))
            header_ = h;
        else
            pendingObs_ = o;
    } else {
        auto s = readObject();
        auto acts = std::dynamic_pointer_cast<CActionCollection>(a);
        auto sf = std::dynamic_pointer_cast<CSensoryFrame>(s);
        if (!acts || !sf)
            throw std::runtime_error(path +
                                     ": neither a rawlog in action/sensory-frame layout "
                                     "nor an observation-only one (see "
                                     "docs/rawlog-layout.md)");
        if (auto h = sf->getObservationByClass<rfir::obs::CObservationLogHeader>())
            header_ = h;
        else
            pending_ = std::make_pair(acts, sf);
    }
    if (!header_) {
        hasHeader_ = false;
        std::cerr << "warning: " << path
                  << ": no rfir log header (a rawlog cut by rawlog-edit, or not written "
                     "by rfir): no start pose; RFID reader geometry comes from the "
                     "observations\n";
        header_ = std::make_shared<rfir::obs::CObservationLogHeader>();
    }
}

mrpt::serialization::CSerializable::Ptr CRawlogReader::readObject() {
    entry_++;  // a stream cut between two objects fails in the next entry
    try {
        uint8_t first = 0;
        if (in_.Read(&first, 1) != 1) {
            entry_--;
            return {};  // the end, between two objects
        }
        CPushbackStream s(in_, first);
        // Counts read by the classes are checked against the bytes left.
        rfir::obs::CBytesLeftScope scope(&s);
        // And no class whose reader allocates from unchecked counts.
        rfir::obs::CCheckedClassesScope checked;
        auto ar = mrpt::serialization::archiveFrom(s);
        return rfir::obs::readCheckedObject(ar, "the entry");
    } catch (const std::exception& e) {
        std::string msg = printable(innermostError(e.what()));
        if (msg.size() > 300) msg = msg.substr(0, 300) + "...";
        throw std::runtime_error(path_ + ": entry " + std::to_string(entry_) +
                                 ": cannot read object (corrupt file, or a class not "
                                 "registered): " +
                                 msg);
    }
}

bool CRawlogReader::nextPair(CActionCollection::Ptr& acts, CSensoryFrame::Ptr& sf) {
    if (pending_) {
        std::tie(acts, sf) = *pending_;
        pending_.reset();
        return true;
    }
    auto a = readObject();
    if (!a) return false;
    auto s = readObject();
    acts = std::dynamic_pointer_cast<CActionCollection>(a);
    sf = std::dynamic_pointer_cast<CSensoryFrame>(s);
    if (!acts || !sf)
        throw std::runtime_error(path_ + ": entry " + std::to_string(entry_) +
                                 ": expected an action collection / sensory frame pair");
    return true;
}

bool CRawlogReader::nextFlatInstant(CSensoryFrame::Ptr& sf) {
    // One instant = the consecutive observations with the same timestamp.
    sf = std::make_shared<CSensoryFrame>();
    for (;;) {
        CObservation::Ptr o = pendingObs_;
        pendingObs_.reset();
        if (!o) {
            auto x = readObject();
            if (!x) break;
            o = std::dynamic_pointer_cast<CObservation>(x);
            if (!o)
                throw std::runtime_error(
                    path_ + ": entry " + std::to_string(entry_) + ": a " +
                    x->GetRuntimeClass()->className +
                    " in an observation-only rawlog (layouts cannot be mixed)");
        }
        if (sf->size() > 0 && o->timestamp != (*sf->begin())->timestamp) {
            pendingObs_ = o;
            break;
        }
        sf->insert(o);
    }
    return sf->size() > 0;
}

namespace {
/** Reader ID of an MRPT CObservationRFID antenna (docs/rawlog-layout.md). */
std::string mrptReaderId(const CObservationRFID& o, const std::string& port) {
    return port.empty() ? o.sensorLabel : o.sensorLabel + "." + port;
}
}  // namespace

rfir::obs::TRFIDReader CRawlogReader::readerOf(const CObservationRFID& o,
                                               const std::string& id) {
    for (const auto& r : header_->readers)
        if (r.id == id) return r;
    rfir::obs::TRFIDReader r;
    r.id = id;
    r.x = o.sensorPoseOnRobot.x();
    r.y = o.sensorPoseOnRobot.y();
    if (warnedReaders_.insert(id).second)
        std::cerr << "warning: " << path_ << ": RFID reader '" << id
                  << "' is not in the rfir log header: its position is the "
                     "observation's sensorPoseOnRobot ("
                  << r.x << ", " << r.y << "), its detection area assumed " << 2 * r.halfX
                  << " x " << 2 * r.halfY << " m\n";
    return r;
}

void CRawlogReader::addMrptRFID(TRawlogStep& st, const CObservationRFID& o) {
    // Copy-on-write: st.rfid may be an observation of the frame itself.
    auto r = st.rfid ? std::make_shared<rfir::obs::CObservationRFIDReaders>(*st.rfid)
                     : rfir::obs::CObservationRFIDReaders::Create();
    if (!st.rfid) {
        r->timestamp = o.timestamp;
        r->sensorLabel = "RFID";
    }
    auto reading = [&](const std::string& id) -> auto& {
        for (auto& x : r->readings)
            if (x.reader.id == id) return x;
        r->readings.push_back({readerOf(o, id), {}});
        return r->readings.back();
    };
    // An antenna polled with nothing read: the label alone (no port known).
    if (o.tag_readings.empty()) reading(mrptReaderId(o, ""));
    for (const auto& tr : o.tag_readings) {
        auto& x = reading(mrptReaderId(o, tr.antennaPort));
        if (std::find(x.tags.begin(), x.tags.end(), tr.epc) == x.tags.end())
            x.tags.push_back(tr.epc);
    }
    st.rfid = r;
}

void CRawlogReader::warnUnused(const CObservation& o) {
    // MRPT's RFID records are read below; the header is no sensor.
    if (dynamic_cast<const CObservationRFID*>(&o) ||
        dynamic_cast<const rfir::obs::CObservationLogHeader*>(&o))
        return;
    const std::string cls = o.GetRuntimeClass()->className;
    if (warnedClasses_.insert(cls).second)
        std::cerr << "warning: " << path_ << ": observations of class " << cls
                  << " (first one labelled '" << o.sensorLabel
                  << "') are kept in each frame but not used by rfir's methods\n";
}

bool CRawlogReader::next(TRawlogStep& st) {
    if (!readStep(st)) return false;
    checkFinite(st);
    return true;
}

void CRawlogReader::checkFinite(const TRawlogStep& st) const {
    // MRPT reads these doubles unchecked; a NaN would travel into every filter.
    // The message is built only for a value that fails (this runs per instant).
    const auto check = [&](const char* what, const char* fields,
                           std::initializer_list<double> v) {
        if (std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); }))
            return;
        rfir::obs::requireFinite(
            (path_ + ": instant " + std::to_string(st.index + 1) + ": " + what).c_str(),
            fields, v);
    };
    const auto pose = [&](const char* what, const mrpt::poses::CPose2D& p) {
        check(what, "x y phi", {p.x(), p.y(), p.phi()});
    };
    if (st.odometry) pose("odometry", *st.odometry);
    if (st.odometryIncrement) pose("odometry increment", *st.odometryIncrement);
    // Every movement, not only the best: MRPT's getBestMovementEstimation
    // skips one whose covariance is NaN, and the step would read as unmoved.
    if (st.action)
        for (size_t i = 0; i < st.action->size(); i++)
            if (const auto* mv = dynamic_cast<const CActionRobotMovement2D*>(
                    &std::as_const(*st.action).get(i)))
                pose("movement action", mv->rawOdometryIncrementReading);
    if (st.rb)
        for (const auto& m : st.rb->sensedData)
            check("range-bearing", "range yaw pitch", {m.range, m.yaw, m.pitch});
}

bool CRawlogReader::readStep(TRawlogStep& st) {
    CActionCollection::Ptr acts;
    CSensoryFrame::Ptr sf;
    if (obsOnly_) {
        if (!nextFlatInstant(sf)) return false;
        acts = std::make_shared<CActionCollection>();
    } else if (!nextPair(acts, sf))
        return false;
    st = TRawlogStep();
    st.index = steps_++;
    st.action = acts;
    st.sf = sf;
    bool haveT = false;
    for (const auto& o : *sf) {
        if (!haveT) {
            st.t = mrpt::Clock::toDouble(o->timestamp);
            haveT = true;
        }
        if (auto od = std::dynamic_pointer_cast<CObservationOdometry>(o))
            st.odometry = od->odometry;
        else if (auto r =
                     std::dynamic_pointer_cast<rfir::obs::CObservationRFIDReaders>(o))
            st.rfid = r;
        else if (auto i = std::dynamic_pointer_cast<rfir::obs::CObservationIRSignals>(o))
            st.ir = i;
        else if (auto b = std::dynamic_pointer_cast<CObservationBearingRange>(o))
            st.rb = b;
        else
            warnUnused(*o);
    }
    for (const auto& o : *sf)
        if (auto m = std::dynamic_pointer_cast<CObservationRFID>(o)) addMrptRFID(st, *m);
    if (obsOnly_) {
        // Increments between absolute odometry poses; the first only anchors
        // the frame (as rfir::slam::inputsFromSteps and the writer do).
        if (st.odometry) {
            if (lastOdometry_) st.odometryIncrement = *st.odometry - *lastOdometry_;
            lastOdometry_ = st.odometry;
        }
        return true;
    }
    // The writer gives the first odometry record a zero movement (it only
    // anchors the frame), and an instant without odometry one too (MRPT's
    // apps want a movement in every action); a filter would still draw
    // motion noise for them. A real first movement (another program's
    // rawlog) is kept.
    const bool anchor = st.odometry && !sawOdometry_;
    if (st.odometry) sawOdometry_ = true;
    if (auto mv = acts->getBestMovementEstimation()) {
        const auto& inc = mv->rawOdometryIncrementReading;
        const bool zero = inc.x() == 0 && inc.y() == 0 && inc.phi() == 0;
        if (!zero || (st.odometry && !anchor)) st.odometryIncrement = inc;
        if (!haveT) st.t = mrpt::Clock::toDouble(mv->timestamp);
    }
    return true;
}

}  // namespace rfir::common
