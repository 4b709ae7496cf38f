/* rfir: plugin library for MRPT's own programs. Loading it (RawLogViewer -l,
 * rawlog-edit -p, or LD_PRELOAD) loads every rfir library it links, whose
 * initializers register their classes; this one makes sure the observation
 * classes, which every rawlog holds, are registered in any case. See
 * docs/rawlogviewer.md. */
#include <rfir/obs/registerAllClasses.h>

#include <mrpt/core/initializer.h>

MRPT_INITIALIZER(rfir_mrpt_plugin_init) {
    rfir::obs::registerAllClasses();
}

/** Which rfir libraries this build of the plugin carries (for diagnostics:
 * `nm -D` or dlsym). */
extern "C" __attribute__((visibility("default"))) const char*
rfir_mrpt_plugin_libraries() {
    return RFIR_PLUGIN_LIBS;
}
