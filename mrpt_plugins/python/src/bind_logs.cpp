/* rfir's Python module: text logs, rawlogs, paths and maps (files). */
#include "bindings.h"

#include <rfir/common/log_convert.h>
#include <rfir/common/textlog.h>

#include <pybind11/stl.h>

#include <sstream>
#include <stdexcept>

namespace rfir::python {
using rfir::common::TMapEntry;

py::array_t<double> pathToArray(const rfir::common::TPath2D& p) {
    py::array_t<double> a({py::ssize_t(p.size()), py::ssize_t(4)});
    auto m = a.mutable_unchecked<2>();
    for (size_t i = 0; i < p.size(); i++) {
        const auto k = py::ssize_t(i);
        m(k, 0) = p[i].t;
        m(k, 1) = p[i].pose.x();
        m(k, 2) = p[i].pose.y();
        m(k, 3) = p[i].pose.phi();
    }
    return a;
}

rfir::common::TPath2D arrayToPath(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& a) {
    if (a.ndim() != 2 || a.shape(1) != 4)
        throw std::invalid_argument("a path is an n x 4 array (t, x, y, phi)");
    const auto m = a.unchecked<2>();
    rfir::common::TPath2D p;
    for (py::ssize_t i = 0; i < a.shape(0); i++)
        p.push_back({m(i, 0), rfir::common::exactPose(m(i, 1), m(i, 2), m(i, 3))});
    return p;
}

namespace {
const char* kindText(TMapEntry::Kind k) {
    return k == TMapEntry::Kind::Tag       ? "tag"
           : k == TMapEntry::Kind::Emitter ? "emitter"
                                           : "landmark";
}

template <class T>
py::object opt(const std::optional<T>& v) {
    return v ? py::cast(*v) : py::none();
}

template <class T>
std::optional<T> optFrom(const py::dict& d, const char* key) {
    if (!d.contains(key) || d[key].is_none()) return std::nullopt;
    return d[key].cast<T>();
}

py::dict recordToDict(const rfir::common::TTimedRecord& r) {
    py::dict d;
    d["kind"] = rfir::common::kindName(r.kind);
    d["t"] = r.t;
    d["line"] = r.line;
    using K = rfir::common::TTimedRecord::Kind;
    if (r.kind != K::Odom) d["id"] = r.id;
    if (r.kind == K::Odom) {
        d["x"] = r.x;
        d["y"] = r.y;
        d["phi"] = r.phi;
    } else if (r.kind == K::Rfid) {
        d["tags"] = r.tags;
    } else if (r.kind == K::Ir) {
        d["codes"] = std::vector<int>(r.codes.begin(), r.codes.end());
        d["volts"] = r.volts;
    } else if (r.kind == K::IrRaw) {
        d["rate_hz"] = r.rateHz;
        d["samples"] = r.samples;
    } else {
        d["range"] = r.range;
        d["bearing"] = r.bearing;
    }
    return d;
}

py::dict reportToDict(const rfir::common::TConvertReport& r) {
    py::dict d;
    d["timed_records"] = r.timedRecords;
    d["instants"] = r.instants;
    d["dropped"] = r.dropped;
    return d;
}
}  // namespace

py::list mapToList(const rfir::common::TMapFile& m) {
    py::list l;
    for (const auto& e : m) {
        py::dict d;
        d["kind"] = kindText(e.kind);
        d["id"] = e.id;
        d["x"] = e.x;
        d["y"] = e.y;
        if (e.kind == TMapEntry::Kind::Emitter) d["z"] = e.z;
        d["sx"] = opt(e.sx);
        d["sy"] = opt(e.sy);
        d["reads"] = opt(e.reads);
        d["contradicted"] = opt(e.contradicted);
        l.append(d);
    }
    return l;
}

rfir::common::TMapFile listToMap(const py::list& l) {
    rfir::common::TMapFile m;
    for (const auto& item : l) {
        const auto d = item.cast<py::dict>();
        TMapEntry e;
        const auto kind = d["kind"].cast<std::string>();
        if (kind == "tag")
            e.kind = TMapEntry::Kind::Tag;
        else if (kind == "emitter")
            e.kind = TMapEntry::Kind::Emitter;
        else if (kind == "landmark")
            e.kind = TMapEntry::Kind::Landmark;
        else
            throw std::invalid_argument("map entry kind '" + kind +
                                        "': tag, emitter or landmark");
        e.id = d["id"].cast<std::string>();
        e.x = d["x"].cast<double>();
        e.y = d["y"].cast<double>();
        e.z = optFrom<double>(d, "z").value_or(0.0);
        e.sx = optFrom<double>(d, "sx");
        e.sy = optFrom<double>(d, "sy");
        e.reads = optFrom<uint64_t>(d, "reads");
        e.contradicted = optFrom<uint64_t>(d, "contradicted");
        m.push_back(std::move(e));
    }
    return m;
}

void bindLogs(py::module_& m) {
    using namespace rfir::common;
    m.def(
        "import_textlog",
        [](const std::string& in, const std::string& out) {
            py::gil_scoped_release nogil;
            const auto r = convertTextLogToRawlog(in, out);
            py::gil_scoped_acquire gil;
            return reportToDict(r);
        },
        py::arg("textlog"), py::arg("rawlog"),
        "Converts a text log into a rawlog, as rfir-import does (checked whole first; "
        "nothing written on an error). Returns the counts of the conversion.");
    m.def(
        "export_textlog",
        [](const std::string& in, const std::string& out, bool lossy) {
            TConvertOptions o;
            o.lossy = lossy;
            py::gil_scoped_release nogil;
            const auto r = convertRawlogToTextLog(in, out, o);
            py::gil_scoped_acquire gil;
            return reportToDict(r);
        },
        py::arg("rawlog"), py::arg("textlog"), py::arg("lossy") = false,
        "Converts a rawlog into a text log, as rfir-import does.");
    m.def(
        "_read_textlog",
        [](const std::string& path) {
            const TTextLog log = readTextLog(path);
            std::ostringstream header;
            writeTextLogHeader(header, log.header);
            py::list recs;
            for (const auto& r : log.records) recs.append(recordToDict(r));
            return py::make_tuple(header.str(), recs);
        },
        py::arg("path"));
    m.def(
        "load_tum", [](const std::string& f) { return pathToArray(loadTUM(f)); },
        py::arg("file"), "A TUM path file as an n x 4 array: t, x, y, phi.");
    m.def(
        "save_tum",
        [](const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
           const std::string& f) { saveTUM(f, arrayToPath(a)); },
        py::arg("path"), py::arg("file"),
        "Writes an n x 4 path (t, x, y, phi) as TUM, byte for byte as the programs do.");
    m.def(
        "_load_map", [](const std::string& f) { return mapToList(loadMapFile(f)); },
        py::arg("file"));
    m.def(
        "_save_map",
        [](const py::list& l, const std::string& f, const std::string& comment) {
            saveMapFile(f, listToMap(l), comment);
        },
        py::arg("entries"), py::arg("file"), py::arg("comment") = "");
}
}  // namespace rfir::python
