#pragma once
namespace rfir::obs
{
/** Registers the observation classes (also done automatically at load time;
 * calling it forces the linker to keep the library). Idempotent. */
void registerAllClasses();
}  // namespace rfir::obs
