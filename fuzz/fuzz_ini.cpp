/* rfir fuzzing: the INI loading of every section, through the functions the
 * programs call. The first byte picks the loader, the rest is the INI text:
 *   '0' rfir-slam      loadSlamConfig ([slam] [motion] [kidnap] [fastslam]
 *                      [tagmap] [tagmap_likelihood])
 *   '1' rfir-localize  loadConfig ([localization] [motion] [MetricMap] and the
 *                      irEmitterMap sections, through MRPT's map factory); the
 *                      INI sits beside a valid emitters.txt
 *   '2' rfir-sim       loadSimConfig (every [simulation] ... section)
 *   '3' the maps       TSetOfMetricMapInitializers::loadFromConfigFile on
 *                      [MetricMap], then CMultiMetricMap builds them
 *                      (rfidTagMap, irEmitterMap; "@EMITTERS@" stands for
 *                      the valid emitters.txt) */
#include "fuzz_util.h"

#include <rfir/localize/localize_config.h>
#include <rfir/maps/CIREmitterMap.h>
#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/obs/registerAllClasses.h>
#include <rfir/sim/simulator.h>
#include <rfir/slam/slam_config.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/system/string_utils.h>

namespace {
const char* kEmitters =
    "emitter 12 1.0 1.0 2.5\nemitter 23 3.0 1.0 2.5\nemitter 5 2.0 3.0 2.5\n";

void loadMaps(std::string text) {
    // MRPT reads emitter_file as given: @EMITTERS@ names the scratch file.
    const std::string tag = "@EMITTERS@",
                      file = rfir::fuzz::scratchDir() + "/emitters.txt";
    for (size_t p = 0; (p = text.find(tag, p)) != std::string::npos; p += file.size())
        text.replace(p, tag.size(), file);
    mrpt::config::CConfigFileMemory c(text);
    // MRPT 2.5.8 counts <class>_count = -1 (keys in any case) as 4e9 map
    // definitions, for any class: a hang (docs/hardening.md, "MRPT's map
    // loader"). rfir-localize refuses such a count; MRPT's apps do not. Over
    // 16 maps adds no code path, only time per input.
    std::vector<std::string> keys;
    c.getAllKeys("MetricMap", keys);
    for (const auto& k : keys) {
        const std::string lk = mrpt::system::lowerCase(k);
        if (lk.size() > 6 && lk.compare(lk.size() - 6, 6, "_count") == 0) {
            const long n = c.read_int("MetricMap", k, 0);
            if (n < 0 || n > 16) return;
        }
    }
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(c, "MetricMap");
    mrpt::maps::CMultiMetricMap mm;
    mm.setListOfMaps(inits);
}
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    rfir::obs::registerAllClasses();
    rfir::maps::registerAllClasses();
    rfir::maps::registerIRClasses();
    // A relative emitter_file is relative to the INI: give the corpus inputs one.
    const std::string e(kEmitters);
    rfir::fuzz::writeInput("emitters.txt", reinterpret_cast<const uint8_t*>(e.data()),
                           e.size());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    try {
        switch (data[0]) {
            case '0': {
                mrpt::config::CConfigFileMemory c(text);
                rfir::slam::loadSlamConfig(c);
                break;
            }
            case '1': {
                rfir::localize::TConfig cfg;
                cfg.iniPath = rfir::fuzz::writeInput("localize.ini", data + 1, size - 1);
                rfir::localize::loadConfig(cfg, "");
                break;
            }
            case '2':
                rfir::sim::loadSimConfig(
                    rfir::fuzz::writeInput("sim.ini", data + 1, size - 1));
                break;
            case '3':
                loadMaps(text);
                break;
            default:
                break;
        }
    } catch (const std::exception&) {
    }
    return 0;
}
