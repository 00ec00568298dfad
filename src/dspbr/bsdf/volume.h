// Volume below a non-thin-walled surface: attenuation and scattering coefficients from the
// user parameters, and the Henyey-Greenstein phase function (eval, sample, pdf).
// Spec "Volume"; [KC17] Kulla & Conty 2017 (albedo inversion); [HG41] Henyey & Greenstein 1941.
// Decisions (limits, sign convention) and measurements: docs/components.md.
#pragma once
#include "dspbr/material.h"
#include "dspbr/vec3.h"

namespace dspbr {

// Attenuation coefficient sigma_t = -log(a) / d per unit length of d (spec "Volume"), with the
// limits: d = +inf -> 0 (no attenuation, also for a = 0); d = 0 -> +inf (opaque, as the spec's
// parameter table says, also for a = 1); a <= 0 with 0 < d < inf -> +inf; a >= 1 -> 0.
// +inf means "opaque": use volume_transmittance, which handles it.
double volume_sigma_t(double a, double d);
Rgb volume_sigma_t(const Rgb& a, double d);

// Single-scattering albedo from the multiple-scattering (subsurface) colour [KC17]:
// rho_ss = 1 - (4.09712 + 4.20863 rho_ms - sqrt(9.59217 + 41.6808 rho_ms + 17.7126 rho_ms^2))^2.
// rho_ms is clamped to [0, 1]; rho_ms = 0 gives exactly 0 (the fit gives 5.6e-6 there; the spec
// disables subsurface scattering at rho_ms = 0), rho_ms = 1 exactly 1 (the fit: 1 - 2.7e-11); the
// result is clamped to [0, 1].
double volume_rho_ss(double rho_ms);
Rgb volume_rho_ss(const Rgb& rho_ms);

struct VolumeCoefficients {
  Rgb sigma_t;  // attenuation (extinction) coefficient, 1 / mfp
  Rgb sigma_a;  // absorption: sigma_t (1 - rho_ss)
  Rgb sigma_s;  // scattering: sigma_t rho_ss
  Rgb rho_ss;   // single-scattering albedo
};
// From attenuation colour a, distance d and subsurface colour rho_ms. Where sigma_t = +inf the
// products follow the convention inf * 0 = 0 (an opaque, purely absorbing channel has sigma_s = 0).
VolumeCoefficients volume_coefficients(const Rgb& a, double d, const Rgb& rho_ms);
inline VolumeCoefficients volume_coefficients(const Material& m) {
  return volume_coefficients(m.attenuationColor, m.attenuationDistance, m.subsurfaceColor);
}

// Beer-Lambert transmittance exp(-sigma_t t) per channel; t = 0 transmits 1 even for sigma_t = +inf.
Rgb volume_transmittance(const Rgb& sigma_t, double distance);

// Henyey-Greenstein phase function (spec "Volume"):
// p(v, l; g) = (1 - g^2) / (4 pi (1 + g^2 + 2 g (v.l))^(3/2)).
// Convention (as for BSDFs, bsdf.h): v and l both point AWAY from the scattering point (v towards
// the viewer, l towards the light); light travels along -l, then along v, so the scattering angle
// is cos theta = -(v.l), and g > 0 (forward scattering) favours l = -v. g is clamped to [-1, 1];
// |g| = 1 is a Dirac (eval returns 0; sampling returns the delta direction).
double hg_phase(const Vec3& v, const Vec3& l, double g);
// Same as a function of the scattering cosine cos theta = -(v.l).
double hg_phase_cos(double cos_theta, double g);
inline double hg_pdf(const Vec3& v, const Vec3& l, double g) { return hg_phase(v, l, g); }

struct PhaseSample {
  Vec3 l;
  double pdf = 0;      // solid-angle density; 1 (discrete) for a delta
  bool delta = false;  // |g| = 1
};
// Samples l with density hg_phase(v, ., g) by exact inversion of the CDF of cos theta
// (cancellation-free forms near g = 0 and |g| = 1); (u1, u2) in [0, 1)^2.
PhaseSample hg_sample(const Vec3& v, double g, double u1, double u2);
// The inverse CDF alone: cos theta of the scattering angle for u in [0, 1).
double hg_sample_cos(double g, double u);

}  // namespace dspbr
