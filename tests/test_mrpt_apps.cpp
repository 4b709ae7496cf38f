// MRPT's own rbpf-slam and pf-localization (the installed programs, with the
// plugin preloaded) run to the end on a bundled RFID rawlog with the stock
// INIs of config_ini/, and their estimated paths are scored against the
// ground truth here, and by rfir-eval --path-format mrpt with the same
// numbers. Skipped when the programs are not installed.
#include <rfir/common/rawlog_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/eval/metrics.h>
#include <rfir/maps/CRFIDTagParticleMap.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/poses/CPoint2D.h>
#include <mrpt/serialization/CArchive.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace fs = std::filesystem;
using rfir::common::TPath2D;

namespace {
using rfir_test::TmpDir;
const std::string kSrc = RFIR_SOURCE_DIR;
const std::string kPlugin = std::string(RFIR_BINARY_DIR) + "/lib/librfir_mrpt_plugin.so";
const std::string kRawlog = kSrc + "/datasets/rfid_60mm_16tags_loop.rawlog";
const std::string kTruth = kSrc + "/datasets/rfid_60mm_16tags_loop.gt.tum";

bool installed(const std::string& exe) {
    return std::system(("command -v " + exe + " > /dev/null 2>&1").c_str()) == 0;
}

/** The stock INI, its repository-relative dataset paths made absolute. */
void copyIni(const std::string& name, const std::string& to) {
    std::ifstream in(kSrc + "/config_ini/" + name);
    ASSERT_TRUE(in) << name;
    std::stringstream ss;
    ss << in.rdbuf();
    std::string s = ss.str();
    for (size_t p = 0; (p = s.find("= datasets/", p)) != std::string::npos;)
        s.replace(p, 11, "= " + kSrc + "/datasets/");
    std::ofstream(to) << s;
}

/** The LD_PRELOAD list: the plugin, after the sanitizer runtimes in the
 * sanitizer build (scripts/sanitize.sh), which MRPT's uninstrumented programs
 * need loaded first to load the instrumented plugin. */
std::string preloadList() {
    const char* san = std::getenv("RFIR_SANITIZER_PRELOAD");
    return san && *san ? std::string(san) + ":" + kPlugin : kPlugin;
}

/** Runs `exe ini rawlog` in `dir` with the plugin preloaded; its exit code. */
int runApp(const std::string& exe, const TmpDir& dir, const std::string& ini) {
    const std::string cmd = "cd " + dir.p.string() + " && LD_PRELOAD='" + preloadList() +
                            "' " + exe + " " + ini + " " + kRawlog + " < /dev/null > " +
                            exe + ".log 2>&1";
    return std::system(cmd.c_str());
}

std::string tail(const std::string& file) {
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string s = ss.str();
    return s.size() > 2000 ? s.substr(s.size() - 2000) : s;
}

/** The instants' times of the rawlog, and its start pose. */
std::vector<double> instantTimes(mrpt::poses::CPose2D& start) {
    rfir::common::CRawlogReader r(kRawlog);
    start = r.header().startPose.value_or(mrpt::poses::CPose2D());
    std::vector<double> t;
    rfir::common::TRawlogStep st;
    while (r.next(st)) t.push_back(st.t);
    return t;
}

/** rfir-eval's JSON line for `args` (with --json-only), run in `dir`. */
nlohmann::json rfirEval(const TmpDir& dir, const std::string& args) {
    const std::string out = dir / "eval.json", err = dir / "eval.err";
    const std::string cmd = std::string(RFIR_BINARY_DIR) + "/bin/rfir-eval --json-only " +
                            args + " > " + out + " 2> " + err;
    EXPECT_EQ(std::system(cmd.c_str()), 0) << tail(err);
    std::ifstream in(out);
    return nlohmann::json::parse(in, nullptr, false);
}

rfir::eval::TErrorStats score(const TPath2D& est) {
    const auto e = rfir::eval::computeRobotErrors(est, rfir::common::loadTUM(kTruth));
    EXPECT_EQ(e.skipped, 0u);
    return e.stats;
}

/** Mean distance of a map file's tags (composed with `origin`) to the
 * truth, and their count. */
std::pair<double, size_t> tagErrors(const std::string& file,
                                    const mrpt::poses::CPose2D& origin) {
    std::map<std::string, mrpt::math::TPoint2D> gt;
    std::ifstream g(kSrc + "/datasets/rfid_60mm_16tags_loop.gt_map.txt");
    for (std::string kind, id, rest; g >> kind;) {
        double x, y;
        if (kind == "tag" && g >> id >> x >> y) gt[id] = {x, y};
        std::getline(g, rest);
    }
    std::ifstream in(file);
    double sum = 0;
    size_t n = 0;
    for (std::string kind, id, rest; in >> kind;) {
        double x, y;
        if (kind == "tag" && in >> id >> x >> y) {
            EXPECT_TRUE(gt.count(id)) << id;
            const auto p = origin + mrpt::poses::CPoint2D(x, y);
            sum += std::hypot(p.x() - gt[id].x, p.y() - gt[id].y);
            n++;
        }
        std::getline(in, rest);
    }
    return {n ? sum / double(n) : 1e9, n};
}

TEST(MrptApps, RbpfSlamWithTheTagMap) {
    if (!installed("rbpf-slam")) GTEST_SKIP() << "rbpf-slam is not installed";
    TmpDir d;
    copyIni("mrpt_rbpf_slam_rfid.ini", d / "rbpf.ini");
    ASSERT_EQ(runApp("rbpf-slam", d, "rbpf.ini"), 0) << tail(d / "rbpf-slam.log");
    // log_estimated_path.txt: step x y z yaw pitch roll t, from the origin.
    mrpt::poses::CPose2D start;
    const auto times = instantTimes(start);
    std::ifstream in(d / "rbpf_slam_out/log_estimated_path.txt");
    TPath2D est;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '%') continue;
        std::istringstream ls(line);
        double step, x, y, z, yaw, pitch, roll, t;
        ASSERT_TRUE(ls >> step >> x >> y >> z >> yaw >> pitch >> roll >> t) << line;
        if (step == 0) continue;  // the rawlog's header entry
        est.push_back({t, start + mrpt::poses::CPose2D(x, y, yaw)});
    }
    ASSERT_EQ(est.size(), times.size());
    for (size_t i = 0; i < est.size(); i++) ASSERT_NEAR(est[i].t, times[i], 1e-6);
    const auto s = score(est);
    std::cout << "rbpf-slam: mean " << 1000 * s.mean_dist << " mm, max "
              << 1000 * s.max_dist << " mm over " << s.count << " poses\n";
    // Odometry alone: 242 mm (rfir-slam's table); rfir-slam's PF-SLAM 156 mm.
    EXPECT_LT(s.mean_dist, 0.2);
    // The most likely particle's tag map, saved by CRFIDTagParticleMap, in
    // the same frame as the path.
    const auto m = tagErrors(
        d / "rbpf_slam_out/finalMap_rfir__maps__CRFIDTagParticleMap_00_tags.txt", start);
    std::cout << "rbpf-slam: " << m.second << " tags, mean error " << 1000 * m.first
              << " mm\n";
    EXPECT_GT(m.second, 80u);  // of the 92 passed over
    EXPECT_LT(m.first, 0.2);

    // rfir-eval reads the same files with --path-format / --map-format mrpt
    // (composed with the rawlog header's start pose): the same numbers.
    const std::string out = d / "rbpf_slam_out";
    const auto j = rfirEval(
        d, "--path-format mrpt --map-format mrpt --rawlog " + kRawlog + " --path " + out +
               "/log_estimated_path.txt --map " + out +
               "/finalMap_rfir__maps__CRFIDTagParticleMap_00_tags.txt --gt-path " +
               kTruth + " --gt-map " + kSrc +
               "/datasets/rfid_60mm_16tags_loop.gt_map.txt");
    ASSERT_TRUE(j.is_object()) << j;
    EXPECT_EQ(j.at("robot").at("poses"), est.size());
    EXPECT_NEAR(j.at("robot").at("mean_dist").get<double>(), s.mean_dist, 1e-9);
    EXPECT_NEAR(j.at("robot").at("max_dist").get<double>(), s.max_dist, 1e-9);
    EXPECT_EQ(j.at("tags").at("count"), m.second);
    EXPECT_NEAR(j.at("tags").at("mean_dist").get<double>(), m.first, 1e-9);
    // As TUM, the file is refused, saying what it is.
    const std::string cmd = std::string(RFIR_BINARY_DIR) + "/bin/rfir-eval --path " +
                            out + "/log_estimated_path.txt --gt-path " + kTruth + " 2> " +
                            (d / "refused.err") + " > /dev/null";
    const int st = std::system(cmd.c_str());
    EXPECT_EQ(WIFEXITED(st) ? WEXITSTATUS(st) : -1, 1);
    EXPECT_NE(tail(d / "refused.err").find("use --path-format mrpt"), std::string::npos);
}

