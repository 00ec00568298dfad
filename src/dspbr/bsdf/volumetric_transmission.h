// Volumetric microfacet transmission (Walter et al. 2007, spec "Microfacet BSDF"):
//   M_t = |l.h_t| |v.h_t| / (|l.n| |v.n|) * eta_o^2 D(h_t) G(v, l, h_t) / (eta_i (v.h_t) + eta_o (l.h_t))^2
//   h_t = -(eta_i v + eta_o l) / |...| (oriented to the upper hemisphere),
// times a colour factor of cos theta_t = v.h_t (e.g. rho_t (1 - s F_d(F_0 rho_s, 1)) in
// VolumetricCore). eta_i is the IOR on v's side, eta_o on l's side (the spec: "current medium" and
// "the other side"). With the eta_o^2 of the spec, the lobe's albedo at small roughness is the
// factor itself (no (eta_i/eta_o)^2 radiance scaling): generalized reciprocity reads
// f(v, l) / eta_o^2 = f(l, v) / eta_i^2. See docs/bsdf.md.
//
// Smooth limit (an effectively smooth distribution, ggx.h) or index-matched media (|eta_i/eta_o - 1| < kIndexMatched):
// a Dirac along the refracted direction (l = -v when index-matched), weight factor(v.z).
// Under total internal reflection at the sampled microfacet the sample fails (valid = false).
#pragma once
#include "dspbr/bsdf/microfacet_reflection.h"
#include "dspbr/fresnel.h"

namespace dspbr {

class VolumetricTransmission final : public Lobe {
 public:
  VolumetricTransmission(double alpha_u, double alpha_v, double eta_i, double eta_o, CosineFactor factor);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override;
  double sampling_weight(const Vec3& v) const override;
  bool is_delta() const override { return delta_; }
  // The conformance diagnosis's mistakes (lobe_assembly.h, Deviation): GgxDistribution's grazing
  // guard, and the factor read at v.n instead of v.h.
  void set_grazing_guard(double cos_theta) { ggx_.set_grazing_guard(cos_theta); }
  void set_factor_at_macro_normal(bool macro) { factor_at_macro_normal_ = macro; }

 private:
  // h_t for (v, l), oriented to +z; false when undefined or not a refraction configuration.
  bool half_vector(const Vec3& v, const Vec3& l, Vec3& h) const;
  GgxDistribution ggx_;
  double eta_i_, eta_o_;
  bool delta_;
  CosineFactor factor_;
  bool factor_at_macro_normal_ = false;
};

}  // namespace dspbr
