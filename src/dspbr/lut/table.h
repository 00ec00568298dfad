// A dense table on a regular grid: 1 to 3 axes, slowest to fastest, each axis cell-centred
// (x_i = lo + (i + 0.5)/N (hi - lo)) or endpoint (x_i = lo + i/(N-1) (hi - lo)).
#pragma once
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace dspbr {

enum class GridKind { CellCentred, Endpoint };
const char* grid_kind_name(GridKind k);  // "cell" / "endpoint"
// "cell" / "endpoint" -> GridKind; throws std::invalid_argument "'<name>' is not cell or endpoint".
GridKind parse_grid_kind(const std::string& name);

struct Axis {
  std::string name;  // e.g. "roughness", "cos_theta", "f0", "alpha_b"
  int size = 0;
  double lo = 0, hi = 1;
  GridKind kind = GridKind::CellCentred;
  double coord(int i) const;          // position of sample i
  double index(double x) const;       // continuous index of position x (inverse of coord)
};

struct Table {
  std::string name;             // e.g. "GGX_E"
  std::vector<Axis> axes;       // slowest -> fastest
  std::vector<double> values;   // row-major, fastest axis contiguous
  std::vector<double> errors;   // per-cell standard error estimate (same layout), may be empty

  size_t size() const;
  size_t offset(const std::vector<int>& idx) const;
  double at(const std::vector<int>& idx) const { return values[offset(idx)]; }
  // Multilinear interpolation at a position (one coordinate per axis, slowest first),
  // clamped to the outermost samples (no extrapolation), as a GPU texture with clamp-to-edge.
  double lookup(const std::vector<double>& x) const;
  // The same without allocating (a braced list of coordinates picks this overload).
  double lookup(std::initializer_list<double> x) const { return lookup(x.begin(), x.size()); }
  double lookup(const double* x, size_t rank) const;
};

}  // namespace dspbr
