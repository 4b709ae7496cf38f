/* rfir: a gzip (or plain) input stream that reports what MRPT's
 * CFileGZInputStream hides: a damaged or truncated stream is an error, not an
 * end of file, and the bytes left are known for bounded reads. */
#pragma once

#include <rfir/obs/bounded_read.h>

#include <mrpt/io/CStream.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rfir::common {
class CGzInputStream : public mrpt::io::CStream, public rfir::obs::IBytesLeft {
  public:
    CGzInputStream() = default;
    ~CGzInputStream() override;
    CGzInputStream(const CGzInputStream&) = delete;
    CGzInputStream& operator=(const CGzInputStream&) = delete;

    /** Opens `path`; throws std::runtime_error("PATH: is a directory" / "no
     * such file" / "cannot open ..."). Decompresses the file once to learn its
     * size (a truncated stream is only reported when the read gets there). */
    void open(const std::string& path) { open(path, kKeepInMemory); }
    /** The same; a stream of at most keepInMemory uncompressed bytes is read
     * whole during the sizing pass and served from memory (one decompression
     * instead of two), a larger one is decompressed again as it is read. */
    void open(const std::string& path, uint64_t keepInMemory);
    static constexpr uint64_t kKeepInMemory = uint64_t(64) << 20;
    /** Reads up to n bytes; fewer only at the end of a complete stream.
     * Throws std::runtime_error when the data are damaged or cut short. */
    size_t Read(void* buf, size_t n) override;
    size_t Write(const void*, size_t) override { return 0; }
    uint64_t Seek(int64_t, mrpt::io::CStream::TSeekOrigin) override;
    uint64_t getTotalBytesCount() const override { return total_; }
    uint64_t getPosition() const override { return pos_; }
    std::string getStreamDescription() const override { return path_; }
    /** Uncompressed bytes after the read position. */
    std::optional<uint64_t> bytesLeft() const override { return total_ - pos_; }

  private:
    void close();
    /** The next chunk of decompressed bytes into buf_; false at the end. */
    bool refill();
    /** Sizes the stream after its first byte; true if it was small enough
     * to keep whole in buf_ (then read from there, without a rewind). */
    bool sizeAndKeep(char first, uint64_t keepInMemory);
    std::string path_;
    std::vector<char> buf_;  //!< decompressed bytes, served from head_
    size_t head_ = 0;
    bool ended_ = false;     //!< the stream gave its last bytes
    bool cutError_ = false;  //!< ...and was cut or damaged there
    std::string cutMessage_;
    void* gz_ = nullptr;  //!< gzFile; void* keeps zlib.h out of the header
    uint64_t total_ = 0, pos_ = 0;
};

}  // namespace rfir::common
