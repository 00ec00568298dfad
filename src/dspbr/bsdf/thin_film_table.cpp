#include "dspbr/bsdf/thin_film_table.h"

#include <algorithm>
#include <cmath>

#include "dspbr/bsdf/thin_film.h"
#include "dspbr/cubic_spline.h"

namespace dspbr {

namespace {

constexpr int kMinCells = 16, kMaxCells = 256;

double cos_of_t(double t) { return 2.0 * t * t / (1.0 + t); }
double t_of_cos(double c) { return 0.25 * (c + std::sqrt(c * (c + 8.0))); }

// The unclamped linear sRGB that thin_film_reflectance clamps.
Rgb unclamped(double c, double eta_base, double thickness_um, double eta_film) {
  return thin_film_xyz_to_linear_srgb(
      thin_film_reflectance_xyz(c, eta_base, thickness_um, eta_film, ThinFilmIntegration::Fourier));
}

}  // namespace

ThinFilmTable::ThinFilmTable(double eta_base, double thickness_um, double eta_film)
    : eta_base_(eta_base), thickness_um_(thickness_um), eta_film_(eta_film) {
  thin_film_reflectance(1.0, eta_base, thickness_um, eta_film);  // validates the arguments
  // The film vanishes optically or the base is a perfect mirror: exact closed forms, no table.
  if (std::isinf(eta_base) || thickness_um <= 0.0 || eta_film == 1.0) return;
  std::vector<Rgb> node(size_t(kMinCells) + 1);
  for (int i = 0; i <= kMinCells; ++i) node[size_t(i)] = unclamped(cos_of_t(double(i) / kMinCells), eta_base, thickness_um, eta_film);
  for (int n = kMinCells;; n *= 2) {
    std::vector<double> coef[3];
    for (int k = 0; k < 3; ++k) {
      std::vector<double> y(size_t(n) + 1);
      for (int i = 0; i <= n; ++i) y[size_t(i)] = node[size_t(i)][k];
      coef[k] = not_a_knot_cubics(y);
    }
    // The midpoints: the check of this level and the new nodes of the next.
    std::vector<Rgb> mid(static_cast<size_t>(n));
    std::vector<uint8_t> bad(static_cast<size_t>(n), 0);
    bool all_good = true;
    for (int i = 0; i < n; ++i) {
      mid[size_t(i)] = unclamped(cos_of_t((i + 0.5) / n), eta_base, thickness_um, eta_film);
      if (i == 0) continue;  // the grazing cell is evaluated directly
      for (int k = 0; k < 3; ++k)
        if (!(std::abs(cubic_at(&coef[k][4 * size_t(i)], 0.5) - mid[size_t(i)][k]) <= kThinFilmTableTolerance)) bad[size_t(i)] = 1;
      all_good = all_good && !bad[size_t(i)];
    }
    if (all_good || n == kMaxCells) {
      n_ = n;
      cubic_.resize(12 * size_t(n));
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) std::copy_n(&coef[k][4 * size_t(i)], 4, &cubic_[12 * size_t(i) + 4 * size_t(k)]);
      direct_ = bad;
      direct_[0] = 1;
      return;
    }
    std::vector<Rgb> next(2 * size_t(n) + 1);
    for (int i = 0; i < n; ++i) next[2 * size_t(i)] = node[size_t(i)], next[2 * size_t(i) + 1] = mid[size_t(i)];
    next[2 * size_t(n)] = node[size_t(n)];
    node = std::move(next);
  }
}

int ThinFilmTable::direct_cells() const { return int(std::count(direct_.begin(), direct_.end(), uint8_t(1))); }

Rgb ThinFilmTable::operator()(double cos_theta) const {
  const double c = std::min(1.0, std::abs(cos_theta));
  if (n_ == 0) return thin_film_reflectance(c, eta_base_, thickness_um_, eta_film_);
  const double g = t_of_cos(c) * n_;
  const int i = std::min(n_ - 1, int(g));
  if (direct_[size_t(i)]) return thin_film_reflectance(c, eta_base_, thickness_um_, eta_film_);
  const double f = g - i;
  const double* q = &cubic_[12 * size_t(i)];
  return {std::clamp(cubic_at(q, f), 0.0, 1.0), std::clamp(cubic_at(q + 4, f), 0.0, 1.0),
          std::clamp(cubic_at(q + 8, f), 0.0, 1.0)};
}

}  // namespace dspbr
