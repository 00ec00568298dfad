// The thin-film reflectance R(cos theta) of one material's film over one base, tabulated once when
// the lobes are built (spec "Thin Film"; the film and the base do not depend on the angle), so
// that the lobes read R by a spline lookup instead of an Airy/Fourier evaluation per call.
//
// Layout: n cells uniform in t, cos theta = 2 t^2 / (1 + t) (t = (c + sqrt(c^2 + 8 c)) / 4):
// nodes gather towards grazing incidence, where R rises to 1 on a scale that shrinks as the base
// reflects more (|r12 r23| -> 1), while the rate at normal incidence, where the interference
// fringes are densest in cos theta, stays 1.5. Values: the unclamped linear sRGB of the Fourier
// evaluation (thin_film.h) at the nodes, interpolated by a not-a-knot cubic spline per channel
// (cubic_spline.h), then clamped to [0, 1] like thin_film_reflectance.
//
// Accuracy: n is the smallest of 16, 32, ..., 256 at which the spline matches the Fourier
// evaluation to kThinFilmTableTolerance at every cell midpoint (the midpoints are the next
// level's nodes); cells still beyond it at n = 256, and always the grazing cell 0, evaluate R
// directly. Measured against the reference quadrature: docs/components.md.
#pragma once
#include <cstdint>
#include <vector>

#include "dspbr/vec3.h"

namespace dspbr {

// Largest difference per channel between the spline and the Fourier evaluation at a cell midpoint.
constexpr double kThinFilmTableTolerance = 1e-4;

class ThinFilmTable {
 public:
  // R(., eta_base, thickness_um, eta_film) over cos theta in [0, 1]; the arguments as for
  // thin_film_reflectance (std::invalid_argument outside its domain).
  ThinFilmTable(double eta_base, double thickness_um, double eta_film);

  // R(cos theta) as linear sRGB in [0, 1] (|cos| is used, like thin_film_reflectance).
  Rgb operator()(double cos_theta) const;

  double eta_base() const { return eta_base_; }
  int cells() const { return n_; }                  // 0: no table (the film vanishes or the base is a mirror)
  int direct_cells() const;                         // cells evaluated directly (grazing cell included)

 private:
  double eta_base_, thickness_um_, eta_film_;
  int n_ = 0;
  std::vector<double> cubic_;     // cell i, channel k: cubic_[12 i + 4 k .. + 3] (cubic_spline.h)
  std::vector<uint8_t> direct_;   // cell i evaluated directly
};

}  // namespace dspbr
