#include <rfir/common/rawlog_io.h>
#include <rfir/eval/metrics.h>

namespace rfir::eval {
CRawlogInfoBuilder::CRawlogInfoBuilder(const rfir::obs::CObservationLogHeader& h) {
    info_.readers = h.readers;
    info_.rbSensor = h.rbSensor;
    info_.startPose = h.startPose;
    readersFromHeader_ = !info_.readers.empty();
}

void CRawlogInfoBuilder::add(const rfir::common::TRawlogStep& st) {
    info_.steps++;
    info_.instantTimes.push_back(st.t);
    if (st.odometry) absolute_.push_back({st.t, *st.odometry});
    if (st.odometryIncrement) {
        acc_ = acc_ + *st.odometryIncrement;
        accumulated_.push_back({st.t, acc_});
    }
    if (!readersFromHeader_ && st.rfid)
        for (const auto& r : st.rfid->readings)
            seenReaders_.emplace(r.reader.id, r.reader);
}

TRawlogInfo CRawlogInfoBuilder::finish() {
    TRawlogInfo info = info_;
    for (const auto& [id, r] : seenReaders_) info.readers.push_back(r);
    info.odometry = absolute_.empty() ? accumulated_ : absolute_;
    return info;
}

TRawlogInfo readRawlogInfo(const std::string& rawlogPath) {
    rfir::common::CRawlogReader rd(rawlogPath);
    CRawlogInfoBuilder b(rd.header());
    rfir::common::TRawlogStep st;
    while (rd.next(st)) b.add(st);
    TRawlogInfo info = b.finish();
    info.hasHeader = rd.hasHeader();
    return info;
}

}  // namespace rfir::eval
