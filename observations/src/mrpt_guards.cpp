/* rfir: field checks for MRPT's classes read from a rawlog (mrpt_guards.h). */
#include <rfir/obs/bounded_read.h>
#include <rfir/obs/mrpt_guards.h>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cstring>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rfir::obs {
namespace {
using mrpt::serialization::CArchive;

/** Reads ahead from an archive, then serves the bytes read ahead again before
 * the rest: MRPT's parser sees the object exactly as stored. */
class CPeekArchive : public CArchive {
  public:
    explicit CPeekArchive(CArchive& in) : in_(in) {}
    template <class T>
    T peek() {
        T v;
        peekBytes(&v, sizeof(v));
        return v;
    }
    void peekBytes(void* b, size_t n) {
        const size_t at = buf_.size();
        buf_.resize(at + n);
        in_.ReadBuffer(buf_.data() + at, n);
        std::memcpy(b, buf_.data() + at, n);
    }

  protected:
    size_t write(const void*, size_t) override {
        throw std::logic_error("CPeekArchive: read only");
    }
    size_t read(void* b, size_t n) override {
        size_t k = 0;
        if (pos_ < buf_.size()) {
            k = std::min(n, buf_.size() - pos_);
            std::memcpy(b, buf_.data() + pos_, k);
            pos_ += k;
        }
        if (k < n) k += in_.ReadBuffer(static_cast<uint8_t*>(b) + k, n - k);
        return k;
    }