TEST(MrptApps, PfLocalizationAgainstThePriorTagMap) {
    if (!installed("pf-localization")) GTEST_SKIP() << "pf-localization is not installed";
    TmpDir d;
    copyIni("mrpt_pf_localization_rfid.ini", d / "pf.ini");
    ASSERT_EQ(runApp("pf-localization", d, "pf.ini"), 0)
        << tail(d / "pf-localization.log");
    // particles_NNNNN.txt at every 10th step: x y phi log-weight per particle;
    // step k is the rawlog's instant k - 1 (step 0: the header entry).
    mrpt::poses::CPose2D start;
    const auto times = instantTimes(start);
    const fs::path parts = d.p / "pf_localization_out_000_0000300/particles";
    TPath2D est;
    for (size_t step = 9; step <= times.size(); step += 10) {
        char name[64];
        std::snprintf(name, sizeof name, "particles_%05zu.txt", step);
        std::ifstream in(parts / name);
        ASSERT_TRUE(in) << parts / name;
        double sw = 0, sx = 0, sy = 0, sc = 0, ss = 0;
        for (std::string line; std::getline(in, line);) {
            if (line.empty() || line[0] == '%') continue;  // the column names
            std::istringstream ls(line);
            double x, y, phi, lw;
            ASSERT_TRUE(ls >> x >> y >> phi >> lw) << line;
            const double w = std::exp(lw);
            sw += w, sx += w * x, sy += w * y;
            sc += w * std::cos(phi), ss += w * std::sin(phi);
        }
        ASSERT_GT(sw, 0) << name;
        est.push_back({times[step - 1], {sx / sw, sy / sw, std::atan2(ss, sc)}});
    }
    ASSERT_GT(est.size(), 150u);
    const auto s = score(est);
    std::cout << "pf-localization: mean " << 1000 * s.mean_dist << " mm, max "
              << 1000 * s.max_dist << " mm over " << s.count << " poses\n";
    EXPECT_LT(s.mean_dist, 0.05);
    EXPECT_LT(s.max_dist, 0.15);
    // rfir-eval reads the output folder (the rawlog gives the steps' times).
    const auto j =
        rfirEval(d, "--path-format mrpt --rawlog " + kRawlog + " --path " +
                        (d / "pf_localization_out_000_0000300") + " --gt-path " + kTruth);
    ASSERT_TRUE(j.is_object()) << j;
    EXPECT_EQ(j.at("robot").at("poses"), est.size());
    EXPECT_NEAR(j.at("robot").at("mean_dist").get<double>(), s.mean_dist, 1e-9);
    EXPECT_NEAR(j.at("robot").at("max_dist").get<double>(), s.max_dist, 1e-9);
}

