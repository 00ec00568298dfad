#include "dspbr/bsdf/thin_transmission.h"

#include "dspbr/bsdf/sampling.h"

namespace dspbr {

ThinTransmission::ThinTransmission(double alpha_u, double alpha_v, CosineFactor factor)
    : reflection_(alpha_u, alpha_v, std::move(factor)) {}

Rgb ThinTransmission::eval(const Vec3& v, const Vec3& l) const {
  if (l.z >= 0) return Rgb(0);
  return reflection_.eval(v, flip_z(l));  // M_r(v, l', h_r') factor(v.h_r')
}

double ThinTransmission::pdf(const Vec3& v, const Vec3& l) const { return reflection_.pdf(v, flip_z(l)); }

BsdfSample ThinTransmission::sample(const Vec3& v, const Vec3& u) const {
  BsdfSample s = reflection_.sample(v, u);
  if (!s.valid) return s;
  s.l = flip_z(s.l);
  if (s.flags & kLobeDelta) {
    s.flags = kLobeTransmission | kLobeDelta;
    return s;
  }
  s.weight = eval(v, s.l) * (std::abs(s.l.z) / s.pdf);
  s.flags = kLobeTransmission | kLobeGlossy;
  return s;
}

uint32_t ThinTransmission::flags() const {
  return kLobeTransmission | (is_delta() ? kLobeDelta : kLobeGlossy);
}

double ThinTransmission::sampling_weight(const Vec3& v) const { return reflection_.sampling_weight(v); }

}  // namespace dspbr
