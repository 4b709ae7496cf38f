/* rfir-bench: whole-process rfir-slam runs, as a user runs them: the rfir-sim
 * and rfir-slam programs beside rfir-bench, the log written as a rawlog with
 * its ground truth, rfir-slam with the stock slam_ps.ini and every default
 * output (path, map, errors, plots, 3D scene). Timed from outside: the
 * child's user + system CPU (wait4) and its wall clock, so loading MRPT's
 * shared libraries, reading the rawlog and writing the outputs all count. */
#include <rfir/bench/bench.h>

#include <rfir/slam/slam_config.h>

#include <mrpt/system/filesystem.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace rfir::bench {
namespace {
/** The folder of this program (where rfir-sim and rfir-slam are built or
 * installed beside it). */
std::string selfDir() {
    char buf[4096];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
    if (n <= 0) return ".";
    buf[n] = '\0';
    return mrpt::system::extractFileDirectory(buf);
}

struct TChildTimes {
    int status = -1;
    double cpu = 0, wall = 0;
};

/** Runs argv[0] with its output discarded; its CPU time from wait4. */
TChildTimes runChild(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const double w0 = wallSeconds();
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("rfir-bench: fork failed");
    if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0) dup2(null, 1), dup2(null, 2);
        execv(argv[0], argv.data());
        _exit(127);
    }
    TChildTimes t;
    struct rusage ru {};
    if (wait4(pid, &t.status, 0, &ru) != pid)
        throw std::runtime_error("rfir-bench: wait4 failed for " + args[0]);
    t.wall = wallSeconds() - w0;
    t.cpu = double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
            1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
    return t;
}

void mustSucceed(const TChildTimes& t, const std::vector<std::string>& args) {
    if (!WIFEXITED(t.status) || WEXITSTATUS(t.status) != 0) {
        std::string cmd;
        for (const auto& a : args) cmd += " " + a;
        throw std::runtime_error("rfir-bench: failed (status " +
                                 std::to_string(t.status) + "):" + cmd);
    }
}
}  // namespace

std::vector<TProcessRun> runProcesses(const TBenchOptions& o) {
    const std::string dir = selfDir();
    const std::string sim = dir + "/rfir-sim", slam = dir + "/rfir-slam";
    if (!mrpt::system::fileExists(sim) || !mrpt::system::fileExists(slam)) return {};
    // The logs and rfir-slam's outputs go to a scratch folder, removed after.
    const char* tmpDir = std::getenv("TMPDIR");
    std::string tmpl =
        std::string(tmpDir && *tmpDir ? tmpDir : "/tmp") + "/rfir-bench-XXXXXX";
    if (!mkdtemp(tmpl.data()))
        throw std::runtime_error("rfir-bench: cannot make a scratch folder " + tmpl);
    const std::string tmp = tmpl;
    struct TLogSpec {
        std::string ini;
        double seconds;
        bool floorEdits;  //!< the --set sim: edits apply (the floor run)
    };
    const std::vector<TLogSpec> logs = {
        {"bench_floor_30x20", o.realtimeSeconds, true},
        {"sim_rfid_300mm_4tags_random", o.compareSeconds, false}};
    std::vector<TProcessRun> out;
    for (const auto& l : logs) {
        char dur[64];
        std::snprintf(dur, sizeof(dur), "simulation.max_duration=%g", l.seconds);
        std::vector<std::string> sa = {sim,         "-q",
                                       "-c",        o.configDir + "/" + l.ini + ".ini",
                                       "-s",        std::to_string(o.seed),
                                       "--out-dir", tmp,
                                       "--set",     dur};
        if (l.floorEdits)
            for (const auto& e : o.simSets) sa.insert(sa.end(), {"--set", e});
        mustSucceed(runChild(sa), sa);
        TProcessRun p;
        p.log = l.ini + ".ini, " + std::to_string(int(l.seconds)) + " s";
        p.robotSeconds = l.seconds;
        p.M = rfir::slam::loadSlamConfigFile(o.configDir + "/slam_ps.ini", std::nullopt)
                  .slam.robot_particles;
        p.cpuSeconds = p.wallSeconds = 1e300;
        const std::vector<std::string> ra = {slam,        "-q",
                                             "--rawlog",  tmp + "/" + l.ini + ".rawlog",
                                             "--config",  o.configDir + "/slam_ps.ini",
                                             "--seed",    std::to_string(o.seed),
                                             "--out-dir", tmp + "/out_" + l.ini};
        for (size_t r = 0; r < std::max<size_t>(1, o.rounds); r++) {
            mrpt::system::deleteFilesInDirectory(tmp + "/out_" + l.ini, true);
            const auto t = runChild(ra);
            mustSucceed(t, ra);
            p.cpuSeconds = std::min(p.cpuSeconds, t.cpu);
            p.wallSeconds = std::min(p.wallSeconds, t.wall);
        }
        // The same binary doing nothing but start and exit: the fixed cost of
        // loading its shared libraries.
        const std::vector<std::string> va = {slam, "--version"};
        p.startupCpuSeconds = 1e300;
        for (size_t r = 0; r < std::max<size_t>(1, o.rounds); r++)
            p.startupCpuSeconds = std::min(p.startupCpuSeconds, runChild(va).cpu);
        out.push_back(p);
    }
    mrpt::system::deleteFilesInDirectory(tmp, true);
    rmdir(tmp.c_str());
    return out;
}

}  // namespace rfir::bench
