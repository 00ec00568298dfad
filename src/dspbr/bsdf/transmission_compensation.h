// Energy compensation of the transparent core (beyond DSPBR 2025x, whose spec leaves it to "a
// future revision"; docs/bsdf.md, "Transmission compensation"). A separable lobe in the spirit of
// the multiple-scattering lobe of Kulla & Conty 2017 ("Revisiting physically based shading at
// Imageworks", dielectrics), towards the same hemisphere (reflection) or the other (transmission):
//   f(v, l) = c (1 - E_v(|v.n|)) (1 - E_l(|l.n|)) / (pi (1 - E_l,avg))
// with E_v the albedo of the uncompensated core on v's side, E_l the one on l's side (the same
// function for reflection and thin-walled transmission; the other side's for volumetric
// transmission), E_l,avg = 2 Integral E_l mu dmu. Its directional albedo is c (1 - E_v(v.n))
// exactly. Cosine-weighted sampling of l in the lobe's hemisphere.
#pragma once
#include <optional>

#include "dspbr/bsdf/lobe.h"
#include "dspbr/tables/albedo_slice.h"

namespace dspbr {

// The albedo of the uncompensated white core (specular 1) on one side, cut from the tables at the
// material's roughness (and ior) when the lobe is built (docs/bsdf.md):
//   E(mu) = E_g(mu) + F_ms (1 - E_m(mu)),  E_g = E_m thin-walled (no glass slice), else the glass
// albedo of that side; F_ms (1 - E_m) is the albedo of the spec's M_r,ms F_ms (closed form).
struct CoreAlbedo {
  AlbedoSlice e_m;                  // E_m(mu; r_uv)
  std::optional<AlbedoSlice> glass;  // E_g(mu; r_uv, ior) of the side (volumetric)
  double f_ms = 0;                   // F_ms(F_0, 1; E_m,avg)
  // E(mu), the E_m part through the mixture's per-call memo (bsdf/lobe_cache.h).
  double operator()(double cos_theta, LobeCache& cache) const;
};

class TransmissionCompensation : public Lobe {
 public:
  using Lobe::eval;
  using Lobe::sampling_weight;
  // transmission: l in the lower hemisphere; c: colour (split fraction times tint); e_l_avg: the
  // cosine average of e_l. The lobe is zero when 1 - e_l_avg < kMinMissingEnergy (multiscatter.h).
  TransmissionCompensation(bool transmission, const Rgb& c, CoreAlbedo e_v, CoreAlbedo e_l, double e_l_avg);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  Rgb eval(const Vec3& v, const Vec3& l, LobeCache& cache) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override;
  double sampling_weight(const Vec3& v) const override;
  double sampling_weight(const Vec3& v, LobeCache& cache) const override;

 private:
  // 1 - E, clamped to [0, 1], on v's side and on l's side.
  double missing_v(double c, LobeCache& cache) const;
  double missing_l(double c, LobeCache& cache) const;
  bool transmission_;
  Rgb c_;
  CoreAlbedo e_v_, e_l_;
  double inv_norm_;  // 1 / (pi (1 - E_l,avg)), 0 when nothing is missing
};

}  // namespace dspbr
