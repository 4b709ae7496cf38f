/* rfir: registers the map classes with MRPT's RTTI (the map-type registry is
 * filled by MAP_DEFINITION_REGISTER at load time). */
#include <rfir/maps/CRFIDTagParticleMap.h>

#include <mrpt/core/initializer.h>
#include <mrpt/rtti/CObject.h>
#include <rfir/obs/registerAllClasses.h>

MRPT_INITIALIZER(registerAllClasses_rfir_maps) {
    rfir::maps::registerAllClasses();
}

void rfir::maps::registerAllClasses() {
    rfir::obs::registerAllClasses();
    mrpt::rtti::registerClass(CLASS_ID(rfir::maps::CRFIDTagParticleMap));
}
