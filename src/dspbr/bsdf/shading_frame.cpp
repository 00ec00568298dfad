#include "dspbr/bsdf/shading_frame.h"

#include <cmath>

namespace dspbr {

Vec3 rotate_tangent(const Vec3& n, const Vec3& t_prime, double beta) {
  // Spec "Tangent Space": t = t' cos(beta) - (n x t') sin(beta).
  return t_prime * std::cos(beta) - cross(n, t_prime) * std::sin(beta);
}

Vec3 material_normal(const Vec3& n) {
  const double len = length(n);
  if (!(len > 0) || !std::isfinite(len)) return {0, 0, 1};
  return n / len;
}

Frame core_frame(const Material& m) {
  const Vec3 n = material_normal(m.normal);
  const Frame base = Frame::from_normal_tangent(n, {1, 0, 0});
  const double beta = 2.0 * 3.14159265358979323846 * m.anisotropyRotation;
  Frame f;
  f.n = n;
  f.t = normalize(rotate_tangent(n, base.t, beta));
  f.b = cross(n, f.t);
  return f;
}

Frame clearcoat_frame(const Material& m) {
  return Frame::from_normal_tangent(material_normal(m.clearcoatNormal), {1, 0, 0});
}

}  // namespace dspbr
