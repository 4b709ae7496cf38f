/* rfir: registers the observation classes with MRPT's RTTI, so that any
 * program linking (or plugin-loading) this library can read project rawlogs. */
#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/obs/mrpt_guards.h>
#include <rfir/obs/registerAllClasses.h>

void rfir::obs::registerAllClasses() {
    // A function-local static: done once, on first use, whatever the order in
    // which the libraries' static objects were initialised.
    static const bool done = [] {
        using namespace rfir::obs;
        mrpt::rtti::registerClass(CLASS_ID(CObservationRFIDReaders));
        mrpt::rtti::registerClass(CLASS_ID(CObservationIRSignals));
        mrpt::rtti::registerClass(CLASS_ID(CObservationLogHeader));
        registerMrptGuards();
        return true;
    }();
    (void)done;
}
