#include "dspbr/bsdf/transmission_compensation.h"

#include <algorithm>
#include <cmath>

#include "dspbr/bsdf/multiscatter.h"
#include "dspbr/bsdf/sampling.h"

namespace dspbr {

double CoreAlbedo::operator()(double cos_theta, LobeCache& cache) const {
  const double e_m_value = cache.albedo(e_m, cos_theta);
  // docs/bsdf.md, "Transmission compensation": E = E_g + F_ms (1 - E_m).
  return (glass ? (*glass)(cos_theta) : e_m_value) + f_ms * (1.0 - e_m_value);
}

TransmissionCompensation::TransmissionCompensation(bool transmission, const Rgb& c, CoreAlbedo e_v, CoreAlbedo e_l,
                                                   double e_l_avg)
    : transmission_(transmission), c_(c), e_v_(std::move(e_v)), e_l_(std::move(e_l)) {
  const double missing_avg = 1.0 - e_l_avg;
  inv_norm_ = missing_avg > kMinMissingEnergy ? 1.0 / (kPi * missing_avg) : 0.0;
}

double TransmissionCompensation::missing_v(double c, LobeCache& cache) const {
  return std::clamp(1.0 - e_v_(std::abs(c), cache), 0.0, 1.0);
}
double TransmissionCompensation::missing_l(double c, LobeCache& cache) const {
  return std::clamp(1.0 - e_l_(std::abs(c), cache), 0.0, 1.0);
}

Rgb TransmissionCompensation::eval(const Vec3& v, const Vec3& l) const {
  LobeCache none;
  return eval(v, l, none);
}

Rgb TransmissionCompensation::eval(const Vec3& v, const Vec3& l, LobeCache& cache) const {
  if (v.z <= 0 || inv_norm_ == 0 || (transmission_ ? !(l.z < 0) : !(l.z > 0))) return Rgb(0);
  // Kulla & Conty 2017: the separable multiple-scattering lobe, normalised by its cosine average.
  return c_ * (missing_v(v.z, cache) * missing_l(l.z, cache) * inv_norm_);
}

double TransmissionCompensation::pdf(const Vec3& v, const Vec3& l) const {
  if (v.z <= 0) return 0.0;
  return cosine_hemisphere_pdf(transmission_ ? flip_z(l) : l);
}

BsdfSample TransmissionCompensation::sample(const Vec3& v, const Vec3& u) const {
  BsdfSample s;
  if (v.z <= 0) return s;
  s.l = sample_cosine_hemisphere(u.y, u.z);
  if (transmission_) s.l = flip_z(s.l);
  return make_sample(*this, v, s.l, flags());
}

uint32_t TransmissionCompensation::flags() const {
  return (transmission_ ? kLobeTransmission : kLobeReflection) | kLobeDiffuse;
}

double TransmissionCompensation::sampling_weight(const Vec3& v) const {
  LobeCache none;
  return sampling_weight(v, none);
}

double TransmissionCompensation::sampling_weight(const Vec3& v, LobeCache& cache) const {
  if (v.z <= 0 || inv_norm_ == 0) return 0.0;
  return std::max(0.0, mean(c_)) * missing_v(v.z, cache);
}

}  // namespace dspbr
