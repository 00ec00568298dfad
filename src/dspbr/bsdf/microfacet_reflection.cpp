#include "dspbr/bsdf/microfacet_reflection.h"

#include <algorithm>

#include "dspbr/bsdf/sampling.h"

namespace dspbr {

MicrofacetReflection::MicrofacetReflection(double alpha_u, double alpha_v, CosineFactor fresnel)
    : ggx_(alpha_u, alpha_v), delta_(ggx_.effectively_smooth()), fresnel_(std::move(fresnel)) {}

double MicrofacetReflection::pdf(const Vec3& v, const Vec3& l) const {
  // Density of l = reflect(v, h), h ~ D_v(h): D_v(h) / (4 v.h) (Heitz 2018). Reflections below the
  // horizon are failed samples (bsdf.h), so the pdf is 0 there and integrates to 1 - P(below).
  if (delta_ || v.z <= 0 || l.z <= 0) return 0.0;
  const Vec3 s = v + l;
  const double len = length(s);
  if (!(len > 0)) return 0.0;
  const Vec3 h = s / len;
  const double vh = dot(v, h);
  if (h.z <= 0 || vh <= 0) return 0.0;
  return ggx_.PDF(v, h) / (4.0 * vh);
}

BsdfSample MicrofacetReflection::sample(const Vec3& v, const Vec3& u) const {
  BsdfSample s;
  if (v.z <= 0) return s;
  if (delta_) {
    s.l = {-v.x, -v.y, v.z};
    s.weight = fresnel_(v.z);
    s.pdf = 1.0;
    s.flags = kLobeReflection | kLobeDelta;
    s.valid = true;
    return s;
  }
  const Vec3 h = ggx_.Sample_wm(v, u.y, u.z);
  if (dot(v, h) <= 0) return s;
  s.l = normalize(reflect(v, h));
  // Below the horizon pdf() is 0, so make_sample returns a failed sample (bsdf.h).
  return make_sample(*this, v, s.l, kLobeReflection | kLobeGlossy);
}

uint32_t MicrofacetReflection::flags() const {
  return kLobeReflection | (delta_ ? kLobeDelta : kLobeGlossy);
}

double MicrofacetReflection::sampling_weight(const Vec3& v) const {
  if (v.z <= 0) return 0.0;
  // Fresnel at the macro normal and at grazing: Schlick-like mixtures grow towards grazing.
  return std::max(0.0, 0.5 * (mean(fresnel_(v.z)) + mean(fresnel_(0.5 * v.z))));
}

}  // namespace dspbr
