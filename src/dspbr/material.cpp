#include "dspbr/material.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace dspbr {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string number_text(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

[[noreturn]] void fail(const std::string& id, const std::string& value, const std::string& what) {
  throw std::invalid_argument("parameter '" + id + "' = " + value + " " + what);
}

void check_float(const char* id, double x, double lo, double hi, bool allow_inf = false) {
  if (std::isnan(x) || (!allow_inf && std::isinf(x))) fail(id, number_text(x), "is not a finite number");
  if (x < lo || x > hi)
    fail(id, number_text(x), "is outside [" + number_text(lo) + ", " + (std::isinf(hi) ? "inf" : number_text(hi)) + "]");
}

void check_color(const char* id, const Rgb& c, double hi) {
  for (int k = 0; k < 3; ++k) {
    const double x = c[k];
    const std::string text = "[" + number_text(c.r) + ", " + number_text(c.g) + ", " + number_text(c.b) + "]";
    if (!std::isfinite(x)) fail(id, text, "has a non-finite channel");
    if (x < 0 || x > hi)
      fail(id, text, "has a channel outside [0, " + (std::isinf(hi) ? std::string("inf") : number_text(hi)) + "]");
  }
}

void check_vector(const char* id, const Vec3& v, bool nonzero) {
  const std::string text = "[" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + "]";
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) fail(id, text, "has a non-finite component");
  if (nonzero && !(length(v) > 0)) fail(id, text, "must be a non-zero vector (it is normalized)");
}

}  // namespace

void validate_material(const Material& m) {
  check_color("albedo", m.albedo, 1);
  check_float("metallic", m.metallic, 0, 1);
  check_float("roughness", m.roughness, 0, 1);
  check_float("anisotropy", m.anisotropy, 0, 1);
  check_float("anisotropyRotation", m.anisotropyRotation, 0, 1);
  check_vector("normal", m.normal, true);
  check_vector("displacement", m.displacement, false);
  check_float("translucency", m.translucency, 0, 1);
  check_color("translucencyColor", m.translucencyColor, 1);
  check_float("transparency", m.transparency, 0, 1);
  check_float("cutoutOpacity", m.cutoutOpacity, 0, 1);
  check_float("specular", m.specular, 0, 1);
  check_color("specularTint", m.specularTint, 1);
  check_float("thinFilm", m.thinFilm, 0, 1);
  check_float("thinFilmThickness", m.thinFilmThickness, 0, 1);
  check_float("thinFilmIor", m.thinFilmIor, 1, 2.5);
  check_color("sheenColor", m.sheenColor, 1);
  check_float("sheenRoughness", m.sheenRoughness, 0, 1);
  check_float("flakeCoverage", m.flakeCoverage, 0, 1);
  check_color("flakeColor", m.flakeColor, 1);
  check_float("flakeSize", m.flakeSize, 0, kInf);
  check_float("flakeRoughness", m.flakeRoughness, 0, 1);
  check_float("flipFlop", m.flipFlop, 0, 1);
  check_color("flipFlopColor", m.flipFlopColor, 1);
  check_float("clearcoat", m.clearcoat, 0, 1);
  check_float("clearcoatRoughness", m.clearcoatRoughness, 0, 1);
  check_vector("clearcoatNormal", m.clearcoatNormal, true);
  check_color("emissionColor", m.emissionColor, kInf);
  check_float("emissionValue", m.emissionValue, 0, kInf);
  check_float("ior", m.ior, 1, kInf);
  check_float("abbeNumber", m.abbeNumber, 0, kInf);
  check_color("attenuationColor", m.attenuationColor, 1);
  check_float("attenuationDistance", m.attenuationDistance, 0, kInf, /*allow_inf=*/true);
  check_color("subsurfaceColor", m.subsurfaceColor, 1);
  check_float("subsurfaceAnisotropy", m.subsurfaceAnisotropy, -1, 1);
}

}  // namespace dspbr