/** A CMultiMetricMap with the tag map, as pf-localization builds it. */
mrpt::maps::CMultiMetricMap mapFromIni(const std::string& priorFile) {
    mrpt::config::CConfigFileMemory ini;
    ini.write("MetricMap", "rfidTagMap_count", 1);
    ini.write("MetricMap_rfidTagMap_00_creationOpts", "prior_map_file", priorFile);
    ini.write("MetricMap_rfidTagMap_00_likelihoodOpts", "robot_update", "literal");
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(ini, "MetricMap");
    mrpt::maps::CMultiMetricMap m;
    m.setListOfMaps(inits);
    return m;
}

TEST(MrptApps, PriorTagMapInACMultiMetricMap) {
    rfir::maps::registerAllClasses();
    TmpDir d;
    std::ofstream(d / "prior.txt") << "# a map\ntag A 1 2\nlandmark L 3 4 0.1 0.1\n"
                                      "emitter E 1 1\n";
    auto mm = mapFromIni(d / "prior.txt");
    auto m = mm.mapByClass<rfir::maps::CRFIDTagParticleMap>();
    ASSERT_TRUE(m);
    ASSERT_EQ(m->tagCount(), 1u);
    ASSERT_EQ(m->landmarkCount(), 1u);
    EXPECT_NEAR(m->getTag("A")->estimate.mean.x, 1, 1e-9);
    EXPECT_NEAR(m->getTag("A")->estimate.mean.y, 2, 1e-9);
    EXPECT_NEAR(m->getLandmark("L")->estimate.mean.x, 3, 0.05);
    // A read of A weighs a robot whose reader covers the tag above one whose
    // reader does not (the likelihood receives the robot pose).
    rfir::obs::CObservationRFIDReaders obs;
    rfir::obs::CObservationRFIDReaders::TReading rd;
    rd.reader = {"R0", 0.1, 0, 0.03, 0.03};
    rd.tags = {"A"};
    obs.readings.push_back(rd);
    const double in =
        mm.computeObservationLikelihood(obs, mrpt::poses::CPose3D(0.9, 2, 0));
    const double out =
        mm.computeObservationLikelihood(obs, mrpt::poses::CPose3D(0.5, 2, 0));
    EXPECT_TRUE(std::isfinite(in) && std::isfinite(out));
    EXPECT_GT(in, out);
    // Copies by serialization (as rbpf-slam's resampling) keep the prior.
    mrpt::io::CMemoryStream buf;
    mrpt::serialization::archiveFrom(buf) << mm;
    buf.Seek(0);
    mrpt::maps::CMultiMetricMap copy;
    mrpt::serialization::archiveFrom(buf) >> copy;
    auto mc = copy.mapByClass<rfir::maps::CRFIDTagParticleMap>();
    ASSERT_TRUE(mc);
    EXPECT_EQ(mc->tagCount(), 1u);
    EXPECT_EQ(copy.computeObservationLikelihood(obs, mrpt::poses::CPose3D(0.9, 2, 0)),
              in);

    // A bad record names the file and line; a missing file is refused.
    std::ofstream(d / "bad.txt") << "tag A 1 2\ntag B 1\n";
    try {
        mapFromIni(d / "bad.txt");
        FAIL() << "no error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("bad.txt:2"), std::string::npos) << e.what();
    }
    EXPECT_THROW(mapFromIni(d / "missing.txt"), std::exception);
}

}  // namespace
