/* rfir: registers the map classes with MRPT's RTTI (the map-type registry is
 * filled by MAP_DEFINITION_REGISTER at load time). */
#include <rfir/maps/CRFIDTagParticleMap.h>

#include <mrpt/rtti/CObject.h>
#include <rfir/obs/registerAllClasses.h>

// The class also registers itself from CRFIDTagParticleMap_io.cpp
// (RFIR_REGISTER_CLASS); this is the on-first-use path for entry points.
void rfir::maps::registerAllClasses() {
    rfir::obs::registerAllClasses();
    static const bool done =
        (mrpt::rtti::registerClass(CLASS_ID(rfir::maps::CRFIDTagParticleMap)), true);
    (void)done;
}
