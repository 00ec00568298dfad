#include "dspbr/frame.h"

namespace dspbr {

Frame Frame::from_normal(const Vec3& n) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  Frame f;
  f.n = n;
  f.t = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  f.b = {b, sign + n.y * n.y * a, -n.y};
  return f;
}

Frame Frame::from_normal_tangent(const Vec3& n, const Vec3& tangent) {
  const Vec3 t = tangent - n * dot(n, tangent);
  const double len = length(t);
  if (!(len > 1e-12)) return from_normal(n);  // degenerate tangent: any orthonormal frame
  Frame f;
  f.n = n;
  f.t = t / len;
  f.b = cross(n, f.t);
  return f;
}

}  // namespace dspbr
