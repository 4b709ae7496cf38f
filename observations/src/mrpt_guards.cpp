/* rfir: field checks for MRPT's classes read from a rawlog (mrpt_guards.h). */
#include <rfir/obs/bounded_read.h>
#include <rfir/obs/mrpt_guards.h>

#include "peek_archive.h"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRFID.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rfir::obs {
namespace {
using detail::CPeekArchive;
using detail::peekClassName;
using detail::refuse;
using mrpt::serialization::CArchive;

constexpr const char* kArm = "mrpt::obs::CActionRobotMovement2D";

/** Checks the fields MRPT trusts in CActionRobotMovement2D, versions 3 to 7
 * (estimationMethod, the odometry pose, the motion model and its particle
 * count), with the layout MRPT 2.5.8 writes; older versions: the method. */
void checkRobotMovement2D(CPeekArchive& a, uint8_t version) {
    // Versions 0 and 1 start with the pose change, which MRPT reads as an
    // object of any class, unchecked: not read.
    if (version < 2)
        refuse(kArm, "version " + std::to_string(version) +
                         " (the pose change as an object of any class) is not read");
    const auto method = a.peek<int32_t>();
    using ARM = mrpt::obs::CActionRobotMovement2D;
    if (method == ARM::emScan2DMatching) {
        // Only a CPosePDFGaussian of version 2 (pose and 6 doubles): the other
        // PDFs, and its older versions (a CMatrixD), size themselves from
        // counts MRPT reads unchecked.
        const auto name = peekClassName(a, kArm);
        const auto* id = mrpt::rtti::findRegisteredClass(name);
        if (!id || !id->derivedFrom(CLASS_ID(mrpt::poses::CPosePDF)))
            refuse(kArm, "the pose change is a '" + name + "', not a pose PDF");
        if (name != "mrpt::poses::CPosePDFGaussian" || a.peek<uint8_t>() != 2)
            refuse(kArm, "the pose change is a '" + name +
                             "': only a CPosePDFGaussian (version 2) is read");
        return;
    }
    if (method != ARM::emOdometry)
        refuse(kArm, "estimationMethod " + std::to_string(method) +
                         " is neither emOdometry (0) nor emScan2DMatching (1)");
    // Version 2 keeps 44 bytes of old options, which MRPT ignores (the
    // default Gaussian model); version 3 has the model, 5 floats and the
    // Thrun particle count, as later versions with 6 floats.
    if (version < 3) return;
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
    a.peekBytes(gauss, (version == 3 ? 5 : 6) * sizeof(float));
    const auto particles = a.peek<uint32_t>();
    if (model == ARM::mmThrun && particles > TMrptReadBounds::kMaxThrunParticles)
        refuse(kArm, "Thrun model particle count " + std::to_string(particles) +
                         " is above the bound " +
                         std::to_string(TMrptReadBounds::kMaxThrunParticles));
}

/** A container (CActionCollection, CSensoryFrame) starts with its object count. */
uint32_t checkContainerCount(CPeekArchive& a, const char* cls) {
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
    return n;
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

/** CObservationOdometry versions 0-2 (MRPT 2.5.8 writes 2): the pose, then the label. */
void checkOdometry(CPeekArchive& a, uint8_t version) {
    constexpr const char* kCls = "mrpt::obs::CObservationOdometry";
    if (version > 2) return;  // MRPT refuses it; 0-2 start alike
    peekPoseObject(a, kCls, "mrpt::poses::CPose2D", 1, 3);
    const auto len = a.peek<uint32_t>();
    const auto left = bytesLeftInStream();
    if (len > TReadBounds::kMaxLabelBytes || (left && len > *left))
        refuse(kCls,
               "sensorLabel length " + std::to_string(len) + " is above the bound " +
                   std::to_string(TReadBounds::kMaxLabelBytes) + " or the bytes left");
}

/** Reads ahead a string in MRPT's layout (uint32 length, bytes), bounded by
 * the label bound and the bytes left. */
void peekLabel(CPeekArchive& a, const char* cls, const char* what) {
    const auto len = a.peek<uint32_t>();
    const auto left = bytesLeftInStream();
    if (len > TReadBounds::kMaxLabelBytes || (left && len > *left))
        refuse(cls, std::string(what) + " length " + std::to_string(len) +
                        " is above the bound " +
                        std::to_string(TReadBounds::kMaxLabelBytes) +
                        " or the bytes left");
    std::string s(len, '\0');
    if (len) a.peekBytes(s.data(), len);
}

/** A count of `minBytesEach`-byte items, bounded by `maxCount` and the bytes left. */
uint32_t peekCount(CPeekArchive& a, const char* cls, const char* what, uint32_t maxCount,
                   uint64_t minBytesEach) {
    const auto n = a.peek<uint32_t>();
    const auto left = bytesLeftInStream();
    if (n > maxCount || (left && n * minBytesEach > *left))
        refuse(cls, std::string(what) + " " + std::to_string(n) + " is above the bound " +
                        std::to_string(maxCount) + " or the bytes left");
    return n;
}

/** A 3x3 covariance as MRPT writes a CMatrixFixed<double,3,3>: a CMatrixD
 * object (version 0: uint32 rows and columns, the doubles), end 0x88. MRPT
 * sizes the matrix from the stored rows and columns before checking them. */
void peekCovariance(CPeekArchive& a, const char* cls) {
    if (peekClassName(a, cls) != "mrpt::math::CMatrixD" || a.peek<uint8_t>() != 0)
        refuse(cls, "a covariance is not a CMatrixD (version 0)");
    const auto rows = a.peek<uint32_t>(), cols = a.peek<uint32_t>();
    if (rows != 3 || cols != 3)
        refuse(cls, "a covariance is " + std::to_string(rows) + "x" +
                        std::to_string(cols) + ", not 3x3");
    double m[9];
    a.peekBytes(m, sizeof(m));
    if (a.peek<uint8_t>() != 0x88) refuse(cls, "a covariance is cut short");
}

/** CObservationBearingRange versions 0-3 (MRPT 2.5.8 writes 3): 4 floats (3
 * before version 3), the sensor pose, the timestamp (from version 2),
 * validCovariances and without covariances 3 float deviations (version 3);
 * the measurement count, the measurements (16 bytes, then a covariance when
 * valid), the label (from version 1). */
void checkBearingRange(CPeekArchive& a, uint8_t version) {
    constexpr const char* kCls = "mrpt::obs::CObservationBearingRange";
    if (version > 3) return;  // MRPT refuses it
    float f[4];
    a.peekBytes(f, (version >= 3 ? 4 : 3) * sizeof(float));
    peekPoseObject(a, kCls, "mrpt::poses::CPose3D", 3, 12);
    if (version >= 2) (void)a.peek<uint64_t>();  // timestamp
    uint8_t validCov = 0;
    if (version >= 3) {
        validCov = a.peek<uint8_t>();
        if (validCov > 1)
            refuse(kCls, "validCovariances byte " + std::to_string(validCov) +
                             " is neither 0 nor 1");
        if (!validCov) {
            float sd[3];
            a.peekBytes(sd, sizeof(sd));
        }
    }
    // A covariance object takes 1 + 20 + 1 + 8 + 72 + 1 bytes.
    const uint64_t each = validCov ? 16 + 103 : 16;
    const auto n =
        peekCount(a, kCls, "measurement count", TMrptReadBounds::kMaxMeasurements, each);
    for (uint32_t i = 0; i < n; i++) {
        uint8_t m[16];
        a.peekBytes(m, sizeof(m));
        if (validCov) peekCovariance(a, kCls);
    }
    if (version >= 1) peekLabel(a, kCls, "sensorLabel");
}

/** CObservationRFID version 4 (MRPT 2.5.8): the tag count, the powers
 * (doubles), the EPCs, the antenna ports (strings), the label. Older
 * versions store the count as a string. */
void checkRFID(CPeekArchive& a, uint8_t version) {
    constexpr const char* kCls = "mrpt::obs::CObservationRFID";
    if (version > 4) return;
    uint64_t n = 0;
    const auto left = bytesLeftInStream();
    if (version < 4) {
        const auto len = a.peek<uint32_t>();
        if (len > 10)
            refuse(kCls, "tag count string of " + std::to_string(len) + " bytes");
        std::string s(len, '\0');
        if (len) a.peekBytes(s.data(), len);
        n = std::strtoull(s.c_str(), nullptr, 10);  // MRPT reads it with atoi
        if (n > TReadBounds::kMaxTagsPerReading || (left && n * 16 > *left))
            refuse(kCls, "tag count " + s + " is above the bound or the bytes left");
    } else {
        // Each tag: a double and two string lengths at least.
        n = peekCount(a, kCls, "tag count", TReadBounds::kMaxTagsPerReading, 16);
    }
    std::vector<double> power(n);
    if (n) a.peekBytes(power.data(), n * sizeof(double));
    for (uint64_t i = 0; i < 2 * n; i++) peekLabel(a, kCls, "EPC/antenna port");
    peekLabel(a, kCls, "sensorLabel");
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

class CGuardedRFID : public mrpt::obs::CObservationRFID {
  protected:
    void serializeFrom(CArchive& in, uint8_t version) override {
        CPeekArchive a(in);
        checkRFID(a, version);
        CObservationRFID::serializeFrom(a, version);
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

/** Reads member `i` of a container, refusing a null or foreign object: MRPT
 * keeps what ReadObject<T> returns, and a null action crashes
 * CActionCollection::serializeFrom (a null deepcopy_poly_ptr is cloned). */
template <class T>
typename T::Ptr readMember(CArchive& a, const char* cls, uint32_t i) {
    const auto o = readCheckedObject(a, cls, i);
    auto t = std::dynamic_pointer_cast<T>(o);
    if (!t)
        refuse(cls, "object " + std::to_string(i) + " is " +
                        (o ? std::string("a ") + o->GetRuntimeClass()->className
                           : std::string("nullptr")) +
                        ", not a " + T::GetRuntimeClassIdStatic().className);
    return t;
}

// The containers are read here, member by member, in MRPT 2.5.8's layout
// (the count, then the objects); other versions go to MRPT, which refuses them.
class CGuardedActionCollection : public mrpt::obs::CActionCollection {
  protected:
    void serializeFrom(CArchive& in, uint8_t version) override {
        constexpr const char* kCls = "mrpt::obs::CActionCollection";
        CPeekArchive a(in);
        const auto n = checkContainerCount(a, kCls);
        if (version != 0) return CActionCollection::serializeFrom(a, version);
        (void)a.ReadAs<uint32_t>();
        clear();
        for (uint32_t i = 0; i < n; i++)
            insertPtr(readMember<mrpt::obs::CAction>(a, kCls, i));
    }
};

class CGuardedSensoryFrame : public mrpt::obs::CSensoryFrame {
  protected:
    void serializeFrom(CArchive& in, uint8_t version) override {
        constexpr const char* kCls = "mrpt::obs::CSensoryFrame";
        CPeekArchive a(in);
        // Versions 0 and 1 (MRPT before 2009) put other fields before the
        // count, which sizes the frame as well: not read.
        if (version < 2)
            refuse(kCls, "version " + std::to_string(version) +
                             " (MRPT before 2009) is not read");
        const auto n = checkContainerCount(a, kCls);
        if (version != 2) return CSensoryFrame::serializeFrom(a, version);
        (void)a.ReadAs<uint32_t>();
        clear();
        for (uint32_t i = 0; i < n; i++)
            insert(readMember<mrpt::obs::CObservation>(a, kCls, i));
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

const std::vector<const mrpt::rtti::TRuntimeClassId*>& guardIds() {
    using namespace mrpt::obs;
    static const std::vector<const mrpt::rtti::TRuntimeClassId*> ids = {
        guardId<CGuardedRobotMovement2D, CActionRobotMovement2D>(),
        guardId<CGuardedActionCollection, CActionCollection>(),
        guardId<CGuardedSensoryFrame, CSensoryFrame>(),
        guardId<CGuardedOdometry, CObservationOdometry>(),
        guardId<CGuardedBearingRange, CObservationBearingRange>(),
        guardId<CGuardedRFID, CObservationRFID>()};
    return ids;
}
}  // namespace

const std::vector<std::string>& detail::guardedClassNames() {
    static const auto names = [] {
        std::vector<std::string> v;
        for (const auto* id : guardIds()) v.emplace_back(id->className);
        return v;
    }();
    return names;
}

void registerMrptGuards() {
    static const bool done = [] {
        // MRPT warns on std::cerr that a name is registered again: that is the
        // point here, so the warning is kept out of every program's output.
        // The lookup makes MRPT process its queue of pending registrations now.
        std::ostringstream quiet;
        auto* const old = std::cerr.rdbuf(quiet.rdbuf());
        for (const auto* id : guardIds()) {
            mrpt::rtti::registerClass(id);
            mrpt::rtti::findRegisteredClass(id->className);
        }
        std::cerr.rdbuf(old);
        return true;
    }();
    (void)done;
}

}  // namespace rfir::obs
