// Direction sampling on the unit sphere (local frame, normal = +z) with their solid-angle pdfs.
// Malley's method for the cosine-weighted hemisphere (concentric disk mapping, Shirley & Chiu 1997).
#pragma once
#include <cmath>

#include "dspbr/constants.h"
#include "dspbr/vec3.h"

namespace dspbr {

constexpr double kBsdfInvPi = 1.0 / kPi;

// Concentric map of [0,1)^2 to the unit disk (Shirley & Chiu 1997).
inline void concentric_disk(double u1, double u2, double& x, double& y) {
  const double a = 2 * u1 - 1, b = 2 * u2 - 1;
  if (a == 0 && b == 0) { x = y = 0; return; }
  double r, phi;
  if (std::abs(a) > std::abs(b)) { r = a; phi = (kPi / 4) * (b / a); }
  else { r = b; phi = kPi / 2 - (kPi / 4) * (a / b); }
  x = r * std::cos(phi);
  y = r * std::sin(phi);
}

// Cosine-weighted direction in the upper hemisphere: pdf = max(0, z) / pi.
inline Vec3 sample_cosine_hemisphere(double u1, double u2) {
  double x, y;
  concentric_disk(u1, u2, x, y);
  return {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))};
}
inline double cosine_hemisphere_pdf(const Vec3& w) { return std::max(0.0, w.z) * kBsdfInvPi; }

// Uniform direction in the upper hemisphere: pdf = 1 / (2 pi) for z > 0.
inline Vec3 sample_uniform_hemisphere(double u1, double u2) {
  const double z = u1, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline double uniform_hemisphere_pdf(const Vec3& w) { return w.z > 0 ? 0.5 * kBsdfInvPi : 0.0; }

// Mirror image through the tangent plane (z -> -z).
inline Vec3 flip_z(const Vec3& w) { return {w.x, w.y, -w.z}; }

inline double mean(const Rgb& c) { return (c.r + c.g + c.b) / 3.0; }

}  // namespace dspbr
