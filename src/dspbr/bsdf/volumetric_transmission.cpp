#include "dspbr/bsdf/volumetric_transmission.h"

#include <algorithm>
#include <cmath>

#include "dspbr/bsdf/sampling.h"

namespace dspbr {

VolumetricTransmission::VolumetricTransmission(double alpha_u, double alpha_v, double eta_i, double eta_o,
                                               CosineFactor factor)
    : ggx_(alpha_u, alpha_v),
      eta_i_(eta_i),
      eta_o_(eta_o),
      delta_(ggx_.effectively_smooth() || std::abs(eta_i / eta_o - 1.0) < kIndexMatched),
      factor_(std::move(factor)) {}

bool VolumetricTransmission::half_vector(const Vec3& v, const Vec3& l, Vec3& h) const {
  Vec3 s = -(v * eta_i_ + l * eta_o_);
  const double len = length(s);
  if (!(len > 0)) return false;
  h = s / len;
  if (h.z < 0) h = -h;
  // Refraction: v and l on opposite sides of the microfacet.
  return h.z > 0 && dot(v, h) > 0 && dot(l, h) < 0;
}

Rgb VolumetricTransmission::eval(const Vec3& v, const Vec3& l) const {
  if (delta_ || v.z <= 0 || l.z >= 0) return Rgb(0);
  Vec3 h;
  if (!half_vector(v, l, h)) return Rgb(0);
  const double vh = dot(v, h), lh = dot(l, h);
  const double denom = eta_i_ * vh + eta_o_ * lh;
  if (denom == 0) return Rgb(0);
  // Height-correlated G for transmission: the chi+ factors are the facet-side checks above.
  const double g = ggx_.G2(v, l);
  const double mt = std::abs(lh) * std::abs(vh) / (std::abs(l.z) * std::abs(v.z)) * eta_o_ * eta_o_ *
                    ggx_.D(h) * g / (denom * denom);
  return factor_(factor_at_macro_normal_ ? v.z : vh) * mt;
}

double VolumetricTransmission::pdf(const Vec3& v, const Vec3& l) const {
  // D_v(h_t) times the Jacobian |dh/dl| = eta_o^2 |l.h| / (eta_i v.h + eta_o l.h)^2 (Walter 2007
  // eq. 17), for every l for which h_t is a refraction configuration.
  if (delta_ || v.z <= 0) return 0.0;
  Vec3 h;
  if (!half_vector(v, l, h)) return 0.0;
  const double vh = dot(v, h), lh = dot(l, h);
  const double denom = eta_i_ * vh + eta_o_ * lh;
  if (denom == 0) return 0.0;
  return ggx_.PDF(v, h) * eta_o_ * eta_o_ * std::abs(lh) / (denom * denom);
}

BsdfSample VolumetricTransmission::sample(const Vec3& v, const Vec3& u) const {
  BsdfSample s;
  if (v.z <= 0) return s;
  const double eta = eta_i_ / eta_o_;
  if (delta_) {
    if (!refract_dir(v, {0, 0, 1}, std::abs(eta - 1.0) < kIndexMatched ? 1.0 : eta, s.l)) return s;
    s.weight = factor_(v.z);
    s.pdf = 1.0;
    s.flags = kLobeTransmission | kLobeDelta;
    s.valid = true;
    return s;
  }
  const Vec3 h = ggx_.Sample_wm(v, u.y, u.z);
  if (dot(v, h) <= 0 || !refract_dir(v, h, eta, s.l)) return s;  // TIR: the sample fails
  return make_sample(*this, v, s.l, kLobeTransmission | kLobeGlossy);
}

uint32_t VolumetricTransmission::flags() const {
  return kLobeTransmission | (delta_ ? kLobeDelta : kLobeGlossy);
}

double VolumetricTransmission::sampling_weight(const Vec3& v) const {
  if (v.z <= 0) return 0.0;
  // Smooth lobe under total internal reflection: nothing is transmitted.
  const double eta = eta_i_ / eta_o_;
  const bool macro_tir = eta * eta * (1.0 - v.z * v.z) >= 1.0 && std::abs(eta - 1.0) >= kIndexMatched;
  if (delta_ && macro_tir) return 0.0;
  if (macro_tir) {
    // Beyond the critical angle theta_c only facets tilted towards v by more than
    // delta = theta_v - theta_c transmit: the share of GGX slopes beyond tan(delta) (the slope
    // distribution's tail, alpha^2 / (alpha^2 + tan^2 delta)), half of them towards v, times the
    // factor at normal incidence. The factor at the macro normal is 0 here: the lobe would be
    // chosen with the floor probability and its weights reach ~1e3 (measured: white rough glass
    // r = 1 seen from inside at cos 0.5, weights up to 860).
    // tan(delta) = num / den from the sines and cosines (sin theta_c = 1 / eta): no inverse
    // trigonometric function, whose float precision a shader does not promise.
    const double alpha = std::max(ggx_.alpha_u(), ggx_.alpha_v());
    const double cos_v = std::clamp(v.z, 0.0, 1.0), sin_v = std::sqrt(1.0 - cos_v * cos_v);
    const double sin_c = 1.0 / eta, cos_c = std::sqrt(std::max(0.0, 1.0 - sin_c * sin_c));
    const double num = std::max(0.0, sin_v * cos_c - cos_v * sin_c), den = cos_v * cos_c + sin_v * sin_c;
    const double a2 = alpha * alpha * den * den;
    return std::max(0.0, 0.5 * a2 / (a2 + num * num) * mean(factor_(1.0)));
  }
  return std::max(0.0, mean(factor_(v.z)));
}

}  // namespace dspbr
