// Multiple-scattering compensation lobe M_r,ms(v, l; r_u, r_v) F_ms (spec eq. "multiscatter",
// Kulla & Conty 2017):
//   M_r,ms = (1 - E_m(v.n; r_uv)) (1 - E_m(l.n; r_uv)) / (pi (1 - E_m,avg(r_uv))),  r_uv = sqrt(r_u r_v)
// times a colour F_ms (computed by the caller with fresnel_ms). Cosine-weighted sampling.
// Its directional albedo is (1 - E_m(v.n)) F_ms exactly (2 pi Integral (1 - E_m) mu dmu = pi (1 - E_m,avg)).
#pragma once
#include <algorithm>

#include "dspbr/bsdf/lobe.h"
#include "dspbr/bsdf/lobe_cache.h"
#include "dspbr/tables/albedo_slice.h"

namespace dspbr {

// 1 - E_m,avg below which the compensation is zero (mirror limit r_uv -> 0, where numerator and
// denominator both vanish: the single-scattering lobe already reflects everything).
constexpr double kMinMissingEnergy = 1e-9;

class MultiScatterReflection final : public Lobe {
 public:
  // r_uv: isotropic roughness sqrt(r_u r_v) (table coordinate); f_ms: the F_ms colour.
  MultiScatterReflection(double r_uv, const Rgb& f_ms, const LutSet& luts);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  Rgb eval(const Vec3& v, const Vec3& l, LobeCache& cache) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override { return kLobeReflection | kLobeDiffuse; }
  double sampling_weight(const Vec3& v) const override;
  double sampling_weight(const Vec3& v, LobeCache& cache) const override;
  // 1 - E_m(cos; r_uv), clamped to [0, 1] (table noise can put E_m a hair above 1).
  double missing(double cos_theta) const;
  double missing(double cos_theta, LobeCache& cache) const;

 private:
  Rgb f_ms_;
  AlbedoSlice e_m_;  // E_m(mu; r_uv)
  double inv_norm_;  // 1 / (pi (1 - E_m,avg)), 0 in the mirror limit
};

// Inline: the mixture calls them directly for the core's compensation (bsdf/lobe_mixture.h).
inline double MultiScatterReflection::missing(double cos_theta, LobeCache& cache) const {
  return missing_energy(cache.albedo(e_m_, std::abs(cos_theta)));
}

inline Rgb MultiScatterReflection::eval(const Vec3& v, const Vec3& l, LobeCache& cache) const {
  if (v.z <= 0 || l.z <= 0 || inv_norm_ == 0) return Rgb(0);
  double e[2];
  cache.albedos(e_m_, v.z, l.z, e);
  return f_ms_ * (missing_energy(e[0]) * missing_energy(e[1]) * inv_norm_);
}

}  // namespace dspbr
