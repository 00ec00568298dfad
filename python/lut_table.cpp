// dspbr.lut.Table and dspbr.lut.Axis: one table of a table file as lut.load returns it, decoded
// (docs/luts.md): the quantity at every sample, the stored values, the per-sample errors, and per
// axis its warp, grid coordinates and the physical coordinate of every sample.
#include "lut_table.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "dspbr/tables/renderer_luts.h"

namespace dspbr::python {

namespace py = pybind11;

namespace {

template <class A>
std::vector<py::ssize_t> shape_of(const std::vector<A>& axes) {
  std::vector<py::ssize_t> shape;
  for (const A& a : axes) shape.push_back(a.size);
  return shape;
}

// An array of `shape` holding f(i) at flat (row-major) index i.
template <class F>
py::array_t<double> array_from(const std::vector<py::ssize_t>& shape, F&& f) {
  py::array_t<double> out(shape);
  double* p = out.mutable_data();
  for (py::ssize_t i = 0; i < out.size(); ++i) p[i] = f(size_t(i));
  return out;
}

py::object errors_of(const std::vector<double>& errors, const std::vector<py::ssize_t>& shape) {
  if (errors.empty()) return py::none();
  return array_from(shape, [&](size_t i) { return errors[i]; });
}

// The index of flat sample i along axis k of `shape`.
size_t axis_index(const std::vector<py::ssize_t>& shape, size_t k, size_t i) {
  for (size_t j = shape.size(); j-- > k + 1;) i /= size_t(shape[j]);
  return i % size_t(shape[k]);
}

}  // namespace

LoadedTable loaded_table(const Table& t) {
  const std::vector<py::ssize_t> shape = shape_of(t.axes);
  LoadedTable out{t.name, "published", "value", {}, {}, {}, {}};
  out.stored = array_from(shape, [&](size_t i) { return t.values[i]; });
  out.values = out.stored;  // the published layout stores the quantity itself
  out.errors = errors_of(t.errors, shape);
  for (size_t k = 0; k < t.axes.size(); ++k) {
    const Axis& a = t.axes[k];
    LoadedAxis la{a.name, a.size, grid_kind_name(a.kind), {}, {}};
    la.grid = array_from({a.size}, [&](size_t i) { return a.coord(int(i)); });
    la.coordinates = array_from(shape, [&](size_t i) { return a.coord(int(axis_index(shape, k, i))); });
    out.axes.push_back(std::move(la));
  }
  return out;
}

LoadedTable loaded_table(const WarpedTable& t) {
  const std::vector<py::ssize_t> shape = shape_of(t.axes);
  const char* encoding = is_lut(t.name, Lut::GgxBeta) ? "beta_minus_mirror"
                         : t.encoding == Encoding::LogOneMinus ? "log_one_minus"
                                                               : "value";
  LoadedTable out{t.name, "renderer", encoding, {}, {}, {}, {}};
  std::vector<std::array<double, 3>> coords(t.size());
  for (size_t i = 0; i < coords.size(); ++i) coords[i] = renderer_sample_coordinates(t, i);
  out.stored = array_from(shape, [&](size_t i) { return t.values[i]; });
  out.values = array_from(shape, [&](size_t i) { return renderer_sample_value(t, i, coords[i]); });
  out.errors = errors_of(t.errors, shape);
  for (size_t k = 0; k < t.axes.size(); ++k) {
    const WarpedAxis& a = t.axes[k];
    LoadedAxis la{a.name, a.size, a.warp.describe(), {}, {}};
    la.grid = array_from({a.size}, [&](size_t i) { return double(i) / double(a.size - 1); });
    la.coordinates = array_from(shape, [&](size_t i) { return coords[i][k]; });
    out.axes.push_back(std::move(la));
  }
  return out;
}

namespace {

// Tables and axes come from lut.load; the constructor says so (and gives the stubs a signature).
template <class T>
T not_constructed(const py::args&, const py::kwargs&) {
  throw py::type_error("dspbr.lut.Table and dspbr.lut.Axis come from dspbr.lut.load(path)");
}
constexpr const char* kInitDoc =
    "__init__(self, *args: typing.Any, **kwargs: typing.Any) -> None\n\nNot constructed: lut.load makes them.";

}  // namespace

void bind_lut_table(py::module_& lut) {
  py::class_<LoadedAxis>(lut, "Axis", "One axis of a loaded table (lut.load).")
      .def(py::init(&not_constructed<LoadedAxis>), kInitDoc)
      .def_readonly("name", &LoadedAxis::name, "(self) -> str\n\nThe physical coordinate: roughness, cos_theta, f0, alpha_b, ior, ior_x.")
      .def_readonly("size", &LoadedAxis::size, "(self) -> int\n\nNumber of samples.")
      .def_readonly("warp", &LoadedAxis::warp,
                    "(self) -> str\n\nPublished layout: the grid, 'cell' (x_i = (i + 0.5) / N) or 'endpoint' "
                    "(x_i = i / (N - 1)). Renderer layout: the warp from the coordinate to the grid coordinate "
                    "i / (N - 1), e.g. 'ggx_cos(p=0.5)' (docs/luts.md, \"Renderer layout\").")
      .def_readonly("grid", &LoadedAxis::grid,
                    "(self) -> numpy.typing.NDArray[numpy.float64]\n\n(size,) sample positions: the coordinates "
                    "(published layout) or the grid coordinates i / (N - 1) in [0, 1] (renderer layout).")
      .def_readonly("coordinates", &LoadedAxis::coordinates,
                    "(self) -> numpy.typing.NDArray[numpy.float64]\n\nThe physical coordinate of every sample (the "
                    "table's shape): a warp may depend on another axis (ggx_cos on alpha = roughness^2, glass_ior on "
                    "cos_theta). On an r = 0 row of the renderer layout (the limit r -> 0 at fixed cos / alpha) "
                    "cos_theta is that limit: 0 below the last sample.")
      .def("__repr__", [](const LoadedAxis& a) { return "<dspbr.lut.Axis " + a.name + " " + std::to_string(a.size) + " " + a.warp + ">"; },
           "__repr__(self) -> str");
  py::class_<LoadedTable>(lut, "Table", "One table of a table file, decoded (lut.load; docs/luts.md).")
      .def(py::init(&not_constructed<LoadedTable>), kInitDoc)
      .def_readonly("name", &LoadedTable::name, "(self) -> str\n\nThe table's name (lut.names()).")
      .def_readonly("layout", &LoadedTable::layout, "(self) -> str\n\n'published' or 'renderer'.")
      .def_readonly("encoding", &LoadedTable::encoding,
                    "(self) -> str\n\nWhat `stored` holds: 'value' (the quantity), 'log_one_minus' (ln(1 - quantity)) "
                    "or 'beta_minus_mirror' (GGX_beta: beta - (1 - cos_theta)^5).")
      .def_readonly("values", &LoadedTable::values,
                    "(self) -> numpy.typing.NDArray[numpy.float64]\n\nThe quantity at every sample (stored values "
                    "decoded at the sample's coordinates), shape = the axes' sizes, slowest first.")
      .def_readonly("stored", &LoadedTable::stored,
                    "(self) -> numpy.typing.NDArray[numpy.float64]\n\nThe values as the file stores them (what a "
                    "renderer uploads and interpolates).")
      .def_readonly("errors", &LoadedTable::errors,
                    "(self) -> typing.Optional[numpy.typing.NDArray[numpy.float64]]\n\nPer-sample standard error "
                    "of the quantity as the file states it, or None.")
      .def_readonly("axes", &LoadedTable::axes, "(self) -> list[Axis]\n\nThe axes, slowest first.")
      .def("__repr__", [](const LoadedTable& t) {
             std::string s = "<dspbr.lut.Table " + t.name + " (" + t.layout + ")";
             for (const LoadedAxis& a : t.axes) s += " " + a.name + "[" + std::to_string(a.size) + "]";
             return s + ">";
           },
           "__repr__(self) -> str");
}

}  // namespace dspbr::python
