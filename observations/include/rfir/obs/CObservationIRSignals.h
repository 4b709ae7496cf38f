/* rfir: IR photodiode receivers reading ceiling emitters (thesis chapter 5). */
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rfir::obs {
/** One IR photodiode receiver on the robot (robot frame, z = height above the
 * floor, metres). */
struct TIRReceiver {
    std::string id;
    double x = 0, y = 0, z = 0;
    bool operator==(const TIRReceiver& o) const {
        return id == o.id && x == o.x && y == o.y && z == o.z;
    }
};

/** What each receiver saw at one instant: the decoded frequency codes (1..9,
 * ascending), the amplified voltage, and optionally the raw sampled window it
 * was decoded from. */
class CObservationIRSignals : public mrpt::obs::CObservation {
    DEFINE_SERIALIZABLE(CObservationIRSignals, rfir::obs)

  public:
    struct TReading {
        TIRReceiver receiver;
        std::vector<uint8_t> codes;  //!< ascending, 1..9; empty: nothing in view
        double volts = 0;
        double rateHz = 0;       //!< > 0 only when raw samples are kept
        std::vector<float> raw;  //!< raw sampled voltage window (optional)
        bool hasRaw() const { return rateHz > 0 && !raw.empty(); }
        /** Emitter ID formed by the codes ("39" for codes 3 and 9). */
        std::string emitterId() const;
        bool operator==(const TReading& o) const {
            return receiver == o.receiver && codes == o.codes && volts == o.volts &&
                   rateHz == o.rateHz && raw == o.raw;
        }
    };
    std::vector<TReading> readings;

    void getSensorPose(mrpt::poses::CPose3D& p) const override {
        p = mrpt::poses::CPose3D();
    }
    void setSensorPose(const mrpt::poses::CPose3D&) override {}
    using mrpt::obs::CObservation::getSensorPose;
    using mrpt::obs::CObservation::setSensorPose;
    void getDescriptionAsText(std::ostream& o) const override;
    bool exportTxtSupported() const override { return true; }
    std::string exportTxtHeader() const override;
    std::string exportTxtDataRow() const override;
};

}  // namespace rfir::obs
