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
 * are written exactly as before). See docs/hardening.md. */
#pragma once

namespace rfir::obs {
/** Registers the guards (idempotent; called by registerAllClasses). */
void registerMrptGuards();

/** Bounds applied by the guards (docs/hardening.md). */
struct TMrptReadBounds {
    static constexpr unsigned kMaxObjectsPerContainer = 4096;
    static constexpr unsigned kMaxThrunParticles = 100000;
    static constexpr unsigned kMaxMeasurements = 1 << 20;  //!< bearing-range
};
}  // namespace rfir::obs
