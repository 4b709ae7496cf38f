/* rfir: text records -> MRPT observations of one instant, timestamps, header. */
#include <rfir/common/log_convert.h>

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>

namespace rfir::common {
using namespace rfir::obs;

TLogFileKind logFileKind(const std::string& path) {
    std::string low;
    for (char c : path) low += char(std::tolower(static_cast<unsigned char>(c)));
    const auto ends = [&](const std::string& e) {
        return low.size() > e.size() &&
               low.compare(low.size() - e.size(), e.size(), e) == 0;
    };
    if (ends(".txt")) return TLogFileKind::Text;
    if (ends(".rawlog")) return TLogFileKind::Rawlog;
    return TLogFileKind::Other;
}

mrpt::poses::CPose2D exactPose(double x, double y, double phi) {
    mrpt::poses::CPose2D p(x, y, 0);
    p.phi(phi);
    return p;
}

std::optional<mrpt::Clock::time_point> timestampFromT(double t) {
    // MRPT's fromDouble converts through an unsigned tick count: negative or
    // huge times would wrap around.
    if (!(t >= 0 && t < 1e11)) return std::nullopt;
    return mrpt::Clock::fromDouble(t);
}

std::optional<std::string> formatTimestamp(mrpt::Clock::time_point ts) {
    // fromDouble truncates t * 1e7 to whole ticks, so the double nearest to
    // the tick may land on the tick below: try its neighbours too, then keep
    // the fewest digits that still give back this very tick.
    const double d0 = mrpt::Clock::toDouble(ts);
    double cand[5] = {d0, 0, 0, 0, 0};
    cand[1] = std::nextafter(d0, 1e300);
    cand[2] = std::nextafter(cand[1], 1e300);
    cand[3] = std::nextafter(d0, -1e300);
    cand[4] = std::nextafter(cand[2], 1e300);
    for (int p = 1; p <= 17; p++)
        for (double d : cand) {
            char buf[64];
            const auto r =
                std::to_chars(buf, buf + sizeof(buf), d, std::chars_format::general, p);
            const std::string s(buf, r.ptr);
            const auto back = parseDecimal(s);
            if (!back) continue;
            const auto tb = timestampFromT(*back);
            if (tb && *tb == ts) return s;
        }
    return std::nullopt;
}

CObservationLogHeader toLogHeader(const TTextLogHeader& h,
                                  const std::vector<std::string>& landmarks, double t0) {
    CObservationLogHeader o;
    o.sensorLabel = "HEADER";
    // CObservation's constructor stamps the current time: replace it.
    o.timestamp = timestampFromT(t0).value_or(mrpt::Clock::fromDouble(0));
    o.readers = h.readers;
    o.receivers = h.receivers;
    o.rbSensor = h.rbSensor;
    if (h.start) o.startPose = exactPose(h.start->x, h.start->y, h.start->phi);
    o.rbLandmarkNames = landmarks;
    return o;
}

TTextLogHeader fromLogHeader(const CObservationLogHeader& o) {
    TTextLogHeader h;
    h.readers = o.readers;
    h.receivers = o.receivers;
    h.rbSensor = o.rbSensor;
    // A heading of -pi (MRPT's CPose2D(x, y, pi) gives it) is pi in the text,
    // whose angles are in (-pi, pi].
    if (o.startPose)
        h.start = TTextLogHeader::TStart{
            o.startPose->x(), o.startPose->y(),
            o.startPose->phi() == -M_PI ? M_PI : o.startPose->phi()};
    return h;
}

CInstantBuilder::CInstantBuilder(const CObservationLogHeader& hdr,
                                 const rfir::ir::TDecoderParams& decoder)
    : hdr_(hdr), decoder_(decoder) {
    for (size_t i = 0; i < hdr_.rbLandmarkNames.size(); i++)
        landmarkIds_.emplace(hdr_.rbLandmarkNames[i], int32_t(i));
}

int32_t CInstantBuilder::landmarkId(const std::string& name) const {
    const auto it = landmarkIds_.find(name);
    return it == landmarkIds_.end() ? -1 : it->second;
}

namespace {
template <class T>
const T* findById(const std::vector<T>& v, const std::string& id) {
    for (const auto& e : v)
        if (e.id == id) return &e;
    return nullptr;
}

void addRb(const TTimedRecord& r, const CObservationLogHeader& hdr, int32_t lmId,
           mrpt::obs::CObservationBearingRange::Ptr& rb) {
    if (!hdr.rbSensor) throw std::runtime_error("rb record without an rb_sensor header");
    if (!rb) {
        const auto& s = *hdr.rbSensor;
        rb = mrpt::obs::CObservationBearingRange::Create();
        rb->sensorLabel = "RB";
        rb->sensorLocationOnRobot = mrpt::poses::CPose3D(s.x, s.y, 0, s.yaw, 0, 0);
        rb->minSensorDistance = 0;
        rb->maxSensorDistance = float(s.maxRange);
        rb->fieldOfView_yaw = float(s.fov);
        rb->fieldOfView_pitch = 0;  // a planar sensor (as the simulator writes it)
    }
    mrpt::obs::CObservationBearingRange::TMeasurement m;
    m.range = r.range;
    m.yaw = r.bearing;
    m.pitch = 0;
    m.landmarkID = lmId;
    m.covariance.setZero();
    rb->sensedData.push_back(m);
}
}  // namespace

void addDarkReceivers(const CObservationLogHeader& hdr, CObservationIRSignals& ir) {
    // textlog 1 writes what a receiver sees; at an instant with IR records,
    // a declared receiver without one saw nothing (negative information the
    // IR localizer uses): it gets a reading with no code, 0 V and no window,
    // after the others, in header order.
    const size_t n = ir.readings.size();
    for (const auto& rc : hdr.receivers) {
        bool named = false;
        for (size_t i = 0; i < n && !named; i++)
            named = ir.readings[i].receiver.id == rc.id;
        if (named) continue;
        CObservationIRSignals::TReading rd;
        rd.receiver = rc;
        ir.readings.push_back(std::move(rd));
    }
}

void CInstantBuilder::build(const std::vector<TTimedRecord>& recs,
                            std::optional<mrpt::poses::CPose2D>& odometry,
                            std::vector<mrpt::obs::CObservation::Ptr>& obs) const {
    using K = TTimedRecord::Kind;
    odometry.reset();
    obs.clear();
    CObservationRFIDReaders::Ptr rfid;
    CObservationIRSignals::Ptr ir;
    mrpt::obs::CObservationBearingRange::Ptr rb;
    for (const auto& r : recs) {
        const std::string where =
            "record '" + std::string(kindName(r.kind)) + " " + r.id + "'";
        if (r.kind == K::Odom)
            odometry = exactPose(r.x, r.y, r.phi);
        else if (r.kind == K::Rfid) {
            const auto* rd = findById(hdr_.readers, r.id);
            if (!rd) throw std::runtime_error(where + ": undeclared reader");
            if (!rfid) {
                rfid = CObservationRFIDReaders::Create();
                rfid->sensorLabel = "RFID";
            }
            rfid->readings.push_back({*rd, r.tags});
        } else if (r.kind == K::Ir || r.kind == K::IrRaw) {
            const auto* rc = findById(hdr_.receivers, r.id);
            if (!rc) throw std::runtime_error(where + ": undeclared receiver");
            if (!ir) {
                ir = CObservationIRSignals::Create();
                ir->sensorLabel = "IR";
            }
            CObservationIRSignals::TReading rd;
            rd.receiver = *rc;
            if (r.kind == K::Ir) {
                rd.codes = r.codes;
                rd.volts = r.volts;
            } else {
                const auto dec = rfir::ir::decodeIRWindow(r.samples, r.rateHz, decoder_);
                rd.codes = dec.codes;
                rd.volts = dec.volts;
                rd.rateHz = r.rateHz;
                rd.raw = r.samples;
            }
            ir->readings.push_back(std::move(rd));
        } else
            addRb(r, hdr_, landmarkId(r.id), rb);
    }
    std::optional<mrpt::Clock::time_point> ts;
    if (!recs.empty() && !(ts = timestampFromT(recs[0].t)))
        throw std::runtime_error("t " + formatNumber(recs[0].t) +
                                 " cannot be an MRPT timestamp");
    if (ir) addDarkReceivers(hdr_, *ir);
    if (rfid) obs.push_back(rfid);
    if (ir) obs.push_back(ir);
    if (rb) obs.push_back(rb);
    for (auto& o : obs) o->timestamp = *ts;
}

bool sameSerialization(const mrpt::serialization::CSerializable& a,
                       const mrpt::serialization::CSerializable& b) {
    mrpt::io::CMemoryStream sa, sb;
    auto aa = mrpt::serialization::archiveFrom(sa);
    auto ab = mrpt::serialization::archiveFrom(sb);
    aa << a;
    ab << b;
    return sa.getTotalBytesCount() == sb.getTotalBytesCount() &&
           std::memcmp(sa.getRawBufferData(), sb.getRawBufferData(),
                       sa.getTotalBytesCount()) == 0;
}

}  // namespace rfir::common
