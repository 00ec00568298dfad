// Orthonormal shading frame (t, b, n). In local coordinates t = +x, b = +y, n = +z.
#pragma once
#include "dspbr/vec3.h"

namespace dspbr {

struct Frame {
  Vec3 t{1, 0, 0}, b{0, 1, 0}, n{0, 0, 1};

  Vec3 to_local(const Vec3& w) const { return {dot(w, t), dot(w, b), dot(w, n)}; }
  Vec3 to_world(const Vec3& w) const { return t * w.x + b * w.y + n * w.z; }

  // Frame around a unit normal (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
  static Frame from_normal(const Vec3& n);
  // Frame from a unit normal and a tangent that need not be orthogonal to it (Gram-Schmidt);
  // falls back to from_normal when the tangent is parallel to the normal.
  static Frame from_normal_tangent(const Vec3& n, const Vec3& tangent);
};

// Trigonometry of a unit vector in the local frame (z = normal).
inline double cos_theta(const Vec3& w) { return w.z; }
inline double abs_cos_theta(const Vec3& w) { return std::abs(w.z); }
inline bool same_hemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0; }
// The unit direction in the xz plane (azimuth 0) with cos theta = mu: the view direction of the
// tables' and the checks' one-dimensional cuts (|mu| <= 1; mu < 0 is below the surface).
inline Vec3 view_dir(double mu) { return {std::sqrt(std::max(0.0, 1.0 - mu * mu)), 0.0, mu}; }

}  // namespace dspbr
