// Small 3-vector and RGB types used throughout the reference (double precision).
#pragma once
#include <algorithm>
#include <cmath>

namespace dspbr {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
  Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};
constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
// Returns v / |v|; a zero vector stays zero (callers check degenerate inputs).
inline Vec3 normalize(const Vec3& v) {
  const double l = length(v);
  return l > 0 ? v / l : v;
}
// Mirror reflection of v about n (both unit, pointing away from the surface).
inline Vec3 reflect(const Vec3& v, const Vec3& n) { return 2.0 * dot(v, n) * n - v; }

// Refraction of v (unit, pointing away, v.h > 0) through a facet h with eta = eta_i / eta_o
// (Snell's law, Walter et al. 2007 eq. 40). Returns false under total internal reflection.
inline bool refract_dir(const Vec3& v, const Vec3& h, double eta, Vec3& l) {
  const double cos_i = dot(v, h);
  const double sin2_t = eta * eta * std::max(0.0, 1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0) return false;  // total internal reflection
  const double cos_t = std::sqrt(1.0 - sin2_t);
  l = normalize(-v * eta + h * (eta * cos_i - cos_t));
  return true;
}

// Linear sRGB triple. Component-wise arithmetic.
struct Rgb {
  double r = 0, g = 0, b = 0;
  constexpr Rgb() = default;
  constexpr explicit Rgb(double s) : r(s), g(s), b(s) {}
  constexpr Rgb(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
  constexpr Rgb operator+(const Rgb& o) const { return {r + o.r, g + o.g, b + o.b}; }
  constexpr Rgb operator-(const Rgb& o) const { return {r - o.r, g - o.g, b - o.b}; }
  constexpr Rgb operator*(const Rgb& o) const { return {r * o.r, g * o.g, b * o.b}; }
  constexpr Rgb operator/(const Rgb& o) const { return {r / o.r, g / o.g, b / o.b}; }
  constexpr Rgb operator*(double s) const { return {r * s, g * s, b * s}; }
  constexpr Rgb operator/(double s) const { return {r / s, g / s, b / s}; }
  Rgb& operator+=(const Rgb& o) { r += o.r; g += o.g; b += o.b; return *this; }
  Rgb& operator*=(double s) { r *= s; g *= s; b *= s; return *this; }
  constexpr double operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
  constexpr double max_component() const { return std::max(r, std::max(g, b)); }
  constexpr double min_component() const { return std::min(r, std::min(g, b)); }
  // Relative luminance of linear sRGB (D65), as in the spec's emission section.
  constexpr double luminance() const { return 0.2126729 * r + 0.7151522 * g + 0.0721750 * b; }
};
constexpr Rgb operator*(double s, const Rgb& c) { return c * s; }
constexpr Rgb operator-(double s, const Rgb& c) { return Rgb(s) - c; }

}  // namespace dspbr
