/* rfir: checks on MRPT's own classes as read from a rawlog.
 *
 * MRPT 2.5.8's readers trust the file: CActionRobotMovement2D crashes
 * (SIGSEGV) on an estimationMethod other than emOdometry followed by anything
 * but a pose PDF, and allocates from unchecked counts (Thrun model particles,
 * the objects of a CActionCollection or CSensoryFrame, the counts and strings
 * of CObservationOdometry, CObservationBearingRange, CObservationRFID). These
 * guards replace
 * those classes in MRPT's class registry by subclasses that check the fields
 * first, then let MRPT parse the same bytes; objects keep MRPT's class (and
 * are written exactly as before). Any other MRPT class, whose reader is not
 * checked, is refused by name inside a CCheckedClassesScope (rfir's own
 * rawlog reader). See docs/hardening.md. */
#pragma once

#include <mrpt/serialization/CArchive.h>

#include <string>

namespace rfir::obs {
/** Registers the guards (idempotent; called by registerAllClasses). */
void registerMrptGuards();

/** Bounds applied by the guards (docs/hardening.md). */
struct TMrptReadBounds {
    static constexpr unsigned kMaxObjectsPerContainer = 4096;
    static constexpr unsigned kMaxThrunParticles = 100000;
    static constexpr unsigned kMaxMeasurements = 1 << 20;  //!< bearing-range
};

/** While one is alive on this thread, the objects read through
 * readCheckedObject (the members of frames and action collections, and the
 * entries of a rawlog read by rfir::common::CRawlogReader) must be of a
 * class whose reader is checked: a guarded MRPT class or one of rfir's. Any
 * other MRPT class is refused by name before MRPT reads it, since MRPT's
 * readers allocate from counts they do not check (a corrupt one took 23 GB:
 * docs/hardening.md), unless the environment variable
 * RFIR_TRUST_MRPT_CLASSES lists it (comma-separated, full or short names;
 * "*" for all). Without a scope (MRPT's own programs with the plugin) every
 * registered class is read, as MRPT does. */
class CCheckedClassesScope {
  public:
    CCheckedClassesScope();
    ~CCheckedClassesScope();
    CCheckedClassesScope(const CCheckedClassesScope&) = delete;
    CCheckedClassesScope& operator=(const CCheckedClassesScope&) = delete;

  private:
    bool prev_;
};

/** The environment variable of CCheckedClassesScope. */
inline constexpr const char* kTrustClassesEnv = "RFIR_TRUST_MRPT_CLASSES";

/** Reads one object (MRPT's ReadObject), first refusing, inside a
 * CCheckedClassesScope, a class not checked nor trusted; `where` (and, when
 * not negative, `index` as "object N") name it in the error. */
mrpt::serialization::CSerializable::Ptr readCheckedObject(
    mrpt::serialization::CArchive& in, const char* where, int64_t index = -1);
}  // namespace rfir::obs
