// Anisotropic GGX (Trowbridge-Reitz, GTR gamma = 2) microfacet distribution and its
// height-correlated Smith shadowing-masking, as one small value type in the shape of pbrt-v4's
// TrowbridgeReitzDistribution. Spec "Microfacet BSDF"; Heitz 2014 ("Understanding the
// Masking-Shadowing Function in Microfacet-Based BRDFs"), Heitz 2018 ("Sampling the GGX
// Distribution of Visible Normals"). All directions are unit vectors in the local shading frame
// (t = +x, b = +y, n = +z); the names are those of the papers: D(w_m), Lambda(w), G1(w), G2(w_o, w_i),
// the visible normals D_w(w_m) = D(w, w_m).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include "dspbr/constants.h"
#include "dspbr/vec3.h"

namespace dspbr {

// User roughness r to GGX alpha: the spec squares roughness ("perceptually linear").
inline double roughness_to_alpha(double r) { return r * r; }

// Anisotropic roughness from isotropic roughness r and anisotropy o: (r_u, r_v) = r (1, 1 - o).
struct Roughness2 { double u, v; };
inline Roughness2 anisotropic_roughness(double r, double o) { return {r, r * (1.0 - o)}; }

// alpha below which a GGX distribution is effectively smooth (a mirror, Dirac lobes): roughness
// < 1e-5. At smaller alpha the double-precision half vector (error ~1e-16) is no longer small
// against the lobe width, so eval and pdf of a sampled direction would not agree to 1e-4.
constexpr double kDeltaAlpha = 1e-10;
// Smallest alpha of a rough distribution's axes: anisotropy 1 gives r_v = 0, clamped up to this so
// that D stays finite.
constexpr double kMinAlpha = kDeltaAlpha;

class GgxDistribution {
 public:
  // The one clamp: a distribution is effectively smooth when max(alpha_u, alpha_v) < kDeltaAlpha,
  // and then keeps its alphas as given (0 is the mirror: Lambda = 0, G1 = G2 = 1, Sample_wm = +z);
  // otherwise each alpha is raised to at least kMinAlpha. D and D(w, w_m) need a rough
  // distribution (they divide by alpha); Lambda, G1, G2 and Sample_wm take either.
  GgxDistribution() = default;
  GgxDistribution(double alpha_u, double alpha_v)
      : smooth_(std::max(alpha_u, alpha_v) < kDeltaAlpha),
        au_(smooth_ ? alpha_u : std::max(alpha_u, kMinAlpha)),
        av_(smooth_ ? alpha_v : std::max(alpha_v, kMinAlpha)) {}

  // The conformance diagnosis's Deviation::LambdaZeroAtGrazing (bsdf/lobe_assembly.h): Lambda = 0
  // where |w.n| < cos_theta (0, the default: never).
  void set_grazing_guard(double cos_theta) { grazing_guard_ = cos_theta; }

  double alpha_u() const { return au_; }
  double alpha_v() const { return av_; }
  // A mirror: the lobes built on it are Dirac (eval = pdf = 0, sample along the mirror direction).
  bool effectively_smooth() const { return smooth_; }

  // D(w_m) = chi+(w_m.n) / (pi a_u a_v ((w_m.t/a_u)^2 + (w_m.b/a_v)^2 + (w_m.n)^2)^2) (spec "Microfacet BSDF").
  double D(const Vec3& wm) const {
    if (wm.z <= 0) return 0.0;
    const double x = wm.x / au_, y = wm.y / av_;
    const double denom = x * x + y * y + wm.z * wm.z;
    return 1.0 / (kPi * au_ * av_ * denom * denom);
  }

  // Smith Lambda(w) = (-1 + sqrt(1 + 1/a^2)) / 2, 1/a^2 = ((w.t a_u)^2 + (w.b a_v)^2) / (w.n)^2
  // (Heitz 2014, GGX with the anisotropic alpha along w's azimuth). +inf at w.n = 0 (grazing).
  double Lambda(const Vec3& w) const {
    if (std::abs(w.z) < grazing_guard_) return 0.0;
    const double cos2 = w.z * w.z;
    const double tan2_alpha2 = w.x * w.x * au_ * au_ + w.y * w.y * av_ * av_;
    if (tan2_alpha2 == 0) return 0.0;  // normal incidence or alpha = 0: no masking
    if (cos2 == 0) return std::numeric_limits<double>::infinity();
    const double inv_a2 = tan2_alpha2 / cos2;
    // (-1 + sqrt(1 + x)) / 2 written x / (2 (1 + sqrt(1 + x))): no cancellation at small x.
    return inv_a2 / (2.0 * (1.0 + std::sqrt(1.0 + inv_a2)));
  }

  // Smith masking G1(w) = 1 / (1 + Lambda(w)) (Heitz 2014, eq. 43), without the facet-side factor
  // chi+(w.w_m) (the caller's, as in D(w, w_m)).
  double G1(const Vec3& w) const { return 1.0 / (1.0 + Lambda(w)); }

  // Height-correlated masking-shadowing G2(w_o, w_i) = 1 / (1 + Lambda(w_o) + Lambda(w_i))
  // (spec "Microfacet BSDF", Heitz 2014 eq. 99), without the chi+ facet-side factors (for the
  // half vector of a reflection w_o.w_m = w_i.w_m = |w_o + w_i| / 2 > 0; transmission checks its own).
  double G2(const Vec3& wo, const Vec3& wi) const { return 1.0 / (1.0 + Lambda(wo) + Lambda(wi)); }

  // Density of visible normals D_w(w_m) = G1(w) max(0, w.w_m) D(w_m) / w.n (Heitz 2018, eq. 1),
  // 0 for w.n <= 0.
  double D(const Vec3& w, const Vec3& wm) const {
    if (w.z <= 0) return 0.0;
    const double cos_wm = dot(w, wm);
    if (cos_wm <= 0) return 0.0;
    return G1(w) * cos_wm * D(wm) / w.z;
  }

  // A visible normal w_m ~ D_w(w_m) for w.n > 0, (u1, u2) in [0, 1)^2; w_m.n >= 0 (Heitz 2018,
  // listing 1: stretch, sample the projected hemisphere, unstretch).
  Vec3 Sample_wm(const Vec3& w, double u1, double u2) const;
  // Solid-angle density of Sample_wm: D(w, w_m).
  double PDF(const Vec3& w, const Vec3& wm) const { return D(w, wm); }

  // Single-scattering microfacet BRDF M_r = D(h) G2(v, l) / (4 |v.n| |l.n|), h = (v + l) / |v + l|
  // (spec "Microfacet BSDF"), without Fresnel; 0 unless v and l are both above the surface.
  double M_r(const Vec3& v, const Vec3& l) const {
    if (v.z <= 0 || l.z <= 0) return 0.0;
    return M_r(v, l, normalize(v + l));
  }
  // The same with the half vector h = normalize(v + l) given (v.n, l.n > 0).
  double M_r(const Vec3& v, const Vec3& l, const Vec3& h) const { return D(h) * G2(v, l) / (4.0 * v.z * l.z); }

 private:
  bool smooth_ = false;
  double au_ = 1, av_ = 1;
  double grazing_guard_ = 0;
};

}  // namespace dspbr
