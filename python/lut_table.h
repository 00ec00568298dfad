// dspbr.lut.Table / dspbr.lut.Axis (lut_table.cpp): a table file's table decoded, as lut.load
// returns it.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "dspbr/tables/table.h"
#include "dspbr/tables/warped_table.h"

namespace dspbr::python {

struct LoadedAxis {
  std::string name;
  int size;
  std::string warp;                  // "cell" / "endpoint" (published) or the warp (renderer)
  pybind11::array_t<double> grid;         // (size,) sample positions on the (grid) axis
  pybind11::array_t<double> coordinates;  // the table's shape: physical coordinate per sample
};

struct LoadedTable {
  std::string name, layout, encoding;
  pybind11::array_t<double> values, stored;  // decoded quantity, stored values
  pybind11::object errors;                   // array or None
  std::vector<LoadedAxis> axes;
};

LoadedTable loaded_table(const Table& t);        // published layout
LoadedTable loaded_table(const WarpedTable& t);  // renderer layout
void bind_lut_table(pybind11::module_& lut);

}  // namespace dspbr::python
