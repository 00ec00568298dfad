// Microfacet reflection lobe M_r(v, l, h_r; r_u, r_v) F(cos theta_r) (spec "Microfacet BSDF"):
// anisotropic GGX, height-correlated Smith G, visible-normal sampling (Heitz 2018). The Fresnel
// factor is any colour function of cos theta_r = v.h_r, so the same lobe serves the metal, the
// merged core Fresnel F(rho_s,r,0, rho_s,r,90), the thin-film R, and the clearcoat c F_c.
//
// Perfectly smooth limit: when the distribution is effectively smooth (max(alpha_u, alpha_v) <
// kDeltaAlpha, ggx.h) the lobe is a mirror (Dirac):
// eval = pdf = 0 and sample returns l = (-v.x, -v.y, v.z) with weight F(v.z), flags Delta.
#pragma once
#include "dspbr/bsdf/lobe.h"
#include "dspbr/ggx.h"

namespace dspbr {

class MicrofacetReflection final : public Lobe {
 public:
  MicrofacetReflection(double alpha_u, double alpha_v, CosineFactor fresnel);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override;
  double sampling_weight(const Vec3& v) const override;
  bool is_delta() const override { return delta_; }
  const GgxDistribution& distribution() const { return ggx_; }
  void set_grazing_guard(double cos_theta) { ggx_.set_grazing_guard(cos_theta); }  // GgxDistribution's

 private:
  GgxDistribution ggx_;
  bool delta_;
  CosineFactor fresnel_;
};

// Inline: the mixture calls it directly for the core's reflection (bsdf/lobe_mixture.h).
inline Rgb MicrofacetReflection::eval(const Vec3& v, const Vec3& l) const {
  if (delta_ || v.z <= 0 || l.z <= 0) return Rgb(0);
  const Vec3 h = normalize(v + l);
  // M_r = D G / (4 |v.n| |l.n|) times the Fresnel factor at cos theta_r = v.h_r.
  return fresnel_(dot(v, h)) * ggx_.M_r(v, l, h);
}

}  // namespace dspbr
