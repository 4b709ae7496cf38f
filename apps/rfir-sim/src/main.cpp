/* rfir-sim: simulates one run of the papers' setups from an INI file and writes
 * its rawlog and ground truth. See docs/simulator.md. */
#include <rfir/common/cli.h>
#include <rfir/common/ini_file.h>
#include <rfir/common/ini_key_docs.h>
#include <rfir/common/ini_override.h>
#include <rfir/obs/registerAllClasses.h>
#include <rfir/sim/simulator.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace {
const char* kDescription =
    "Simulates an omnidirectional robot with HF RFID readers over a tag carpet, IR "
    "receivers under a ceiling emitter lattice and/or a range-and-bearing sensor, as "
    "configured by an INI file (config_ini/sim_*.ini). Writes DIR/NAME.rawlog, "
    "DIR/NAME.gt.tum (true robot path), DIR/NAME.gt_map.txt (true tags, emitters, "
    "landmarks) and, when the trajectory has marked spots, DIR/NAME.spots.tum; with "
    "faults (docs/simulator.md) DIR/NAME.gt_faults.txt, with moved IR emitters "
    "DIR/NAME.map.txt (the map for the localizer). The same INI and seed give "
    "byte-identical files.";

int run(const std::string& ini, const std::vector<std::string>& sets,
        const std::string& dir, uint64_t seed, std::string name, bool quiet) {
    namespace fs = std::filesystem;
    if (name.empty()) name = fs::path(ini).stem().string();
    if (name.empty() || name.find('/') != std::string::npos)
        throw rfir::common::CUsageError("--name '" + name + "' is not a file name");
    // A --set edit the INI refuses is a command-line error naming it.
    rfir::sim::TSimConfig cfg;
    rfir::common::loadWithIniEdits(sets, [&](const std::vector<std::string>& e) {
        cfg = rfir::sim::loadSimConfig(ini, e);
    });
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (!fs::is_directory(dir)) {
        std::cerr << "rfir-sim: error: " << dir
                  << ": cannot create the output directory\n";
        return 1;
    }
    if (!quiet)
        std::cerr << "rfir-sim: " << ini << " seed " << seed << ": simulating...\n";
    const auto out = rfir::sim::simulate(cfg, seed);
    if (!quiet) {
        size_t det = 0;
        for (const auto& s : out.steps)
            for (const auto& o : s.obs)
                if (auto r =
                        std::dynamic_pointer_cast<rfir::obs::CObservationRFIDReaders>(o))
                    det += r->detectionCount();
        // Odometry alone against the truth: how much there is to correct.
        double sumErr = 0, maxErr = 0;
        size_t nOdo = 0;
        for (const auto& s : out.steps)
            if (s.odometry) {
                const double e = s.odometry->distanceTo(s.truePose);
                sumErr += e, maxErr = std::max(maxErr, e), nOdo++;
            }
        std::cerr << "rfir-sim: " << out.steps.size() << " steps ("
                  << (out.steps.empty() ? 0.0 : out.steps.back().t) << " s), "
                  << out.gtMap.size() << " map entries, " << det << " RFID detections, "
                  << out.spots.size() << " spots; odometry alone: mean error "
                  << (nOdo ? sumErr / nOdo : 0.0) << " m, max " << maxErr << " m\n";
    }
    rfir::sim::writeOutputs(out, dir, name, quiet ? nullptr : &std::cerr);
    if (!quiet) std::cerr << "rfir-sim: wrote " << dir << "/" << name << ".*\n";
    return 0;
}
/** --help-keys: the keys of the INI with the --set edits, on stdout. */
int listKeys(const std::string& ini, const std::vector<std::string>& sets) {
    std::cout << rfir::common::describeKeys("rfir-sim", [&] {
        std::string text;
        rfir::common::loadWithIniEdits(sets, [&](const std::vector<std::string>& e) {
            rfir::sim::loadSimConfig(ini, e);
            auto f = rfir::common::readIniFile(ini);
            rfir::common::applyIniOverrides(f, e);
            text = f.getContent();
        });
        return text;
    });
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    try {
        rfir::obs::registerAllClasses();
        // --help-keys simulates nothing: no output directory then.
        const bool keysOnly =
            std::find(argv, argv + argc, std::string("--help-keys")) != argv + argc;
        TCLAP::CmdLine cmd(kDescription, ' ', RFIR_VERSION);
        rfir::common::CConfigArg ini(
            "c", "config",
            "simulation INI file, or a stock one by name (e.g. sim_kidnap)", true, cmd,
            "sim_");
        TCLAP::ValueArg<std::string> dir("", "out-dir", "output directory (created)",
                                         !keysOnly, "", "DIR", cmd);
        rfir::common::CNumberArg<uint64_t> seed("s", "seed", "random seed (default 1)",
                                                false, 1, "N", cmd);
        TCLAP::ValueArg<std::string> name("n", "name",
                                          "output file stem (default: the INI's stem)",
                                          false, "", "NAME", cmd);
        TCLAP::MultiArg<std::string> sets(
            "", "set",
            "override an INI key, e.g. --set trajectory.speed=0.3 (repeatable)", false,
            "SECTION.KEY=VALUE", cmd);
        TCLAP::SwitchArg quiet("q", "quiet", rfir::common::kQuietHelp, cmd, false);
        TCLAP::SwitchArg helpKeys("", "help-keys", rfir::common::kHelpKeysHelp, cmd,
                                  false);
        // -o was the folder here but is a file elsewhere (rfir-import).
        if (const auto code =
                rfir::common::parseCommandLine(cmd, argc, argv, {{"-o", "--out-dir"}}))
            return *code;
        if (helpKeys.getValue()) return listKeys(ini.getValue(), sets.getValue());
        return run(ini.getValue(), sets.getValue(), dir.getValue(), seed.getValue(),
                   name.getValue(), quiet.getValue());
    } catch (const rfir::common::CUsageError& e) {  // thrown before any work
        std::cerr << "rfir-sim: error: " << e.what() << "\n";
        return rfir::common::kUsageExitCode;
    } catch (const std::exception& e) {
        std::cerr << "rfir-sim: error: " << e.what() << "\n";
        return 1;
    }
}
