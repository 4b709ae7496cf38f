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
template <class T>
T parseNumber(const std::string& opt, const std::string& s) {
    const auto v = rfir::common::parseNumber<T>(s);
    if (!v) throw std::invalid_argument(opt + ": '" + s + "' is not a number");
    return *v;
}

rfir::models::OdometryNoiseParams parseMotion(const std::string& s) {
    double v[6];
    size_t at = 0;
    for (int k = 0; k < 6; k++) {
        const size_t end = k < 5 ? s.find(',', at) : s.size();
        if (end == std::string::npos || (k == 5 && s.find(',', at) != std::string::npos))
            throw std::invalid_argument("--motion: expected 6 comma-separated numbers");
        v[k] = parseNumber<double>("--motion", s.substr(at, end - at));
        if (!(v[k] >= 0)) throw std::invalid_argument("--motion: values must be >= 0");
        at = end + 1;
    }
    return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

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
            ' ', "0.1");
        TCLAP::ValueArg<std::string> input("i", "input", "text log (format textlog 1)",
                                           true, "", "FILE", cmd);
        TCLAP::ValueArg<std::string> output("o", "output", "mean path to write (TUM)",
                                            false, "", "TUM", cmd);
        TCLAP::ValueArg<std::string> particles(
            "m", "particles", "robot particles (default 500)", false, "500", "M", cmd);
        TCLAP::ValueArg<std::string> seed("s", "seed", "random seed (default 1)", false,
                                          "1", "N", cmd);
        TCLAP::ValueArg<std::string> motion(
            "", "motion",
            "odometry noise a1,a2,a3,a4,min_std_xy,min_std_phi (default MRPT's "
            "Gaussian model's: 0.05,0.001,0.02,0.02,0.001,0.002)",
            false, "", "LIST", cmd);
        if (const auto exit = rfir::common::parseCommandLine(cmd, argc, argv))
            return *exit;
        rfir::bench::TPlainOptions o;
        o.M = parseNumber<size_t>("--particles", particles.getValue());
        if (o.M == 0) throw std::invalid_argument("--particles: must be > 0");
        o.seed = parseNumber<uint64_t>("--seed", seed.getValue());
        if (motion.isSet()) o.motion = parseMotion(motion.getValue());

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
    } catch (const std::invalid_argument& e) {
        std::cerr << "rfir-plain-ps: error: " << e.what() << "\n";
        return rfir::common::kUsageExitCode;
    } catch (const std::exception& e) {
        std::cerr << "rfir-plain-ps: " << e.what() << "\n";
        return 1;
    }
}
