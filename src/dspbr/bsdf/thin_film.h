// Thin-film iridescence: the Airy-summed reflectance R(cos theta, eta, d_i, eta_i) of a thin
// dielectric film between air and a base, integrated over the visible spectrum to linear sRGB.
// Spec "Thin Film"; Belcour & Barla 2017, "A Practical Extension to Microfacet Theory for the
// Modeling of Varying Iridescence" (BB17). Decisions and measured accuracy: docs/components.md.
//
// Geometry: air (eta = 1) | film (eta_film, thickness d) | base (eta_base, semi-infinite).
// The base is a real-IOR dielectric; a metal base enters through its equivalent IOR eta_rho
// (thin_film_metal_eta). Both polarizations are summed coherently inside the film (Airy) and
// averaged incoherently (unpolarized light).
#pragma once
#include <array>
#include <vector>

#include "dspbr/material.h"
#include "dspbr/vec3.h"

namespace dspbr {

// Exact unpolarized Fresnel reflectance of the interface air | eta (eta may be < 1 for an
// interface seen from the denser side: total internal reflection gives 1). This is what
// thin_film_reflectance reduces to at thickness 0 or film IOR 1 (NOT Schlick's F: see docs).
double fresnel_dielectric_exact(double cos_theta, double eta);

// Equivalent IOR of a metal base (spec "Thin Film"): eta_rho = (1 + sqrt(max rho)) / (1 - sqrt(max rho)),
// the real IOR whose normal-incidence reflectance is max(rho). Returns +infinity for max(rho) >= 1
// (a perfect mirror; thin_film_reflectance then returns 1).
double thin_film_metal_eta(const Rgb& rho);

// Spectral thin-film reflectance at one wavelength (nm) for unpolarized light, in [0, 1].
// cos_theta: cosine of the incidence angle in air (|cos| is used); eta_base > 0 (may be +inf);
// thickness_um >= 0 in micrometres; eta_film > 0. Outside this domain (or NaN) the thin-film
// functions throw std::invalid_argument (material validation keeps legal materials inside it).
double thin_film_reflectance_spectral(double cos_theta, double eta_base, double thickness_um,
                                      double eta_film, double lambda_nm);

// How the spectral integral is evaluated.
//  Quadrature: the reference, composite Gauss-Legendre over 360..830 nm of the per-wavelength Airy
//    reflectance (~15 us per call).
//  Fourier: BB17 sec. 4, the Airy reflectance as a Fourier series in the round-trip phase whose
//    terms integrate against the tabulated Fourier transform of the same CMF weights (~0.1 us);
//    falls back to Quadrature where the series does not apply (see thin_film_optics.h).
//    Difference to Quadrature: docs/components.md.
enum class ThinFilmIntegration { Fourier, Quadrature };

// Tristimulus values of the reflected light under an equal-energy illuminant, each normalized by
// the integral of its colour-matching function (a perfect white reflector gives (1, 1, 1)).
// CMF: Wyman, Sloan & Shirley 2013 multi-lobe fit of CIE 1931 2 deg. Returned as (X, Y, Z) in an
// Rgb for convenience.
Rgb thin_film_reflectance_xyz(double cos_theta, double eta_base, double thickness_um, double eta_film,
                              ThinFilmIntegration how = ThinFilmIntegration::Quadrature);

// Converts E-white-normalized XYZ to linear sRGB (Bradford adaptation E -> D65, IEC 61966-2-1
// matrix, then scaled so that XYZ = (1,1,1) maps exactly to RGB = (1,1,1)). Not clamped.
Rgb thin_film_xyz_to_linear_srgb(const Rgb& xyz);

// R(cos theta, eta_base, d_i, eta_i) of the spec as linear sRGB, each channel clamped to [0, 1]
// (interference colours can lie outside the sRGB gamut). Exactly fresnel_dielectric_exact in all
// three channels when thickness_um == 0 or eta_film == 1 (the film vanishes optically).
// The BSDF reads R from per-material tables of the Fourier evaluation (thin_film_table.h).
Rgb thin_film_reflectance(double cos_theta, double eta_base, double thickness_um, double eta_film,
                          ThinFilmIntegration how = ThinFilmIntegration::Fourier);

// Convenience: the material's film (thinFilmThickness in microns, thinFilmIor).
inline Rgb thin_film_reflectance(double cos_theta, double eta_base, const Material& m) {
  return thin_film_reflectance(cos_theta, eta_base, m.thinFilmThickness, m.thinFilmIor);
}

// The tabulated sensitivity of the Fourier evaluation, for the shader library's copy
// (luts/dspbr_thin_film_lookup.h): S_c(x) = E_c(x) exp(i x nu_c), the envelope E_c sampled every
// `step` rad nm (x = phase times lambda) from x = -step (the ghost sample E_c(-x) = conj(E_c(x)));
// sample k holds Re E_X, Re E_Y, Re E_Z, Im E_X, Im E_Y, Im E_Z at x = (k - 1) step; S_c = 0 from
// x_end on. Catmull-Rom between samples.
struct ThinFilmSensitivity {
  double step = 0, x_end = 0;
  double nu[3] = {0, 0, 0};
  std::vector<std::array<double, 6>> samples;
};
const ThinFilmSensitivity& thin_film_sensitivity();

// Wyman, Sloan & Shirley 2013 multi-lobe fit of the CIE 1931 2 deg colour-matching functions
// (x_bar, y_bar, z_bar at lambda in nm), exposed for tests and plots.
Rgb cie1931_cmf_wss(double lambda_nm);

}  // namespace dspbr
