/* rfir: bounded reads of counts, strings and flags from a serialized stream.
 * Every count or length read from a file goes through these before anything
 * is allocated, so a corrupt file gives an error instead of a multi-GB
 * allocation (bounds: docs/rawlog-layout.md, "Bounds on read"). */
#pragma once

#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>

namespace rfir::obs {
/** Bounds on what a rawlog may hold, documented in docs/rawlog-layout.md. */
struct TReadBounds {
    static constexpr size_t kMaxLabelBytes = 4096;  //!< ids, labels, names
    static constexpr size_t kMaxSensors = 4096;     //!< readers, receivers
    static constexpr size_t kMaxTagsPerReading = 1 << 20;
    static constexpr size_t kMaxCodesPerReading = 255;
    static constexpr size_t kMaxRawSamples = 1 << 24;  //!< IR raw window
    static constexpr size_t kMaxNames = 1 << 20;       //!< landmark names
    static constexpr size_t kMaxMapEntries = 1 << 24;  //!< tags, emitters, points
};

/** Tells how many bytes are left in the stream being read on this thread.
 * A reader that knows (CRawlogReader) installs one with CBytesLeftScope. */
class IBytesLeft {
  public:
    virtual ~IBytesLeft() = default;
    virtual std::optional<uint64_t> bytesLeft() const = 0;
};

/** Installs `src` as this thread's IBytesLeft for the scope's life. */
class CBytesLeftScope {
  public:
    explicit CBytesLeftScope(const IBytesLeft* src);
    ~CBytesLeftScope();
    CBytesLeftScope(const CBytesLeftScope&) = delete;
    CBytesLeftScope& operator=(const CBytesLeftScope&) = delete;

  private:
    const IBytesLeft* prev_;
};

/** Bytes left in the stream being read on this thread; nullopt: unknown. */
std::optional<uint64_t> bytesLeftInStream();

/** Reads a uint32 count; throws std::runtime_error naming `what` when it is
 * above `maxCount` or when `count * minBytesEach` exceeds the bytes left. */
size_t readBoundedCount(mrpt::serialization::CArchive& in, const char* what,
                        size_t maxCount, size_t minBytesEach);
/** The same for a uint64 count (the maps write 64-bit counts). */
size_t readBoundedCount64(mrpt::serialization::CArchive& in, const char* what,
                          size_t maxCount, size_t minBytesEach);
/** Reads a string in MRPT's layout (uint32 length, bytes), bounded. */
std::string readBoundedString(mrpt::serialization::CArchive& in, const char* what,
                              size_t maxLen = TReadBounds::kMaxLabelBytes);
/** Throws std::runtime_error naming `what` and `fields` unless every value
 * is finite: a NaN or infinity read from a file is corrupt data, which the
 * filters would otherwise carry along silently. */
void requireFinite(const char* what, const char* fields,
                   std::initializer_list<double> values);

/** Reads a bool written by MRPT (one byte); refuses values other than 0/1. */
bool readStrictBool(mrpt::serialization::CArchive& in, const char* what);

}  // namespace rfir::obs
