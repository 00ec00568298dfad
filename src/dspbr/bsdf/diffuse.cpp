#include "dspbr/bsdf/diffuse.h"

#include <algorithm>

#include "dspbr/bsdf/multiscatter.h"
#include "dspbr/bsdf/sampling.h"

namespace dspbr {

DiffuseBase::DiffuseBase(const DiffuseParams& p, const LutSet& luts)
    : p_(p), e_base_(AlbedoSlice::E_base(luts, p.r_uv, p.f0_max)) {
  const double missing_avg = 1.0 - luts.E_base_avg(p_.r_uv, p_.f0_max);
  inv_norm_ = missing_avg > kMinMissingEnergy ? 1.0 / (kPi * missing_avg) : 0.0;
}

double DiffuseBase::missing(double cos_theta, LobeCache& cache) const {
  return missing_energy(cache.albedo(e_base_, std::abs(cos_theta)));
}

Rgb DiffuseBase::eval(const Vec3& v, const Vec3& l) const {
  LobeCache none;
  return eval(v, l, none);
}

Rgb DiffuseBase::eval(const Vec3& v, const Vec3& l, LobeCache& cache) const {
  if (v.z <= 0 || l.z == 0) return Rgb(0);
  const double t = l.z > 0 ? 1.0 - p_.translucency : p_.translucency;  // T(v, l; l)
  if (t == 0) return Rgb(0);
  const double b_u = t * kBsdfInvPi;                                  // eq. "diffuse"
  double e[2];
  cache.albedos(e_base_, v.z, std::abs(l.z), e);
  const double b_c = missing_energy(e[0]) * missing_energy(e[1]) * inv_norm_ * t;  // eq. "b_c"
  const double s = p_.specular, i = p_.film_weight;
  Rgb base = Rgb((1.0 - i) * (b_u * (1.0 - s) + s * b_c));
  if (i > 0) {
    const Rgb rv = p_.film.reflectance(v.z, p_.film_eta_base), rl = p_.film.reflectance(std::abs(l.z), p_.film_eta_base);
    const Rgb rmax(std::max(rv.r, rl.r), std::max(rv.g, rl.g), std::max(rv.b, rl.b));
    base += (1.0 - rmax) * (i * b_u);
  }
  return p_.rho_d * base;
}

double DiffuseBase::pdf(const Vec3& v, const Vec3& l) const {
  if (v.z <= 0) return 0.0;
  const double pt = p_.translucency;
  return (1.0 - pt) * cosine_hemisphere_pdf(l) + pt * cosine_hemisphere_pdf(-l);
}

BsdfSample DiffuseBase::sample(const Vec3& v, const Vec3& u) const {
  BsdfSample s;
  if (v.z <= 0) return s;
  s.l = sample_cosine_hemisphere(u.y, u.z);
  const bool transmit = u.x < p_.translucency;  // u.x is a fresh uniform for this choice
  if (transmit) s.l = -s.l;
  return make_sample(*this, v, s.l, (transmit ? kLobeTransmission : kLobeReflection) | kLobeDiffuse);
}

uint32_t DiffuseBase::flags() const {
  return kLobeDiffuse | (p_.translucency < 1 ? kLobeReflection : 0u) | (p_.translucency > 0 ? kLobeTransmission : 0u);
}

double DiffuseBase::sampling_weight(const Vec3& v) const {
  LobeCache none;
  return sampling_weight(v, none);
}

double DiffuseBase::sampling_weight(const Vec3& v, LobeCache& cache) const {
  if (v.z <= 0) return 0.0;
  const double s = p_.specular, i = p_.film_weight;
  double w = (1.0 - i) * ((1.0 - s) + s * missing(v.z, cache) * (inv_norm_ > 0 ? 1.0 : 0.0));
  if (i > 0) w += i * (1.0 - mean(p_.film.reflectance(v.z, p_.film_eta_base)));
  return std::max(0.0, mean(p_.rho_d) * w);
}

}  // namespace dspbr
