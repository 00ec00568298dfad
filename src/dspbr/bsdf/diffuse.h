// Diffuse base of the opaque dielectric (spec "Diffuse BRDF", eq. "diffuse" and "b_c"), weighted as in
// ThinCore / VolumetricCore:
//   rho_d [ B_u (1 - s) + s B_c(F_0 rho_s) ]
//   B_u = T(v, l; l) / pi
//   B_c = (1 - E(v.n; r_uv, f0_max)) (1 - E(l.n; r_uv, f0_max)) / (pi (1 - E_avg(r_uv, f0_max))) T(v, l; l)
//   T   = 1 - l when v and l are on the same side, l (translucency) otherwise.
// With a thin film of weight i (ThinFilmOver* equations) the base becomes
//   rho_d { (1 - i) [B_u (1 - s) + s B_c] + i B_u (1 - max(R(v.n), R(l.n))) }.
// Sampling: cosine-weighted, upper hemisphere with probability 1 - l, lower with probability l.
#pragma once
#include "dspbr/bsdf/lobe.h"
#include "dspbr/tables/albedo_slice.h"

namespace dspbr {

struct DiffuseParams {
  Rgb rho_d{1, 1, 1};          // rho_d of ThinCore (colour and layer weight)
  double specular = 1;         // s
  double translucency = 0;     // l
  double f0_max = 0.04;        // max of F_0 rho_s (table coordinate of E, E_avg)
  double r_uv = 0;             // sqrt(r_u r_v)
  double film_weight = 0;      // i
  FilmLayer film;              // the film (only read when film_weight > 0)
  double film_eta_base = 1.5;  // the base IOR under the film: R(cos) = film.reflectance(cos, film_eta_base)
};

class DiffuseBase final : public Lobe {
 public:
  DiffuseBase(const DiffuseParams& p, const LutSet& luts);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  Rgb eval(const Vec3& v, const Vec3& l, LobeCache& cache) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override;
  double sampling_weight(const Vec3& v) const override;
  double sampling_weight(const Vec3& v, LobeCache& cache) const override;

 private:
  double missing(double cos_theta, LobeCache& cache) const;  // 1 - E(|cos|; r_uv, f0_max), clamped to [0, 1]
  DiffuseParams p_;
  AlbedoSlice e_base_;  // E(mu; r_uv, f0_max)
  double inv_norm_;  // 1 / (pi (1 - E_avg)); 0 when no energy is left for the base
};

}  // namespace dspbr
