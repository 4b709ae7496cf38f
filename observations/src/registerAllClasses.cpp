/* rfir: registers the observation classes with MRPT's RTTI, so that any
 * program linking (or plugin-loading) this library can read project rawlogs. */
#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/obs/registerAllClasses.h>

#include <mrpt/core/initializer.h>
#include <mrpt/rtti/CObject.h>

MRPT_INITIALIZER(registerAllClasses_rfir_obs) { rfir::obs::registerAllClasses(); }

void rfir::obs::registerAllClasses()
{
    using namespace rfir::obs;
    mrpt::rtti::registerClass(CLASS_ID(CObservationRFIDReaders));
    mrpt::rtti::registerClass(CLASS_ID(CObservationIRSignals));
    mrpt::rtti::registerClass(CLASS_ID(CObservationLogHeader));
}
