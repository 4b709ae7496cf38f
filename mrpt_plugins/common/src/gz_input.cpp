/* rfir: gzip input stream with errors and a known size. */
#include <rfir/common/gz_input.h>

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace rfir::common {
namespace {
constexpr size_t kChunk = 1 << 16;

/** The gzip trailer's ISIZE (the uncompressed size mod 2^32), at most what
 * deflate can expand the file to (1032:1), 0 if it cannot be read. Only a hint
 * for reserving: a damaged or multi-member file may lie. */
uint64_t trailerSize(const std::string& path) {
    std::ifstream f(path, std::ios::binary | std::ios::ate);
    const auto size = f ? int64_t(f.tellg()) : 0;
    if (size < 18) return 0;
    unsigned char b[4];
    f.seekg(-4, std::ios::end);
    if (!f.read(reinterpret_cast<char*>(b), 4)) return 0;
    const uint64_t isize = uint64_t(b[0]) | uint64_t(b[1]) << 8 | uint64_t(b[2]) << 16 |
                           uint64_t(b[3]) << 24;
    return std::min(isize, uint64_t(size) * 1032);
}

std::string gzMessage(gzFile f) {
    int code = 0;
    const char* m = gzerror(f, &code);
    return m && *m ? m : "read error";
}
}  // namespace

CGzInputStream::~CGzInputStream() {
    close();
}

void CGzInputStream::close() {
    if (gz_) gzclose(static_cast<gzFile>(gz_));
    gz_ = nullptr;
}

void CGzInputStream::open(const std::string& path, uint64_t keepInMemory) {
    close();
    path_ = path;
    total_ = pos_ = 0;
    buf_.clear();
    head_ = 0;
    ended_ = cutError_ = false;
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw std::runtime_error(path + ": is a directory, not a rawlog file");
    if (!std::filesystem::exists(path, ec))
        throw std::runtime_error(path + ": no such file");
    gz_ = gzopen(path.c_str(), "rb");
    if (!gz_) throw std::runtime_error(path + ": cannot open for reading");
    // The uncompressed size: counts read from the file are checked against it
    // before anything is allocated. A gzip stream takes one pass (its trailer
    // could lie); a damaged tail stops the count, and the read reports it at
    // the entry where it is met.
    auto f = static_cast<gzFile>(gz_);
    char probe = 0;
    const int first = gzread(f, &probe, 1);
    if (first == 1 && gzdirect(f)) {
        // Not compressed: the size is the file's, no second pass needed.
        total_ = std::filesystem::file_size(path, ec);
        if (ec) {
            close();
            throw std::runtime_error(path + ": cannot read its size");
        }
    } else if (first == 1 && sizeAndKeep(probe, keepInMemory)) {
        return;  // the whole stream is in buf_: no second pass
    }
    gzclearerr(f);
    if (gzrewind(f) != 0) {
        close();
        throw std::runtime_error(path + ": cannot rewind after sizing");
    }
}

bool CGzInputStream::sizeAndKeep(char first, uint64_t keepInMemory) {
    // The sizing pass keeps what it decompresses while that stays small:
    // the reads are then served from memory, with one decompression instead
    // of two. A damaged or cut stream keeps its good bytes and the error,
    // raised when a read goes past them (as Read does when streaming).
    auto f = static_cast<gzFile>(gz_);
    // Reserved once from the trailer's size (capped): no regrowth copies.
    buf_.reserve(size_t(std::min(trailerSize(path_), keepInMemory)) + kChunk);
    buf_.assign(1, first);
    total_ = 1;
    bool keep = true;
    for (;;) {
        // Decompressed straight into buf_ while it is kept, else into a
        // scratch chunk at its start that only counts.
        const size_t at = keep ? buf_.size() : 0;
        buf_.resize(at + kChunk);
        const int r = gzread(f, buf_.data() + at, unsigned(kChunk));
        buf_.resize(at + size_t(std::max(r, 0)));
        if (r <= 0) break;
        total_ += uint64_t(r);
        keep = keep && total_ <= keepInMemory;
        if (!keep && buf_.capacity() > 2 * kChunk) std::vector<char>().swap(buf_);
    }
    if (!keep) {
        std::vector<char>().swap(buf_);
        return false;
    }
    int code = Z_OK;
    gzerror(f, &code);
    ended_ = true;
    cutError_ = code != Z_OK;
    if (cutError_) cutMessage_ = gzMessage(f);
    head_ = 0;
    return true;
}

size_t CGzInputStream::Read(void* buf, size_t n) {
    if (!gz_) throw std::logic_error("CGzInputStream: read before open");
    // MRPT's archives read a field at a time: served from a buffer of
    // decompressed bytes, one gzread per kChunk instead of one per field.
    size_t got = 0;
    auto* out = static_cast<char*>(buf);
    while (got < n) {
        if (head_ == buf_.size()) {
            if (ended_ || !refill()) break;
        }
        const size_t k = std::min(n - got, buf_.size() - head_);
        std::memcpy(out + got, buf_.data() + head_, k);
        head_ += k;
        got += k;
    }
    pos_ += got;
    if (got < n && cutError_)
        throw std::runtime_error(path_ + ": damaged or truncated gzip stream (" +
                                 cutMessage_ + ")");
    return got;
}

bool CGzInputStream::refill() {
    auto f = static_cast<gzFile>(gz_);
    buf_.resize(kChunk);
    head_ = 0;
    const int r = gzread(f, buf_.data(), unsigned(kChunk));
    if (r < 0) {
        buf_.clear();
        throw std::runtime_error(path_ + ": damaged or truncated gzip stream (" +
                                 gzMessage(f) + ")");
    }
    buf_.resize(size_t(r));
    if (size_t(r) < kChunk) {
        // zlib ends a stream cut before its trailer like a complete one (a
        // short read); only the error state (Z_BUF_ERROR) tells them apart.
        // The bytes before the cut are served first; the error is raised
        // when a read needs more than they hold.
        int code = Z_OK;
        gzerror(f, &code);
        ended_ = true;
        cutError_ = code != Z_OK;
        if (cutError_) cutMessage_ = gzMessage(f);
    }
    return r > 0;
}

uint64_t CGzInputStream::Seek(int64_t, mrpt::io::CStream::TSeekOrigin) {
    throw std::logic_error("CGzInputStream: no seek");
}

}  // namespace rfir::common
