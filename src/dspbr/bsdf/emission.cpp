#include "dspbr/bsdf/emission.h"

#include <cmath>
#include <stdexcept>

#include "dspbr/constants.h"
#include "dspbr/fresnel.h"

namespace dspbr {

namespace {
bool non_negative_finite(double x) { return x >= 0 && std::isfinite(x); }
}  // namespace

Rgb emission_rho_e(const Rgb& color, double value, EmissionMode mode, bool normalize, double area_m2) {
  if (!non_negative_finite(value))
    throw std::invalid_argument("emissionValue must be a finite number >= 0");
  if (!non_negative_finite(color.r) || !non_negative_finite(color.g) || !non_negative_finite(color.b))
    throw std::invalid_argument("emissionColor channels must be finite numbers >= 0");
  if (mode == EmissionMode::LuminousPower && !(area_m2 > 0 && std::isfinite(area_m2)))
    throw std::invalid_argument(
        "emissionMode LUMINOUS_POWER (lm) needs the object's surface area as a positive finite number of m^2");
  Rgb l_vc = color * value;  // l_norm false
  if (normalize) {
    // Luminance of linear sRGB (D65), spec "Emission"; 0 only for a black colour (channels >= 0).
    const double lum = color.luminance();
    l_vc = lum > 0 ? color * (value / lum) : Rgb(0.0);
  }
  const double scale = mode == EmissionMode::LuminousPower ? 1.0 / (kPi * area_m2) : 1.0 / kPi;
  return l_vc * scale;
}

Rgb emission_radiance(const Rgb& rho_e, const Vec3& v, const Vec3& n_c, double clearcoat) {
  if (!(v.z > 0)) return Rgb(0.0);  // emission into the upper hemisphere only
  const double f_c = fresnel_schlick(dot(v, n_c), 0.04, 1.0);  // F_c: Schlick with eta = 1.5
  return rho_e * (1.0 - clearcoat * f_c);
}

}  // namespace dspbr
