#include "dspbr/lut/table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dspbr {

const char* grid_kind_name(GridKind k) { return k == GridKind::CellCentred ? "cell" : "endpoint"; }

GridKind parse_grid_kind(const std::string& name) {
  if (name == "cell") return GridKind::CellCentred;
  if (name == "endpoint") return GridKind::Endpoint;
  throw std::invalid_argument("'" + name + "' is not cell or endpoint");
}

double Axis::coord(int i) const {
  if (kind == GridKind::CellCentred) return lo + (i + 0.5) / size * (hi - lo);
  return size > 1 ? lo + double(i) / (size - 1) * (hi - lo) : 0.5 * (lo + hi);
}

size_t Table::size() const {
  size_t n = 1;
  for (const Axis& a : axes) n *= size_t(a.size);
  return n;
}

size_t Table::offset(const std::vector<int>& idx) const {
  if (idx.size() != axes.size()) throw std::invalid_argument("Table::offset: wrong index rank for " + name);
  size_t o = 0;
  for (size_t d = 0; d < axes.size(); ++d) o = o * size_t(axes[d].size) + size_t(idx[d]);
  return o;
}

double Table::lookup(const std::vector<double>& x) const { return lookup(x.data(), x.size()); }

double Axis::index(double x) const {
  // On a unit axis (lo = 0, hi = 1: every published table) t is x itself: (x - 0) / 1 == x
  // exactly, without the division.
  const double t = lo == 0 && hi == 1 ? x : (x - lo) / (hi - lo);
  return kind == GridKind::CellCentred ? t * size - 0.5 : t * (size - 1);
}

namespace {

// Cell index i in [0, max(0, n - 2)] and fraction f of position x on an axis, clamped to the
// outermost samples (clamp-to-edge).
inline void locate(const Axis& a, double x, int& i, double& f) {
  const int n = a.size;
  const double u = a.index(x);
  const double c = u > 0.0 ? std::min(u, double(n - 1)) : 0.0;  // NaN -> 0
  i = std::min(int(c), std::max(0, n - 2));  // c >= 0: truncation is floor
  f = n > 1 ? c - i : 0.0;
}

}  // namespace

double Table::lookup(const double* x, size_t x_rank) const {
  const size_t rank = axes.size();
  if (x_rank != rank || rank > 3) throw std::invalid_argument("Table::lookup: wrong coordinate rank for " + name);
  const Axis* ax = axes.data();
  const double* v = values.data();
  if (rank == 2) {
    // The corner loop below written out for two axes (same products and order).
    int i0, i1;
    double f0, f1;
    locate(ax[0], x[0], i0, f0);
    locate(ax[1], x[1], i1, f1);
    const size_t n1 = size_t(ax[1].size);
    const size_t r0 = size_t(i0) * n1, r1 = size_t(std::min(i0 + 1, ax[0].size - 1)) * n1;
    const size_t c0 = size_t(i1), c1 = size_t(std::min(i1 + 1, ax[1].size - 1));
    const double w00 = (1.0 - f0) * (1.0 - f1), w10 = f0 * (1.0 - f1);
    const double w01 = (1.0 - f0) * f1, w11 = f0 * f1;
    // Zero weights add +0 (the values are finite): no branches, the same sum as the loop below.
    return ((w00 * v[r0 + c0] + w10 * v[r1 + c0]) + w01 * v[r0 + c1]) + w11 * v[r1 + c1];
  }
  int i0[3] = {0, 0, 0};
  double f[3] = {0, 0, 0};
  for (size_t d = 0; d < rank; ++d) locate(ax[d], x[d], i0[d], f[d]);
  double result = 0;
  for (int corner = 0; corner < (1 << rank); ++corner) {
    double w = 1;
    size_t o = 0;
    for (size_t d = 0; d < rank; ++d) {
      const int bit = (corner >> d) & 1;
      w *= bit ? f[d] : 1.0 - f[d];
      o = o * size_t(axes[d].size) + size_t(std::min(i0[d] + bit, axes[d].size - 1));
    }
    result += w * v[o];  // +0 for a zero weight (finite values)
  }
  return result;
}

}  // namespace dspbr
