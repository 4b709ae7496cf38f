/* rfir-bench: whole-process rfir-slam runs, as a user runs them: the rfir-sim
 * and rfir-slam programs beside rfir-bench, the log written as a rawlog with
 * its ground truth, rfir-slam with the stock slam_ps.ini and every default
 * output (path, map, errors, plots, 3D scene). Timed from outside: the
 * child's user + system CPU (wait4) and its wall clock, so loading MRPT's
 * shared libraries, reading the rawlog and writing the outputs all count.
 * Side by side in the same rounds: rfir-plain-ps, the plain reference as a
 * whole program (no MRPT library), on the same log exported as text by
 * rfir-import, writing its path. */
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

/** An executable `name` on PATH, or "". */
std::string onPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "";
    for (size_t at = 0; at <= dirs.size();) {
        size_t end = dirs.find(':', at);
        if (end == std::string::npos) end = dirs.size();
        const std::string f = dirs.substr(at, end - at) + "/" + name;
        if (end > at && access(f.c_str(), X_OK) == 0) return f;
        at = end + 1;
    }
    return "";
}

struct TPrograms {
    std::string sim, slam, import, plain, tmp;
};

/** rfir-slam, the same binary only starting (--version) and rfir-plain-ps on
 * one simulated log, alternating in each round: the start-up the run is
 * compared with is timed under the same conditions. */
void timeOnLog(const TBenchOptions& o, const TPrograms& pr, const std::string& ini,
               TProcessRun& p) {
    const std::string rawlog = pr.tmp + "/" + ini + ".rawlog",
                      out = pr.tmp + "/out_" + ini;
    const auto cfg =
        rfir::slam::loadSlamConfigFile(o.configDir + "/slam_ps.ini", std::nullopt);
    p.M = cfg.slam.robot_particles;
    const std::vector<std::string> ra = {pr.slam,     "-q",
                                         "--rawlog",  rawlog,
                                         "--config",  o.configDir + "/slam_ps.ini",
                                         "--seed",    std::to_string(o.seed),
                                         "--out-dir", out};
    std::vector<std::string> pa;
    if (!pr.plain.empty()) {
        const std::vector<std::string> ia = {pr.import, "-q", "-i",
                                             rawlog,    "-o", rawlog + ".txt"};
        mustSucceed(runChild(ia), ia);
        const auto& m = cfg.motion;
        char motion[256];
        std::snprintf(motion, sizeof(motion), "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", m.a1,
                      m.a2, m.a3, m.a4, m.min_std_xy, m.min_std_phi);
        pa = {pr.plain,
              "-i",
              rawlog + ".txt",
              "-o",
              out + "_plain.tum",
              "-m",
              std::to_string(p.M),
              "-s",
              std::to_string(o.seed),
              "--motion",
              motion};
    }
    const std::vector<std::string> va = {pr.slam, "--version"};
    p.cpuSeconds = p.wallSeconds = p.plainCpuSeconds = p.plainWallSeconds = 1e300;
    p.startupCpuSeconds = 1e300;
    for (size_t r = 0; r < std::max<size_t>(1, o.rounds); r++) {
        mrpt::system::deleteFilesInDirectory(out, true);
        const auto t = runChild(ra);
        mustSucceed(t, ra);
        p.cpuSeconds = std::min(p.cpuSeconds, t.cpu);
        p.wallSeconds = std::min(p.wallSeconds, t.wall);
        const auto tv = runChild(va);
        mustSucceed(tv, va);
        p.startupCpuSeconds = std::min(p.startupCpuSeconds, tv.cpu);
        if (pa.empty()) continue;
        const auto tp = runChild(pa);
        mustSucceed(tp, pa);
        p.plainCpuSeconds = std::min(p.plainCpuSeconds, tp.cpu);
        p.plainWallSeconds = std::min(p.plainWallSeconds, tp.wall);
    }
    if (pa.empty()) p.plainCpuSeconds = p.plainWallSeconds = 0;
}
}  // namespace

std::vector<TProcessRun> runProcesses(const TBenchOptions& o) {
    const std::string dir = selfDir();
    TPrograms pr{dir + "/rfir-sim", dir + "/rfir-slam", dir + "/rfir-import",
                 dir + "/rfir-plain-ps", ""};
    if (!mrpt::system::fileExists(pr.sim) || !mrpt::system::fileExists(pr.slam))
        return {};
    if (!mrpt::system::fileExists(pr.import) || !mrpt::system::fileExists(pr.plain))
        pr.plain.clear();
    // The logs and the programs' outputs go to a scratch folder, removed after.
    const char* tmpDir = std::getenv("TMPDIR");
    std::string tmpl =
        std::string(tmpDir && *tmpDir ? tmpDir : "/tmp") + "/rfir-bench-XXXXXX";
    if (!mkdtemp(tmpl.data()))
        throw std::runtime_error("rfir-bench: cannot make a scratch folder " + tmpl);
    pr.tmp = tmpl;
    struct TLogSpec {
        std::string ini;
        double seconds;
        bool floorEdits;  //!< the --set sim: edits apply (the floor run)
    };
    const std::vector<TLogSpec> logs = {
        {"bench_floor_30x20", o.realtimeSeconds, true},
        {"sim_rfid_300mm_4tags_random", o.compareSeconds, false}};
    // MRPT's own program only starting: the fixed cost of loading MRPT, once
    // (the same for every log).
    const std::string rawlogEdit = onPath("rawlog-edit");
    double mrptStartup = 0;
    if (!rawlogEdit.empty()) {
        const std::vector<std::string> va = {rawlogEdit, "--version"};
        mrptStartup = 1e300;
        for (size_t r = 0; r < std::max<size_t>(1, o.rounds); r++)
            mrptStartup = std::min(mrptStartup, runChild(va).cpu);
    }
    std::vector<TProcessRun> out;
    for (const auto& l : logs) {
        char dur[64];
        std::snprintf(dur, sizeof(dur), "simulation.max_duration=%g", l.seconds);
        std::vector<std::string> sa = {pr.sim,      "-q",
                                       "-c",        o.configDir + "/" + l.ini + ".ini",
                                       "-s",        std::to_string(o.seed),
                                       "--out-dir", pr.tmp,
                                       "--set",     dur};
        if (l.floorEdits)
            for (const auto& e : o.simSets) sa.insert(sa.end(), {"--set", e});
        mustSucceed(runChild(sa), sa);
        TProcessRun p;
        p.log = l.ini + ".ini, " + std::to_string(int(l.seconds)) + " s";
        p.robotSeconds = l.seconds;
        timeOnLog(o, pr, l.ini, p);
        p.mrptStartupCpuSeconds = mrptStartup;
        out.push_back(p);
    }
    mrpt::system::deleteFilesInDirectory(pr.tmp, true);
    rmdir(pr.tmp.c_str());
    return out;
}

}  // namespace rfir::bench
