/* A program built against the installed rfir package: it creates the tag map
 * from an INI section through MRPT's map registry, as MRPT's own programs do,
 * inserts RFID reads and checks the estimate lands under the reader.
 * Usage: app INI [SECTION]   (exit 0 when the estimate is where expected) */
#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

namespace {
/** One reader 0.1 m ahead of the robot, 6 cm square, that read tag E0. */
rfir::obs::CObservationRFIDReaders readOfE0() {
    rfir::obs::CObservationRFIDReaders obs;
    obs.sensorLabel = "RFID";
    rfir::obs::CObservationRFIDReaders::TReading rd;
    rd.reader.id = "R0";
    rd.reader.x = 0.1;
    rd.reader.halfX = rd.reader.halfY = 0.03;
    rd.tags = {"E0"};
    obs.readings.push_back(rd);
    return obs;
}

bool near(double v, double want, double tol, const char* what) {
    if (std::abs(v - want) <= tol) return true;
    std::fprintf(stderr, "app: %s is %.4f, expected %.4f +- %.4f\n", what, v, want, tol);
    return false;
}

int run(const std::string& file, const std::string& section) {
    mrpt::config::CConfigFile ini(file);
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(ini, section);
    mrpt::maps::CMultiMetricMap mm;
    mm.setListOfMaps(inits);
    const auto m = mm.mapByClass<rfir::maps::CRFIDTagParticleMap>();
    if (!m) {
        std::fprintf(stderr, "app: [%s] of %s made no rfidTagMap\n", section.c_str(),
                     file.c_str());
        return 1;
    }
    // First read: the tag is somewhere under the reader, centred at (1.1, 2).
    const auto obs = readOfE0();
    mm.insertObservation(obs, mrpt::poses::CPose3D(1.0, 2.0, 0));
    const auto* t = m->getTag("E0");
    if (!t) {
        std::fprintf(stderr, "app: tag E0 not in the map after its read\n");
        return 1;
    }
    const double x1 = t->estimate.mean.x;
    bool ok = near(x1, 1.1, 0.01, "x after one read");
    ok = near(t->estimate.mean.y, 2.0, 0.01, "y after one read") && ok;
    // A second read 3 cm further on overlaps the first over x in [1.10, 1.13]:
    // the estimate moves forward, into the overlap.
    mm.insertObservation(obs, mrpt::poses::CPose3D(1.03, 2.0, 0));
    const double x2 = m->getTag("E0")->estimate.mean.x;
    ok = near(x2, 1.115, 0.015, "x after two reads") && ok;
    if (!(x2 > x1 + 0.003)) {
        std::fprintf(stderr, "app: the second read did not move x (%.4f -> %.4f)\n", x1,
                     x2);
        ok = false;
    }
    std::printf("app: E0 at (%.4f, %.4f) after one read, x %.4f after two\n", x1,
                t->estimate.mean.y, x2);
    return ok ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: app INI [SECTION]\n");
        return 2;
    }
    try {
        return run(argv[1], argc == 3 ? argv[2] : "MappingApplication");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "app: %s\n", e.what());
        return 1;
    }
}
