/* rfir tests: the observation classes are registered with MRPT's RTTI by the
 * library itself, whatever the order of its sources or of static
 * initialisation. Built twice (tests/registration.cmake): against the library,
 * and from the library's sources in reverse order. Neither calls
 * registerAllClasses(): a reader that forgot to would otherwise see "not
 * registered" and stop as if at the end of the file. */
#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <memory>

namespace {
const char* const kClasses[] = {"rfir::obs::CObservationRFIDReaders",
                                "rfir::obs::CObservationIRSignals",
                                "rfir::obs::CObservationLogHeader"};

// Writes obj and reads it back through MRPT's class factory.
mrpt::serialization::CSerializable::Ptr roundTrip(
    const mrpt::serialization::CSerializable& obj) {
    mrpt::io::CMemoryStream buf;
    auto out = mrpt::serialization::archiveFrom(buf);
    out << obj;
    buf.Seek(0);
    auto in = mrpt::serialization::archiveFrom(buf);
    return in.ReadObject();
}
}  // namespace

TEST(Registration, EveryClassIsRegisteredWithoutAnExplicitCall) {
    for (const char* name : kClasses) {
        const auto* id = mrpt::rtti::findRegisteredClass(name);
        ASSERT_NE(id, nullptr) << name << " is not registered";
        EXPECT_STREQ(id->className, name);
        // The factory makes an object of the class itself.
        const auto obj = id->createObject();
        ASSERT_TRUE(obj) << name;
        EXPECT_STREQ(obj->GetRuntimeClass()->className, name);
    }
}

TEST(Registration, ObjectsReadBackThroughTheFactory) {
    rfir::obs::CObservationRFIDReaders rfid;
    rfid.sensorLabel = "RFID";
    rfir::obs::CObservationRFIDReaders::TReading r;
    r.reader.id = "R1";
    r.tags = {"E004015012345678"};
    rfid.readings.push_back(r);
    const auto back = roundTrip(rfid);
    const auto* got = dynamic_cast<const rfir::obs::CObservationRFIDReaders*>(back.get());
    ASSERT_NE(got, nullptr);
    ASSERT_EQ(got->readings.size(), 1u);
    EXPECT_EQ(got->readings[0].tags, r.tags);

    rfir::obs::CObservationIRSignals ir;
    ir.sensorLabel = "IR";
    EXPECT_TRUE(
        dynamic_cast<const rfir::obs::CObservationIRSignals*>(roundTrip(ir).get()));
    rfir::obs::CObservationLogHeader hdr;
    hdr.sensorLabel = "HEADER";
    EXPECT_TRUE(
        dynamic_cast<const rfir::obs::CObservationLogHeader*>(roundTrip(hdr).get()));
}
