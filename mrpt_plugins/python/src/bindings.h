/* rfir's Python module: conversions shared by its source files. */
#pragma once

#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace rfir::python {
namespace py = pybind11;

/** A path as an n x 4 array: t, x, y, phi (the poses of path.tum). */
py::array_t<double> pathToArray(const rfir::common::TPath2D& p);
/** The reverse; phi kept bit for bit. Throws std::invalid_argument on a
 * shape other than n x 4. */
rfir::common::TPath2D arrayToPath(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& a);
/** A map as a list of dicts: kind, id, x, y (z for emitters), sx, sy, reads,
 * contradicted (None when the file would not hold them). */
py::list mapToList(const rfir::common::TMapFile& m);
rfir::common::TMapFile listToMap(const py::list& l);

void bindLogs(py::module_& m);
}  // namespace rfir::python