  private:
    CArchive& in_;
    std::vector<uint8_t> buf_;
    size_t pos_ = 0;
};

[[noreturn]] void refuse(const std::string& cls, const std::string& why) {
    throw std::runtime_error(cls + ": " + why +
                             " (corrupt data; refused before MRPT parses it)");
}

/** The class name of the serialized object that follows (MRPT's header: a
 * length byte, 0x80 set in the current format, then the name). */
std::string peekClassName(CPeekArchive& a, const char* cls) {
    const auto len = a.peek<uint8_t>();
    if (!(len & 0x80)) refuse(cls, "object in MRPT's pre-2008 format");
    std::string name(len & 0x7F, '\0');
    if (!name.empty()) a.peekBytes(name.data(), name.size());
    return name;
}

constexpr const char* kArm = "mrpt::obs::CActionRobotMovement2D";

/** Checks the fields MRPT trusts in CActionRobotMovement2D, versions 4 to 7
 * (estimationMethod, the odometry pose, the motion model and its particle
 * count), with the layout MRPT 2.5.8 writes; older versions: the method. */
void checkRobotMovement2D(CPeekArchive& a, uint8_t version) {
    if (version < 2) return;  // pose PDF first: MRPT reads it as an object
    const auto method = a.peek<int32_t>();
    using ARM = mrpt::obs::CActionRobotMovement2D;
    if (method == ARM::emScan2DMatching) {
        const auto name = peekClassName(a, kArm);
        const auto* id = mrpt::rtti::findRegisteredClass(name);
        if (!id || !id->derivedFrom(CLASS_ID(mrpt::poses::CPosePDF)))
            refuse(kArm, "the pose change is a '" + name + "', not a pose PDF");
        return;
    }
    if (method != ARM::emOdometry)
        refuse(kArm, "estimationMethod " + std::to_string(method) +
                         " is neither emOdometry (0) nor emScan2DMatching (1)");
    if (version < 4) return;
    // The odometry increment: a CPose2D object, version 1 (3 doubles), end 0x88.
    if (peekClassName(a, kArm) != "mrpt::poses::CPose2D" || a.peek<uint8_t>() != 1)
        refuse(kArm, "the odometry increment is not a CPose2D (version 1)");
    double xyz[3];
    a.peekBytes(xyz, sizeof(xyz));
    if (a.peek<uint8_t>() != 0x88) refuse(kArm, "the odometry increment is cut short");
    const auto model = a.peek<int32_t>();
    if (model != ARM::mmGaussian && model != ARM::mmThrun)
        refuse(kArm, "motion model " + std::to_string(model) + " is neither 0 nor 1");
    float gauss[6];
    a.peekBytes(gauss, sizeof(gauss));
    const auto particles = a.peek<uint32_t>();
    if (model == ARM::mmThrun && particles > TMrptReadBounds::kMaxThrunParticles)
        refuse(kArm, "Thrun model particle count " + std::to_string(particles) +
                         " is above the bound " +
                         std::to_string(TMrptReadBounds::kMaxThrunParticles));
}

/** A container (CActionCollection, CSensoryFrame) starts with its object count. */
void checkContainerCount(CPeekArchive& a, const char* cls) {
    const auto n = a.peek<uint32_t>();
    // Each object takes at least a name-length byte, a one-letter name, a
    // version byte and the end marker.
    constexpr uint64_t kMinObjectBytes = 4;
    const auto left = bytesLeftInStream();
    if (n > TMrptReadBounds::kMaxObjectsPerContainer)
        refuse(cls, "object count " + std::to_string(n) + " is above the bound " +
                        std::to_string(TMrptReadBounds::kMaxObjectsPerContainer));
    if (left && n * kMinObjectBytes > *left)
        refuse(cls, "object count " + std::to_string(n) + " exceeds the " +
                        std::to_string(*left) + " bytes left");
}

/** Reads ahead a whole pose object of class `name` (version `ver`, `n` doubles). */
void peekPoseObject(CPeekArchive& a, const char* cls, const char* name, uint8_t ver,
                    size_t n) {
    if (peekClassName(a, cls) != name || a.peek<uint8_t>() != ver)
        refuse(cls, std::string("expected a ") + name + " (version " +
                        std::to_string(ver) + ")");
    std::vector<double> v(n);
    a.peekBytes(v.data(), n * sizeof(double));
    if (a.peek<uint8_t>() != 0x88)
        refuse(cls, std::string("the ") + name + " is cut short");
}

/** CObservationOdometry version 2 (MRPT 2.5.8): the pose, then the label. */
void checkOdometry(CPeekArchive& a, uint8_t version) {
    constexpr const char* kCls = "mrpt::obs::CObservationOdometry";
    if (version != 2) return;
    peekPoseObject(a, kCls, "mrpt::poses::CPose2D", 1, 3);
    const auto len = a.peek<uint32_t>();
    const auto left = bytesLeftInStream();
    if (len > TReadBounds::kMaxLabelBytes || (left && len > *left))
        refuse(kCls,
               "sensorLabel length " + std::to_string(len) + " is above the bound " +
                   std::to_string(TReadBounds::kMaxLabelBytes) + " or the bytes left");
}

/** CObservationBearingRange version 3 (MRPT 2.5.8): 4 floats, the sensor pose,
 * the timestamp, validCovariances; without covariances 3 float deviations,
 * then the measurement count (16 bytes each at least). */
void checkBearingRange(CPeekArchive& a, uint8_t version) {
    constexpr const char* kCls = "mrpt::obs::CObservationBearingRange";
    if (version != 3) return;
    float f[4];
    a.peekBytes(f, sizeof(f));
    peekPoseObject(a, kCls, "mrpt::poses::CPose3D", 3, 12);
    (void)a.peek<uint64_t>();  // timestamp
    const auto validCov = a.peek<uint8_t>();
    if (validCov > 1)
        refuse(kCls, "validCovariances byte " + std::to_string(validCov) +
                         " is neither 0 nor 1");
    if (validCov) return;  // the layout with covariances is not checked
    float sd[3];
    a.peekBytes(sd, sizeof(sd));
    const auto n = a.peek<uint32_t>();
    const auto left = bytesLeftInStream();
    if (n > TMrptReadBounds::kMaxMeasurements || (left && uint64_t(n) * 16 > *left))
        refuse(kCls, "measurement count " + std::to_string(n) + " is above the bound " +
                         std::to_string(TMrptReadBounds::kMaxMeasurements) +
                         " or the bytes left");
}

class CGuardedOdometry : public mrpt::obs::CObservationOdometry {
  protected:
    void serializeFrom(CArchive& in, uint8_t version) override {
        CPeekArchive a(in);
        checkOdometry(a, version);
        CObservationOdometry::serializeFrom(a, version);
    }
};

class CGuardedBearingRange : public mrpt::obs::CObservationBearingRange {
  protected:
    void serializeFrom(CArchive& in, uint8_t version) override {
        CPeekArchive a(in);
        checkBearingRange(a, version);
        CObservationBearingRange::serializeFrom(a, version);
    }
};

class CGuardedRobotMovement2D : public mrpt::obs::CActionRobotMovement2D {
  protected:
    void serializeFrom(CArchive& in, uint8_t version) override {
        CPeekArchive a(in);
        checkRobotMovement2D(a, version);
        CActionRobotMovement2D::serializeFrom(a, version);
    }
};

class CGuardedActionCollection : public mrpt::obs::CActionCollection {
  protected:
    void serializeFrom(CArchive& in, uint8_t version) override {
        CPeekArchive a(in);
        checkContainerCount(a, "mrpt::obs::CActionCollection");
        CActionCollection::serializeFrom(a, version);
    }
};

class CGuardedSensoryFrame : public mrpt::obs::CSensoryFrame {
  protected:
    void serializeFrom(CArchive& in, uint8_t version) override {
        CPeekArchive a(in);
        // Versions 0 and 1 (before 2009) start with a timestamp.
        if (version >= 2) checkContainerCount(a, "mrpt::obs::CSensoryFrame");
        CSensoryFrame::serializeFrom(a, version);
    }
};

template <class GUARD, class BASE>
const mrpt::rtti::TRuntimeClassId* guardId() {
    // Same name and base as MRPT's entry: only the factory differs.
    static const mrpt::rtti::TRuntimeClassId id = {
        CLASS_ID(BASE)->className,
        [] {
            return std::static_pointer_cast<mrpt::rtti::CObject>(
                std::make_shared<GUARD>());
        },
        CLASS_ID(BASE)->getBaseClass};
    return &id;
}
}  // namespace

void registerMrptGuards() {
    static const bool done = [] {
        using namespace mrpt::obs;
        // MRPT warns on std::cerr that a name is registered again: that is the
        // point here, so the warning is kept out of every program's output.
        // The lookup makes MRPT process its queue of pending registrations now.
        std::ostringstream quiet;
        auto* const old = std::cerr.rdbuf(quiet.rdbuf());
        for (const auto* id :
             {guardId<CGuardedRobotMovement2D, CActionRobotMovement2D>(),
              guardId<CGuardedActionCollection, CActionCollection>(),
              guardId<CGuardedSensoryFrame, CSensoryFrame>(),
              guardId<CGuardedOdometry, CObservationOdometry>(),
              guardId<CGuardedBearingRange, CObservationBearingRange>()}) {
            mrpt::rtti::registerClass(id);
            mrpt::rtti::findRegisteredClass(id->className);
        }
        std::cerr.rdbuf(old);
        return true;
    }();
    (void)done;
}

}  // namespace rfir::obs
