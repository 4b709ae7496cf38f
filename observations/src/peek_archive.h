/* rfir: private helpers of the MRPT guards (mrpt_guards.cpp,
 * checked_classes.cpp): an archive that reads ahead, and the refusal. */
#pragma once

#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace rfir::obs::detail {
using mrpt::serialization::CArchive;

/** Reads ahead from an archive, then serves the bytes read ahead again before
 * the rest: MRPT's parser sees the object exactly as stored. */
class CPeekArchive : public CArchive {
  public:
    explicit CPeekArchive(CArchive& in) : in_(in) {}
    template <class T>
    T peek() {
        T v;
        peekBytes(&v, sizeof(v));
        return v;
    }
    void peekBytes(void* b, size_t n) {
        const size_t at = buf_.size();
        buf_.resize(at + n);
        in_.ReadBuffer(buf_.data() + at, n);
        std::memcpy(b, buf_.data() + at, n);
    }

  protected:
    size_t write(const void*, size_t) override {
        throw std::logic_error("CPeekArchive: read only");
    }
    size_t read(void* b, size_t n) override {
        size_t k = 0;
        if (pos_ < buf_.size()) {
            k = std::min(n, buf_.size() - pos_);
            std::memcpy(b, buf_.data() + pos_, k);
            pos_ += k;
        }
        if (k < n) k += in_.ReadBuffer(static_cast<uint8_t*>(b) + k, n - k);
        return k;
    }

  private:
    CArchive& in_;
    std::vector<uint8_t> buf_;
    size_t pos_ = 0;
};

[[noreturn]] inline void refuse(const std::string& cls, const std::string& why) {
    throw std::runtime_error(cls + ": " + why +
                             " (corrupt data; refused before MRPT parses it)");
}

/** The class name of the serialized object that follows (MRPT's header: a
 * length byte, 0x80 set in the current format, then the name); `where()`
 * names the object in the error, and is called only for one. */
template <class Where>
std::string peekClassNameOf(CPeekArchive& a, Where&& where) {
    const auto len = a.peek<uint8_t>();
    if (!(len & 0x80)) refuse(where(), "object in MRPT's pre-2008 format");
    std::string name(len & 0x7F, '\0');
    if (!name.empty()) a.peekBytes(name.data(), name.size());
    return name;
}
inline std::string peekClassName(CPeekArchive& a, const std::string& cls) {
    return peekClassNameOf(a, [&]() -> const std::string& { return cls; });
}

/** The MRPT classes mrpt_guards.cpp replaces by checked readers. */
const std::vector<std::string>& guardedClassNames();
}  // namespace rfir::obs::detail
