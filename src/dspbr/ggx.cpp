#include "dspbr/ggx.h"

namespace dspbr {

Vec3 GgxDistribution::Sample_wm(const Vec3& w, double u1, double u2) const {
  // Heitz 2018, listing 1: stretch w to the hemisphere configuration (alpha = 1), sample the
  // projected hemisphere as a disk whose far half is compressed by (1 + vh.z) / 2, unstretch.
  const Vec3 vh = normalize(Vec3{au_ * w.x, av_ * w.y, w.z});
  const double lensq = vh.x * vh.x + vh.y * vh.y;
  const Vec3 t1 = lensq > 0 ? Vec3{-vh.y, vh.x, 0} / std::sqrt(lensq) : Vec3{1, 0, 0};
  const Vec3 t2 = cross(vh, t1);
  const double r = std::sqrt(u1);
  const double phi = 2.0 * kPi * u2;
  const double p1 = r * std::cos(phi);
  double p2 = r * std::sin(phi);
  const double s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
  const Vec3 nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2));
  return normalize(Vec3{au_ * nh.x, av_ * nh.y, std::max(0.0, nh.z)});
}

}  // namespace dspbr
