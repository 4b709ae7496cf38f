#include <rfir/common/json_text.h>

#include <nlohmann/json.hpp>

namespace rfir::common {
std::string jsonString(const std::string& s) {
    return nlohmann::json(s).dump(-1, ' ', false,
                                  nlohmann::json::error_handler_t::replace);
}
}  // namespace rfir::common
