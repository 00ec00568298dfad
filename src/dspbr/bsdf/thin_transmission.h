// Thin-walled microfacet transmission: the reflection lobe mirrored to the lower hemisphere,
// rho M_r(v, l', h_r') (1 - s F(cos theta_r')) with l' = l + 2 n (-l.n) (spec "Dielectric BSDF for
// Transparent Surfaces", thin-walled). `factor` is the colour factor of cos theta_r' = v.h_r'
// (e.g. rho_t (1 - s F(F_0 rho_s, 1)) in ThinCore).
// Smooth limit (max alpha < kDeltaAlpha): a Dirac straight through, l = -v, weight factor(v.z).
#pragma once
#include "dspbr/bsdf/microfacet_reflection.h"

namespace dspbr {

class ThinTransmission : public Lobe {
 public:
  ThinTransmission(double alpha_u, double alpha_v, CosineFactor factor);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  // Density of l = flip(l'), l' from the reflection lobe's sampler: pdf_r(v, flip(l)).
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override;
  double sampling_weight(const Vec3& v) const override;
  bool is_delta() const override { return reflection_.is_delta(); }
  void set_grazing_guard(double cos_theta) { reflection_.set_grazing_guard(cos_theta); }  // GgxDistribution's

 private:
  MicrofacetReflection reflection_;  // M_r with the transmission factor as its "Fresnel"
};

}  // namespace dspbr
