// Fresnel terms of the spec's "Fresnel" and "Energy Preservation" sections.
#pragma once
#include <cmath>

#include "dspbr/vec3.h"

namespace dspbr {

// Schlick: F(cos; f0, f90) = f0 + (f90 - f0) (1 - |cos|)^5 (spec "Fresnel").
template <class T>
T fresnel_schlick(double cos_theta, const T& f0, const T& f90) {
  const double m = 1.0 - std::min(1.0, std::abs(cos_theta));
  const double m2 = m * m;
  return f0 + (f90 - f0) * (m2 * m2 * m);
}

// Reflectance at normal incidence F0 = ((eta_i - eta_o) / (eta_i + eta_o))^2 (spec, transparent BSDF).
inline double f0_from_ior(double eta_i, double eta_o) {
  const double r = (eta_i - eta_o) / (eta_i + eta_o);
  return r * r;
}

// Relative IOR difference below which the interface does not bend light: transmission is then a
// Dirac straight through at any roughness (the half-vector map l -> h_t degenerates at eta = 1).
constexpr double kIndexMatched = 1e-7;

// sin^2 of the transmitted angle from Snell's law: (eta_i/eta_o)^2 (1 - cos^2) (spec "Fresnel", [Lag13]).
inline double sin2_transmitted(double cos_theta, double eta_i, double eta_o) {
  const double e = eta_i / eta_o;
  return e * e * std::max(0.0, 1.0 - cos_theta * cos_theta);
}

// F_d: Schlick evaluated on the side of the denser medium, 1 under total internal reflection
// (spec "Fresnel"). eta_i: medium the ray travels in; eta_o: the other side.
template <class T>
T fresnel_schlick_d(double cos_theta, const T& f0, const T& f90, double eta_i, double eta_o) {
  if (eta_o >= eta_i) return fresnel_schlick(cos_theta, f0, f90);
  const double s2 = sin2_transmitted(cos_theta, eta_i, eta_o);
  if (s2 >= 1.0) return T(1.0);  // total internal reflection: F_d = 1 whatever f90
  return fresnel_schlick(std::sqrt(1.0 - s2), f0, f90);
}

// Hemispherical average of Schlick's Fresnel: F_m,avg = f0 20/21 + f90/21 (spec eq. fr_avg).
template <class T>
T fresnel_avg(const T& f0, const T& f90) {
  return f0 * (20.0 / 21.0) + f90 * (1.0 / 21.0);
}

// Multiple-scattering Fresnel F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) (spec eq. multiscatter).
template <class T>
T fresnel_ms(const T& f0, const T& f90, double e_avg) {
  const T fa = fresnel_avg(f0, f90);
  return fa * fa * e_avg / (1.0 - fa * (1.0 - e_avg));
}

}  // namespace dspbr
