#include "dspbr/tables/table.h"

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

double Table::lookup(const double* x, size_t x_rank) const {
  const size_t rank = axes.size();
  if (x_rank != rank || rank > 3) throw std::invalid_argument("Table::lookup: wrong coordinate rank for " + name);
  if (rank == 2) return lookup_2d(x[0], x[1]);  // its own rank check passes
  int i0[3] = {0, 0, 0};
  double f[3] = {0, 0, 0};
  for (size_t d = 0; d < rank; ++d) axes[d].locate(x[d], i0[d], f[d]);
  double result = 0;
  for (int corner = 0; corner < (1 << rank); ++corner) {
    double w = 1;
    size_t o = 0;
    for (size_t d = 0; d < rank; ++d) {
      const int bit = (corner >> d) & 1;
      w *= bit ? f[d] : 1.0 - f[d];
      o = o * size_t(axes[d].size) + size_t(std::min(i0[d] + bit, axes[d].size - 1));
    }
    result += w * values[o];  // +0 for a zero weight (finite values)
  }
  return result;
}

}  // namespace dspbr
