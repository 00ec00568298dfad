// A dense table on a regular grid: 1 to 3 axes, slowest to fastest, each axis cell-centred
// (x_i = lo + (i + 0.5)/N (hi - lo)) or endpoint (x_i = lo + i/(N-1) (hi - lo)).
#pragma once
#include <algorithm>
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
  double index(double x) const {      // continuous index of position x (inverse of coord)
    // On a unit axis (lo = 0, hi = 1: every published table) t is x itself: (x - 0) / 1 == x
    // exactly, without the division.
    const double t = lo == 0 && hi == 1 ? x : (x - lo) / (hi - lo);
    return kind == GridKind::CellCentred ? t * size - 0.5 : t * (size - 1);
  }
  // Cell index i in [0, max(0, size - 2)] and fraction f of position x, clamped to the outermost
  // samples (clamp-to-edge).
  void locate(double x, int& i, double& f) const {
    const double u = index(x);
    const double c = u > 0.0 ? std::min(u, double(size - 1)) : 0.0;  // NaN -> 0
    i = std::min(int(c), std::max(0, size - 2));  // c >= 0: truncation is floor
    f = size > 1 ? c - i : 0.0;
  }
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
  // The same at two coordinates, inline: the published layout's E_m and E_sheen lookups
  // (another rank throws as lookup does).
  double lookup_2d(double x0, double x1) const {
    if (axes.size() != 2) return lookup({x0, x1});
    int i0, i1;
    double f0, f1;
    axes[0].locate(x0, i0, f0);
    axes[1].locate(x1, i1, f1);
    const double* v = values.data();
    const size_t n1 = size_t(axes[1].size);
    const size_t r0 = size_t(i0) * n1, r1 = size_t(std::min(i0 + 1, axes[0].size - 1)) * n1;
    const size_t c0 = size_t(i1), c1 = size_t(std::min(i1 + 1, axes[1].size - 1));
    const double w00 = (1.0 - f0) * (1.0 - f1), w10 = f0 * (1.0 - f1);
    const double w01 = (1.0 - f0) * f1, w11 = f0 * f1;
    // Zero weights add +0 (the values are finite): no branches, the same sum as lookup's corner
    // loop.
    return ((w00 * v[r0 + c0] + w10 * v[r1 + c0]) + w01 * v[r0 + c1]) + w11 * v[r1 + c1];
  }
};

}  // namespace dspbr
