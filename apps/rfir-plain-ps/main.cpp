/* rfir-plain-ps: the plain reference PS-SLAM (rfir_plain) as a whole program
 * on a text log, the one rfir-bench times rfir-slam's whole process against
 * (docs/benchmark.md). Writes the posterior mean path as TUM. */
#include <rfir/bench/plain_textlog.h>

#include <rfir/common/cli.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>

namespace {
void writeTum(const std::string& path, const std::string& text) {
    // Whole or not at all: a temporary beside the target, then a rename.
    const std::string tmp = path + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw std::runtime_error(path + ": cannot write");
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw std::runtime_error(path + ": cannot write");
    }
}
}  // namespace

int main(int argc, char** argv) {
    try {
        TCLAP::CmdLine cmd(
            "rfir-plain-ps: the plain reference PS-SLAM (one file of flat loops, the "
            "stock slam_ps.ini's method without kidnap recovery) on a text log with "
            "RFID records; what rfir-bench times rfir-slam against.",
            ' ', RFIR_VERSION);
        TCLAP::ValueArg<std::string> input("i", "input", "text log (format textlog 1)",
                                           true, "", "FILE", cmd);
        TCLAP::ValueArg<std::string> output("o", "output", "mean path to write (TUM)",
                                            false, "", "TUM", cmd);
        rfir::common::CNumberArg<size_t> particles(
            "m", "particles", "robot particles (default 500)", false, 500, "M", cmd, 1);
        rfir::common::CNumberArg<uint64_t> seed("s", "seed", "random seed (default 1)",
                                                false, 1, "N", cmd);
        rfir::common::CNumberListArg<double> motion(
            "", "motion",
            "odometry noise a1,a2,a3,a4,min_std_xy,min_std_phi, each >= 0 (default "
            "MRPT's Gaussian model's: 0.05,0.001,0.02,0.02,0.001,0.002)",
            false, "LIST", cmd, ',', 6, 0);
        if (const auto exit = rfir::common::parseCommandLine(cmd, argc, argv))
            return *exit;
        rfir::bench::TPlainOptions o;
        o.M = particles.getValue();
        o.seed = seed.getValue();
        if (motion.isSet()) {
            const auto& v = motion.values();
            o.motion = {v[0], v[1], v[2], v[3], v[4], v[5]};
        }

        const auto log = rfir::bench::loadPlainTextLog(input.getValue());
        rfir::bench::CPlainPsCore core(o);
        core.reset(log.start[0], log.start[1], log.start[2]);
        std::string tum;
        char line[160];
        for (const auto& in : log.instants) {
            core.step(in.hasU ? in.u : nullptr, log.reads.data() + in.firstRead,
                      in.nReads);
            double x, y, phi;
            core.meanPose(x, y, phi);
            const int n =
                std::snprintf(line, sizeof(line), "%.6f %.6f %.6f 0 0 0 %.9f %.9f\n",
                              in.t, x, y, std::sin(phi / 2), std::cos(phi / 2));
            tum.append(line, size_t(n));
        }
        if (output.isSet()) writeTum(output.getValue(), tum);
        std::cerr << "rfir-plain-ps: " << log.instants.size() << " instants, "
                  << core.tagsMapped() << " tags mapped\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "rfir-plain-ps: error: " << e.what() << "\n";
        return 1;
    }
}
