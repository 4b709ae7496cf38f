// CGzInputStream (rfir/common/gz_input.h): a stream small enough is kept in
// memory by the sizing pass, a larger one is decompressed again as it is
// read. Both ways must give the same bytes, the same size and, on a cut or
// damaged stream, the same good bytes before the same error.
#include <rfir/common/gz_input.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;

namespace {
/** 300 kB of half-compressible bytes (several 64 kB chunks), gzipped. */
std::string writeGz(const fs::path& p, std::string* plain) {
    uint64_t x = 88172645463325252ull;
    plain->clear();
    for (int i = 0; i < 300000; i++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        plain->push_back(char(i % 3 ? (x & 0x0F) : (x >> 24)));
    }
    gzFile f = gzopen(p.c_str(), "wb");
    gzwrite(f, plain->data(), unsigned(plain->size()));
    gzclose(f);
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

struct TOutcome {
    std::string bytes;
    std::string error;  //!< empty: read to the end without one
    uint64_t total = 0;
};

/** Reads the whole stream in pieces of 1, 7, 8 and 5000 bytes, in turn. */
TOutcome readAll(const fs::path& p, uint64_t keep) {
    TOutcome o;
    rfir::common::CGzInputStream in;
    in.open(p, keep);
    o.total = in.getTotalBytesCount();
    const size_t sizes[] = {1, 7, 8, 5000};
    try {
        for (size_t k = 0;; k++) {
            char buf[5000];
            const size_t n = sizes[k % 4], got = in.Read(buf, n);
            o.bytes.append(buf, got);
            if (got < n) break;
        }
    } catch (const std::runtime_error& e) {
        o.error = e.what();
    }
    return o;
}

void expectSameBothWays(const fs::path& p, const std::string& what) {
    const auto mem = readAll(p, rfir::common::CGzInputStream::kKeepInMemory);
    const auto streamed = readAll(p, 0);
    EXPECT_EQ(mem.total, streamed.total) << what;
    EXPECT_EQ(mem.bytes.size(), streamed.bytes.size()) << what;
    EXPECT_TRUE(mem.bytes == streamed.bytes) << what;
    EXPECT_EQ(mem.error, streamed.error) << what;
}
}  // namespace

TEST(GzInput, MemoryAndStreamingReadTheSameBytes) {
    const rfir_test::TmpDir tmp;
    const fs::path d = tmp.p;
    std::string plain;
    const std::string gz = writeGz(d / "whole.gz", &plain);
    const auto mem = readAll(d / "whole.gz", rfir::common::CGzInputStream::kKeepInMemory);
    EXPECT_EQ(mem.total, plain.size());
    EXPECT_TRUE(mem.bytes == plain);
    EXPECT_EQ(mem.error, "");
    expectSameBothWays(d / "whole.gz", "whole");

    // The trailer cut off, the stream cut in half, a byte flipped inside the
    // compressed data: an error after the good bytes, the same both ways.
    const std::pair<const char*, std::string> bad[] = {
        {"no_trailer", gz.substr(0, gz.size() - 8)},
        {"half", gz.substr(0, gz.size() / 2)},
        {"flipped", [&] {
             std::string b = gz;
             b[b.size() / 3] ^= 0x5A;
             return b;
         }()}};
    for (const auto& [name, bytes] : bad) {
        const fs::path p = d / (std::string(name) + ".gz");
        std::ofstream(p, std::ios::binary) << bytes;
        const auto o = readAll(p, rfir::common::CGzInputStream::kKeepInMemory);
        EXPECT_NE(o.error.find("damaged or truncated"), std::string::npos) << name;
        EXPECT_LT(o.bytes.size(), plain.size()) << name;
        // A flip can decode to wrong bytes that only the CRC at the end
        // catches; a cut stream's bytes are all good.
        if (std::string(name) != "flipped") {
            EXPECT_TRUE(o.bytes == plain.substr(0, o.bytes.size())) << name;
        }
        expectSameBothWays(p, name);
    }
}
