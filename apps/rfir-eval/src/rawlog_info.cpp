#include <rfir/common/rawlog_io.h>
#include <rfir/eval/metrics.h>

#include <map>

namespace rfir::eval {
TRawlogInfo readRawlogInfo(const std::string& rawlogPath) {
    rfir::common::CRawlogReader rd(rawlogPath);
    TRawlogInfo info;
    info.readers = rd.header().readers;
    info.rbSensor = rd.header().rbSensor;
    info.startPose = rd.header().startPose;
    const bool readersFromHeader = !info.readers.empty();
    std::map<std::string, rfir::obs::TRFIDReader> seenReaders;
    rfir::common::TPath2D absolute, accumulated;
    mrpt::poses::CPose2D acc;
    rfir::common::TRawlogStep st;
    while (rd.next(st)) {
        info.steps++;
        if (st.odometry) absolute.push_back({st.t, *st.odometry});
        if (st.odometryIncrement) {
            acc = acc + *st.odometryIncrement;
            accumulated.push_back({st.t, acc});
        }
        if (!readersFromHeader && st.rfid)
            for (const auto& r : st.rfid->readings)
                seenReaders.emplace(r.reader.id, r.reader);
    }
    for (const auto& [id, r] : seenReaders) info.readers.push_back(r);
    info.odometry = absolute.empty() ? accumulated : absolute;
    return info;
}

}  // namespace rfir::eval
