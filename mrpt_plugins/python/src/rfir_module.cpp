/* rfir's Python module (_rfir, wrapped by the package rfir): the programs'
 * runs in-process, through the same library functions as rfir-slam,
 * rfir-localize and rfir-eval, with the GIL released while they run. */
#include "bindings.h"

#include <rfir/common/install_paths.h>
#include <rfir/common/usage_error.h>
#include <rfir/evalapp/eval_app.h>
#include <rfir/localize/localize_output.h>
#include <rfir/localize/localize_run.h>
#include <rfir/maps/CIREmitterMap.h>
#include <rfir/obs/registerAllClasses.h>
#include <rfir/slamapp/slam_app.h>
#include <rfir/version.h>

#include <pybind11/stl.h>

namespace rfir::python {
namespace {
std::optional<mrpt::poses::CPose2D> startFrom(
    const std::optional<std::vector<double>>& s) {
    if (!s) return std::nullopt;
    if (s->size() != 3) throw rfir::common::CUsageError("start: three numbers, x y phi");
    return mrpt::poses::CPose2D((*s)[0], (*s)[1], (*s)[2]);
}

/** MRPT's exceptions carry banners and a backtrace: the message only. */
template <class F>
auto cleanly(F&& f) {
    try {
        return f();
    } catch (const rfir::common::CUsageError&) {
        throw;
    } catch (const std::exception& e) {
        throw std::runtime_error(rfir::localize::cleanMessage(e));
    }
}

py::dict slam(const std::string& rawlog, const std::string& config,
              std::optional<std::string> method, uint64_t seed,
              const std::vector<std::string>& sets,
              const std::optional<std::vector<double>>& start,
              std::optional<std::string> gtPath, std::optional<std::string> gtMap,
              bool smooth, const std::string& outDir, bool quiet) {
    rfir::slamapp::TAppArgs a;
    a.rawlog = rawlog;
    a.outDir = outDir;
    a.method = std::move(method);
    if (!config.empty()) a.config = config;
    a.seed = seed;
    a.sets = sets;
    a.start = startFrom(start);
    a.gtPath = std::move(gtPath);
    a.gtMap = std::move(gtMap);
    a.smooth = smooth;
    a.quiet = quiet;
    rfir::slamapp::TSlamAppResult r;
    {
        py::gil_scoped_release nogil;
        r = cleanly([&] { return rfir::slamapp::runSlam(a); });
    }
    py::dict d;
    d["path"] = pathToArray(r.path);
    d["map"] = mapToList(r.map);
    d["stats_json"] = r.statsJson;
    d["errors_json"] = r.errorsJson;
    d["error_table"] = r.errorTable;
    if (smooth) {
        d["smoothed_path"] = pathToArray(r.smoothedPath);
        d["smoothed_map"] = mapToList(r.smoothedMap);
        d["smoothed_errors_json"] = r.smoothedErrorsJson;
    }
    return d;
}

py::dict localize(const std::string& rawlog, const std::string& config, uint64_t seed,
                  const std::string& emitters, const std::string& gtPath,
                  const std::vector<std::string>& sets, bool odometryOnly,
                  const std::string& outDir, bool quiet) {
    rfir::localize::TConfig cfg;
    cfg.iniPath = config.empty() ? rfir::localize::stockIniPath() : config;
    cfg.rawlogPath = rawlog;
    cfg.gtPath = gtPath;
    cfg.seed = seed;
    cfg.overrides = sets;
    cfg.odometryOnly = odometryOnly;
    cfg.quiet = quiet;
    cfg.outDir = outDir;
    rfir::localize::TLocalizeJob job;
    {
        py::gil_scoped_release nogil;
        job = cleanly([&] {
            return rfir::localize::runLocalizeJob(cfg, emitters, "rfir.localize");
        });
    }
    py::dict d;
    d["path"] = pathToArray(job.run.path);
    d["odometry"] = pathToArray(job.run.odometry);
    d["stats_json"] = job.summary.statsJson;
    d["errors_json"] = job.summary.errorsJson;
    d["error_table"] = job.summary.errorTable;
    return d;
}

/** rfir-eval's run, its JSON line written into `jsonFile`. */
void evaluate(rfir::evalapp::TEvalArgs a) {
    a.quiet = true;
    rfir::evalapp::validateEvalArgs(a);
    py::gil_scoped_release nogil;
    cleanly([&] { return rfir::evalapp::runEvalApp(a); });
}
}  // namespace

PYBIND11_MODULE(_rfir, m) {
    m.doc() = "rfir's runs in-process (see the package rfir and docs/python.md)";
    rfir::obs::registerAllClasses();
    rfir::maps::registerIRClasses();
    py::register_exception<rfir::common::CUsageError>(m, "UsageError", PyExc_ValueError);
    m.attr("__version__") = RFIR_VERSION;
    m.def("_set_stock_config_dir", &rfir::common::setStockConfigDir);
    m.def("_stock_config_dir", &rfir::common::stockConfigDir);
    m.def("_slam", &slam, py::arg("rawlog"), py::arg("config"), py::arg("method"),
          py::arg("seed"), py::arg("sets"), py::arg("start"), py::arg("gt_path"),
          py::arg("gt_map"), py::arg("smooth"), py::arg("out_dir"), py::arg("quiet"));
    m.def("_localize", &localize, py::arg("rawlog"), py::arg("config"), py::arg("seed"),
          py::arg("emitters"), py::arg("gt_path"), py::arg("sets"),
          py::arg("odometry_only"), py::arg("out_dir"), py::arg("quiet"));
    m.def(
        "_evaluate",
        [](const std::string& path, const std::string& gtPath, const std::string& map,
           const std::string& gtMap, const std::string& rawlog, const std::string& label,
           const std::string& kind, bool atGtTimes, bool noOdometry, int segments,
           const std::optional<std::vector<double>>& start, const std::string& jsonFile) {
            rfir::evalapp::TEvalArgs a;
            a.path = path;
            a.gtPath = gtPath;
            a.map = map;
            a.gtMap = gtMap;
            a.rawlog = rawlog;
            a.label = label;
            a.kind = kind;
            a.atGtTimes = atGtTimes;
            a.noOdometry = noOdometry;
            a.segments = segments;
            a.start = startFrom(start);
            a.jsonFile = jsonFile;
            evaluate(a);
        },
        py::arg("path"), py::arg("gt_path"), py::arg("map"), py::arg("gt_map"),
        py::arg("rawlog"), py::arg("label"), py::arg("kind"), py::arg("at_gt_times"),
        py::arg("no_odometry"), py::arg("segments"), py::arg("start"),
        py::arg("json_file"));
    bindLogs(m);
}
}  // namespace rfir::python
