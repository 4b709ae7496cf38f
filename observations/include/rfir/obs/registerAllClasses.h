#pragma once
#include <mrpt/rtti/CObject.h>

namespace rfir::obs {
/** Registers the observation classes. Each class also registers itself from
 * its own source file (RFIR_REGISTER_CLASS); the rawlog reader and writer
 * and the plugin call this as well, so registration never depends on link
 * or static-initialisation order. Idempotent and cheap after the first call;
 * calling it also forces the linker to keep the library. */
void registerAllClasses();
}  // namespace rfir::obs

/** Registers class T with MRPT's RTTI from T's own source file. Place it after
 * IMPLEMENTS_SERIALIZABLE: objects of one translation unit are initialised in
 * the order they are defined, so T's runtimeClassId is complete by then
 * (MRPT_INITIALIZER, a constructor function, has no such guarantee). */
#define RFIR_REGISTER_CLASS(tag, T)                     \
    namespace {                                         \
    [[maybe_unused]] const bool rfir_registered_##tag = \
        (mrpt::rtti::registerClass(CLASS_ID(T)), true); \
    }
