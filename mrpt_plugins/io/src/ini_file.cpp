/* rfir: reading an INI file into memory. */
#include <rfir/common/ini_file.h>
#include <rfir/common/text_input.h>

#include <filesystem>
#include <system_error>

namespace rfir::common {
rfir::ini::CIniFile readIniFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw rfir::ini::CIniError(path + ": no such INI file");
    try {
        return rfir::ini::CIniFile(path, readSmallTextFile(path, "INI file"));
    } catch (const std::runtime_error& e) {  // its messages start with the path
        throw rfir::ini::CIniError(e.what());
    }
}
}  // namespace rfir::common
