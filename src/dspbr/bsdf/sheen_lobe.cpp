#include "dspbr/bsdf/sheen_lobe.h"

#include <algorithm>

#include "dspbr/bsdf/sampling.h"
#include "dspbr/sheen.h"

namespace dspbr {

SheenLobe::SheenLobe(const Rgb& color, double sheen_roughness, SheenModel model, const LutSet& luts)
    : color_(color),
      alpha_b_(std::max(sheen_roughness * sheen_roughness, kMinAlphaB)),
      model_(model),
      e_b_(AlbedoSlice::E_sheen(luts, alpha_b_, model == SheenModel::Ash)) {}

Rgb SheenLobe::eval(const Vec3& v, const Vec3& l) const {
  if (v.z <= 0 || l.z <= 0) return Rgb(0);
  const double mb = model_ == SheenModel::Main ? sheen_brdf(v, l, alpha_b_, *fit_) : sheen_brdf_ash(v, l, alpha_b_);
  return color_ * mb;
}

double SheenLobe::pdf(const Vec3& v, const Vec3& l) const { return v.z > 0 ? uniform_hemisphere_pdf(l) : 0.0; }

BsdfSample SheenLobe::sample(const Vec3& v, const Vec3& u) const {
  BsdfSample s;
  if (v.z <= 0) return s;
  s.l = sample_uniform_hemisphere(u.y, u.z);
  return make_sample(*this, v, s.l, kLobeReflection | kLobeGlossy);
}

double SheenLobe::albedo(double cos_theta) const {
  const double c = std::abs(cos_theta);
  return std::clamp(e_b_(c), 0.0, 1.0);
}

double SheenLobe::layer_scale(double cos_v, double cos_l) const {
  if (!scales_layers_) return 1.0;
  const double rho_hat = color_.max_component();
  return std::clamp(std::min(1.0 - rho_hat * albedo(cos_v), 1.0 - rho_hat * albedo(cos_l)), 0.0, 1.0);
}

double SheenLobe::sampling_weight(const Vec3& v) const {
  if (v.z <= 0) return 0.0;
  return std::max(0.0, mean(color_)) * std::max(albedo(v.z), 1e-3);
}

}  // namespace dspbr
