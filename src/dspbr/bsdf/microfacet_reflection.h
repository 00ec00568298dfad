// Microfacet reflection lobe M_r(v, l, h_r; r_u, r_v) F(cos theta_r) (spec "Microfacet BSDF"):
// anisotropic GGX, height-correlated Smith G, visible-normal sampling (Heitz 2018). The Fresnel
// factor is any colour function of cos theta_r = v.h_r, so the same lobe serves the metal, the
// merged core Fresnel F(rho_s,r,0, rho_s,r,90), the thin-film R, and the clearcoat c F_c.
//
// Perfectly smooth limit: when max(alpha_u, alpha_v) < kDeltaAlpha the lobe is a mirror (Dirac):
// eval = pdf = 0 and sample returns l = (-v.x, -v.y, v.z) with weight F(v.z), flags Delta.
#pragma once
#include "dspbr/bsdf/lobe.h"

namespace dspbr {

// alpha below which a GGX lobe is treated as a Dirac: roughness < 1e-5. At smaller alpha the
// double-precision half vector (error ~1e-16) is no longer small against the lobe width, so
// eval and pdf of a sampled direction would not agree to 1e-4.
constexpr double kDeltaAlpha = 1e-10;
// Smallest alpha of a non-delta lobe's minor axis (anisotropy = 1 gives r_v = 0): clamped up to
// kDeltaAlpha, so that D stays finite.
constexpr double kMinAlpha = kDeltaAlpha;

class MicrofacetReflection : public Lobe {
 public:
  MicrofacetReflection(double alpha_u, double alpha_v, CosineFactor fresnel);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override;
  double sampling_weight(const Vec3& v) const override;
  bool is_delta() const override { return delta_; }
  double alpha_u() const { return au_; }
  double alpha_v() const { return av_; }

 private:
  double au_, av_;
  bool delta_;
  CosineFactor fresnel_;
};

}  // namespace dspbr
