/* rfir: bounded reads of counts, strings and flags. */
#include <rfir/obs/bounded_read.h>

#include <cmath>
#include <stdexcept>

namespace rfir::obs {
namespace {
thread_local const IBytesLeft* tlBytesLeft = nullptr;

size_t checkCount(uint64_t n, const char* what, size_t maxCount, size_t minBytesEach) {
    if (n > maxCount)
        throw std::runtime_error(std::string(what) + ": count " + std::to_string(n) +
                                 " read from the stream is above the bound " +
                                 std::to_string(maxCount) + " (corrupt data)");
    const auto left = bytesLeftInStream();
    if (left && minBytesEach > 0 && n > *left / minBytesEach)
        throw std::runtime_error(std::string(what) + ": count " + std::to_string(n) +
                                 " needs at least " + std::to_string(n * minBytesEach) +
                                 " bytes, only " + std::to_string(*left) +
                                 " left in the stream (corrupt or truncated data)");
    return static_cast<size_t>(n);
}
}  // namespace

CBytesLeftScope::CBytesLeftScope(const IBytesLeft* src) : prev_(tlBytesLeft) {
    tlBytesLeft = src;
}

CBytesLeftScope::~CBytesLeftScope() {
    tlBytesLeft = prev_;
}

std::optional<uint64_t> bytesLeftInStream() {
    return tlBytesLeft ? tlBytesLeft->bytesLeft() : std::nullopt;
}

size_t readBoundedCount(mrpt::serialization::CArchive& in, const char* what,
                        size_t maxCount, size_t minBytesEach) {
    return checkCount(in.ReadAs<uint32_t>(), what, maxCount, minBytesEach);
}

size_t readBoundedCount64(mrpt::serialization::CArchive& in, const char* what,
                          size_t maxCount, size_t minBytesEach) {
    return checkCount(in.ReadAs<uint64_t>(), what, maxCount, minBytesEach);
}

std::string readBoundedString(mrpt::serialization::CArchive& in, const char* what,
                              size_t maxLen) {
    const size_t n = checkCount(in.ReadAs<uint32_t>(), what, maxLen, 1);
    std::string s(n, '\0');
    // ReadBuffer only throws when nothing at all is read.
    if (n > 0 && in.ReadBuffer(s.data(), n) != n)
        throw std::runtime_error(std::string(what) +
                                 ": string cut short (truncated data)");
    return s;
}

void requireFinite(const char* what, const char* fields,
                   std::initializer_list<double> values) {
    for (const double v : values)
        if (!std::isfinite(v))
            throw std::runtime_error(std::string(what) + ": " + fields +
                                     " not finite (corrupt data)");
}

bool readStrictBool(mrpt::serialization::CArchive& in, const char* what) {
    const auto b = in.ReadAs<uint8_t>();
    if (b > 1)
        throw std::runtime_error(
            std::string(what) + ": flag byte " + std::to_string(b) +
            " read from the stream is neither 0 nor 1 (corrupt data)");
    return b == 1;
}

}  // namespace rfir::obs
