/* rfir: which classes a rawlog read by rfir may hold (mrpt_guards.h). */
#include <rfir/obs/mrpt_guards.h>

#include "peek_archive.h"

#include <mrpt/rtti/CObject.h>

#include <algorithm>
#include <cstdlib>

namespace rfir::obs {
namespace {
thread_local bool tlChecked = false;

/** Whether RFIR_TRUST_MRPT_CLASSES lists `name` (full, or after its last "::"),
 * or is "*". */
bool trusted(const std::string& name) {
    const char* env = std::getenv(kTrustClassesEnv);
    if (!env) return false;
    const std::string list = env;
    const auto shortName = name.substr(name.rfind(':') + 1);  // npos + 1 == 0
    for (size_t b = 0; b <= list.size();) {
        auto e = list.find(',', b);
        if (e == std::string::npos) e = list.size();
        auto item = list.substr(b, e - b);
        item.erase(0, item.find_first_not_of(" \t"));
        item.erase(item.find_last_not_of(" \t") + 1);
        if (item == "*" || item == name || item == shortName) return true;
        b = e + 1;
    }
    return false;
}

/** Whether the reader of registered class `cls` is rfir's or checked by a
 * guard. The name MRPT resolves is the one that counts, not the file's: MRPT
 * also finds a class by the part after the last "::", so a file's
 * "rfir::obs::Cmrpt::math::CPolygon" is read as MRPT's CPolygon (fuzz find). */
bool checked(const std::string& cls) {
    if (cls.rfind("rfir::", 0) == 0) return true;
    const auto& g = detail::guardedClassNames();
    return std::find(g.begin(), g.end(), cls) != g.end();
}
}  // namespace

CCheckedClassesScope::CCheckedClassesScope() : prev_(tlChecked) {
    tlChecked = true;
}

CCheckedClassesScope::~CCheckedClassesScope() {
    tlChecked = prev_;
}

mrpt::serialization::CSerializable::Ptr readCheckedObject(
    mrpt::serialization::CArchive& in, const char* container, int64_t index) {
    if (!tlChecked) return in.ReadObject();
    // The object's name is built only for an error (this runs per object).
    const auto where = [&] {
        return index < 0 ? std::string(container)
                         : std::string(container) + ": object " + std::to_string(index);
    };
    detail::CPeekArchive a(in);
    const auto stored = detail::peekClassNameOf(a, where);
    // "nullptr" is read as an empty pointer, which the containers refuse.
    if (stored == "nullptr") return a.ReadObject();
    const auto* id = mrpt::rtti::findRegisteredClass(stored);
    if (!id)
        throw std::runtime_error(where() + " names the class '" + stored +
                                 "', which is not registered (corrupt data, or a "
                                 "class of a library this program does not load)");
    const std::string name = id->className;
    if (!checked(name) && !trusted(name))
        throw std::runtime_error(
            where() + " is a '" + name +
            "', an MRPT class whose reader rfir does not check (a corrupt count in "
            "it can take all memory): refused; to read it unchecked, set " +
            kTrustClassesEnv + "=" + name.substr(name.rfind(':') + 1) +
            " (docs/hardening.md)");
    return a.ReadObject();
}
}  // namespace rfir::obs
