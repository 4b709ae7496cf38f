// Which MRPT classes rfir's rawlog reader reads (rfir/obs/mrpt_guards.h,
// CCheckedClassesScope): a class whose reader allocates from unchecked counts
// is refused by name unless RFIR_TRUST_MRPT_CLASSES lists it; MRPT's own
// programs (no scope) read it as before.
#include <rfir/common/rawlog_io.h>
#include <rfir/obs/mrpt_guards.h>
#include <rfir/obs/registerAllClasses.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationBeaconRanges.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace {
using rfir_test::TmpDir;

/** Sets (or unsets) the trust variable for one test, restoring it after. */
struct TTrust {
    explicit TTrust(const char* v) {
        if (const char* o = std::getenv(rfir::obs::kTrustClassesEnv)) old_ = o;
        if (v)
            setenv(rfir::obs::kTrustClassesEnv, v, 1);
        else
            unsetenv(rfir::obs::kTrustClassesEnv);
    }
    ~TTrust() {
        if (old_)
            setenv(rfir::obs::kTrustClassesEnv, old_->c_str(), 1);
        else
            unsetenv(rfir::obs::kTrustClassesEnv);
    }
    std::optional<std::string> old_;
};

/** A rawlog of two steps; the second holds a beacon-ranges observation. */
std::string rawlogWithBeacons(const TmpDir& d) {
    const std::string p = d / "beacons.rawlog";
    rfir::common::CRawlogWriter w(p, rfir::obs::CObservationLogHeader());
    w.writeStep(1.0, mrpt::poses::CPose2D(0, 0, 0), {});
    auto b = mrpt::obs::CObservationBeaconRanges::Create();
    b->sensorLabel = "UWB";
    b->sensedData.resize(3);
    w.writeStep(2.0, mrpt::poses::CPose2D(0.1, 0, 0), {b});
    w.close();
    return p;
}

/** Reads the whole rawlog; the number of beacon-ranges observations seen. */
size_t beaconsIn(const std::string& p) {
    rfir::common::CRawlogReader r(p);
    rfir::common::TRawlogStep st;
    size_t n = 0;
    while (r.next(st))
        for (const auto& o : *st.sf)
            if (auto b =
                    std::dynamic_pointer_cast<mrpt::obs::CObservationBeaconRanges>(o))
                n += b->sensedData.size();
    return n;
}

