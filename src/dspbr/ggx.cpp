#include <limits>

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

double ggx_d(const Vec3& h, double alpha_u, double alpha_v) {
  if (h.z <= 0) return 0.0;  // chi+(h.n)
  const double x = h.x / alpha_u, y = h.y / alpha_v;
  const double denom = x * x + y * y + h.z * h.z;
  return 1.0 / (kPi * alpha_u * alpha_v * denom * denom);
}

double smith_lambda(const Vec3& w, double alpha_u, double alpha_v) {
  const double cos2 = w.z * w.z;
  const double tan2_alpha2 = (w.x * w.x * alpha_u * alpha_u + w.y * w.y * alpha_v * alpha_v);
  if (tan2_alpha2 == 0) return 0.0;  // normal incidence or alpha = 0: no masking
  if (cos2 == 0) return std::numeric_limits<double>::infinity();
  const double inv_a2 = tan2_alpha2 / cos2;
  // (-1 + sqrt(1 + x)) / 2 rewritten as x / (2 (1 + sqrt(1 + x))) to avoid cancellation at small x.
  return inv_a2 / (2.0 * (1.0 + std::sqrt(1.0 + inv_a2)));
}

double ggx_g1(const Vec3& w, const Vec3& h, double alpha_u, double alpha_v) {
  if (dot(w, h) <= 0) return 0.0;
  return 1.0 / (1.0 + smith_lambda(w, alpha_u, alpha_v));
}

double ggx_g2(const Vec3& v, const Vec3& l, const Vec3& h, double alpha_u, double alpha_v) {
  if (dot(v, h) <= 0 || dot(l, h) <= 0) return 0.0;
  return 1.0 / (1.0 + smith_lambda(v, alpha_u, alpha_v) + smith_lambda(l, alpha_u, alpha_v));
}

Vec3 ggx_sample_vndf(const Vec3& v, double alpha_u, double alpha_v, double u1, double u2) {
  // Heitz 2018, listing 1: stretch, sample the projected hemisphere, unstretch.
  const Vec3 vh = normalize(Vec3{alpha_u * v.x, alpha_v * v.y, v.z});
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
  return normalize(Vec3{alpha_u * nh.x, alpha_v * nh.y, std::max(0.0, nh.z)});
}

double ggx_vndf_pdf(const Vec3& v, const Vec3& h, double alpha_u, double alpha_v) {
  if (v.z <= 0) return 0.0;
  return ggx_g1(v, h, alpha_u, alpha_v) * std::max(0.0, dot(v, h)) * ggx_d(h, alpha_u, alpha_v) / v.z;
}

double ggx_microfacet_brdf(const Vec3& v, const Vec3& l, double alpha_u, double alpha_v) {
  if (v.z <= 0 || l.z <= 0) return 0.0;
  const Vec3 h = normalize(v + l);
  return ggx_d(h, alpha_u, alpha_v) * ggx_g2(v, l, h, alpha_u, alpha_v) / (4.0 * v.z * l.z);
}

}  // namespace dspbr
