// Dispersion: wavelength-dependent IOR from the Abbe number by Cauchy's two-term equation.
// Spec "Dispersion". The printed constants are checked against the Fraunhofer lines in
// tests/test_dispersion.cpp and docs/components.md.
#pragma once
#include "dspbr/material.h"

namespace dspbr {

// Fraunhofer lines of the Abbe number's definition (spec "Dispersion"), in nm.
constexpr double kFraunhoferD = 587.56;
constexpr double kFraunhoferF = 486.13;
constexpr double kFraunhoferC = 656.27;

// eta(lambda) = max(eta_d + (eta_d - 1) / nu_d (523655 / lambda^2 - 1.5168), 1), lambda in nm, with
// the spec's printed constants (523655 = 1 / (1/F^2 - 1/C^2), 1.5168 = 523655 / d^2, both rounded).
// nu_d = 0 disables dispersion and returns eta_d exactly; so does any nu_d that is not > 0
// (negative or NaN Abbe numbers are rejected by material validation) and nu_d = +inf.
// Throws std::invalid_argument unless lambda_nm > 0.
double dispersion_ior(double eta_d, double abbe_number, double lambda_nm);
inline double dispersion_ior(const Material& m, double lambda_nm) {
  return dispersion_ior(m.ior, m.abbeNumber, lambda_nm);
}

}  // namespace dspbr