std::string errorOf(const std::string& p) {
    try {
        beaconsIn(p);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(CheckedClasses, UncheckedMrptClassIsRefusedByNameWithTheWayOut) {
    TmpDir d;
    const auto p = rawlogWithBeacons(d);
    TTrust none(nullptr);
    const auto e = errorOf(p);
    EXPECT_NE(e.find(p + ": entry "), std::string::npos) << e;
    EXPECT_NE(e.find("'mrpt::obs::CObservationBeaconRanges'"), std::string::npos) << e;
    EXPECT_NE(e.find("RFIR_TRUST_MRPT_CLASSES=CObservationBeaconRanges"),
              std::string::npos)
        << e;
}

TEST(CheckedClasses, TrustedByShortOrFullNameOrStarIsRead) {
    TmpDir d;
    const auto p = rawlogWithBeacons(d);
    for (const char* v :
         {"CObservationBeaconRanges", "mrpt::obs::CObservationBeaconRanges",
          "CObservationComment , CObservationBeaconRanges", "*"}) {
        TTrust t(v);
        EXPECT_EQ(beaconsIn(p), 3u) << v;
    }
    // Read, but not used: said once, not dropped silently.
    {
        TTrust t("*");
        testing::internal::CaptureStderr();
        beaconsIn(p);
        const auto err = testing::internal::GetCapturedStderr();
        const std::string w =
            "observations of class mrpt::obs::CObservationBeaconRanges (first one "
            "labelled 'UWB') are kept in each frame but not used";
        EXPECT_NE(err.find(w), std::string::npos) << err;
        EXPECT_EQ(err.find(w), err.rfind(w)) << err;
    }
    // A list without it, or a mere prefix of the name, does not trust it.
    for (const char* v : {"CObservationComment", "CObservationBeacon", ""}) {
        TTrust t(v);
        EXPECT_NE(errorOf(p).find("refused"), std::string::npos) << v;
    }
}

TEST(CheckedClasses, WithoutAScopeMrptReadsAsBefore) {
    // MRPT's own programs with the plugin loaded (RawLogViewer) keep reading
    // every registered class.
    rfir::obs::registerAllClasses();
    TTrust none(nullptr);
    mrpt::obs::CSensoryFrame sf;
    auto c = mrpt::obs::CObservationComment::Create();
    c->text = "hello";
    sf.insert(c);
    mrpt::io::CMemoryStream m;
    auto w = mrpt::serialization::archiveFrom(m);
    w << sf;
    m.Seek(0);
    auto r = mrpt::serialization::archiveFrom(m);
    auto back = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(r.ReadObject());
    ASSERT_TRUE(back);
    ASSERT_EQ(back->size(), 1u);
    EXPECT_EQ(back->getObservationByClass<mrpt::obs::CObservationComment>()->text,
              "hello");
    // The same bytes inside a scope are refused.
    m.Seek(0);
    rfir::obs::CCheckedClassesScope scope;
    try {
        r.ReadObject();
        FAIL() << "a comment was read inside the scope";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("CObservationComment"), std::string::npos);
    }
}

TEST(CheckedClasses, TheClassMrptResolvesIsTheOneChecked) {
    // MRPT finds a class by the part of the name after the last "::" as well:
    // a file naming "rfir::x::CObservationComment" gets MRPT's comment
    // (fuzz_rawlog found "rfir::obs::Cmrpt::math::CPolygon", a 57 GB read).
    rfir::obs::registerAllClasses();
    TTrust none(nullptr);
    mrpt::obs::CSensoryFrame sf;
    sf.insert(mrpt::obs::CObservationComment::Create());
    mrpt::io::CMemoryStream m;
    auto w = mrpt::serialization::archiveFrom(m);
    w << sf;
    const auto* p = static_cast<const char*>(m.getRawBufferData());
    std::string b(p, p + m.getTotalBytesCount());
    const std::string from = "mrpt::obs::CObservationComment",
                      to = "rfir::x::CObservationComment";
    const auto at = b.find(from);
    ASSERT_NE(at, std::string::npos);
    b.replace(at, from.size(), to);
    b[at - 1] = char(0x80 | to.size());
    mrpt::io::CMemoryStream in;
    in.Write(b.data(), b.size());
    in.Seek(0);
    auto r = mrpt::serialization::archiveFrom(in);
    rfir::obs::CCheckedClassesScope scope;
    try {
        r.ReadObject();
        FAIL() << "an aliased MRPT class was read inside the scope";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("'mrpt::obs::CObservationComment'"),
                  std::string::npos)
            << e.what();
    }
}

TEST(CheckedClasses, FileBytesInAnErrorAreEscaped) {
    // A corrupt class name is quoted as \xNN, so the error stays text.
    rfir::obs::registerAllClasses();
    mrpt::io::CMemoryStream m;
    auto w = mrpt::serialization::archiveFrom(m);
    mrpt::obs::CSensoryFrame sf;
    sf.insert(mrpt::obs::CObservationComment::Create());
    w << mrpt::obs::CActionCollection() << sf;
    const auto* p = static_cast<const char*>(m.getRawBufferData());
    std::string b(p, p + m.getTotalBytesCount());
    const auto at = b.find("mrpt::obs::CObservationComment");
    ASSERT_NE(at, std::string::npos);
    b[at + std::string("mrpt::obs::CObservation").size()] = char(0xD9);
    TmpDir d;
    const std::string path = d / "bad.rawlog";
    std::ofstream(path, std::ios::binary) << b;
    std::string e;
    try {
        beaconsIn(path);
    } catch (const std::exception& x) {
        e = x.what();
    }
    EXPECT_NE(e.find("'mrpt::obs::CObservation\\xD9omment'"), std::string::npos) << e;
    for (const unsigned char c : e) EXPECT_TRUE(c >= 0x20 && c < 0x7F) << int(c);
}
