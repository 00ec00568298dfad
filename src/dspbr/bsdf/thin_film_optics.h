// The wavelength-independent part of the thin-film optics and the spectral quadrature, shared by
// the reference spectral integration (thin_film.cpp) and the Fourier-space evaluation
// (thin_film_fourier.cpp). Spec "Thin Film"; Belcour & Barla 2017 (BB17). Not a public interface.
#pragma once
#include <complex>
#include <vector>

#include "dspbr/material.h"

namespace dspbr::thin_film_detail {

// Everything of the Airy sum that does not depend on the wavelength (the film is not dispersive).
struct FilmSetup {
  std::complex<double> r12[2], r23[2];  // amplitude coefficients [s, p], air|film and film|base
  std::complex<double> phase_nm;        // Airy phase times lambda: 4 pi eta_film d cos(theta_film), d in nm
};

// Fresnel amplitudes and phase for incidence cosine c1 in (0, 1] from air (BB17 eq. 2-3).
FilmSetup film_setup(double c1, double eta_base, double thickness_um, double eta_film);

// Airy reflectance (|r_s|^2 + |r_p|^2) / 2 at one wavelength (BB17 eq. 2).
double airy_reflectance(const FilmSetup& f, double lambda_nm);

// A spectral quadrature: nodes and the weights w_i cmf(lambda_i) / Integral cmf for X, Y, Z.
struct SpectralRule {
  std::vector<double> lambda;
  std::vector<Rgb> w_xyz;
};

// Width (in phase, rad) of the Airy resonances, 1 - max over polarizations of |r12 r23|, in (0, 1].
double resonance_width(const FilmSetup& f);

// The coarsest precomputed rule on which the Airy reflectance is resolved: the phase
// |phase_nm| / lambda turns by at most 2 resonance widths per 6-node panel.
const SpectralRule& spectral_rule(double phase_nm_abs, double resonance_width);
// The coarsest precomputed rule whose panels are at most panel_nm wide.
const SpectralRule& spectral_rule_of_width(double panel_nm);

// The spectral integral in Fourier space (BB17 sec. 4) for c1 in (0, 1], a finite base and a film
// of positive thickness and eta_film != 1. False (xyz untouched) where the series does not apply or
// would converge slowly: an evanescent wave in the film, or |r12 r23| close to 1 (then the caller
// integrates per wavelength).
bool try_fourier_xyz(double c1, double eta_base, double thickness_um, double eta_film, Rgb& xyz);

}  // namespace dspbr::thin_film_detail
