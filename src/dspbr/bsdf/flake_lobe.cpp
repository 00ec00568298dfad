#include "dspbr/bsdf/flake_lobe.h"

#include <algorithm>

#include "dspbr/bsdf/sampling.h"

namespace dspbr {

FlakeLobe::FlakeLobe(const Vec3& flake_normal, const Material& m)
    : n_f_(flake_normal),
      cos_cone_(flake_cos_cone(m.flakeRoughness)),
      delta_(flake_cone_is_delta(cos_cone_)),
      rho_f_(m.flakeColor),
      rho_ff_(m.flipFlopColor),
      f_f_(m.flipFlop) {}

Rgb FlakeLobe::eval(const Vec3& v, const Vec3& l) const {
  if (delta_ || v.z <= 0 || l.z <= 0) return Rgb(0);
  const double b = flake_cone_bsdf(v, l, n_f_, cos_cone_);
  if (b == 0) return Rgb(0);
  return flake_flip_flop_tint(v, l, rho_f_, f_f_, rho_ff_) * b;
}

double FlakeLobe::pdf(const Vec3& v, const Vec3& l) const {
  if (delta_ || v.z <= 0 || l.z <= 0) return 0.0;  // below the horizon: failed sample (bsdf.h)
  return flake_cone_pdf(v, l, n_f_, cos_cone_);
}

BsdfSample FlakeLobe::sample(const Vec3& v, const Vec3& u) const {
  BsdfSample s;
  if (v.z <= 0) return s;
  const FlakeConeSample c = flake_cone_sample(v, n_f_, cos_cone_, u.y, u.z);
  if (!c.valid) return s;
  s.l = c.l;
  if (delta_ || c.delta) {
    if (s.l.z <= 0) return s;  // mirror flake reflecting below the surface
    s.weight = flake_flip_flop_tint(v, s.l, rho_f_, f_f_, rho_ff_) * s.l.z;
    s.pdf = 1.0;
    s.flags = kLobeReflection | kLobeDelta;
    s.valid = true;
    return s;
  }
  return make_sample(*this, v, s.l, kLobeReflection | kLobeGlossy);
}

double FlakeLobe::sampling_weight(const Vec3& v) const {
  if (v.z <= 0 || dot(v, n_f_) <= 0) return 0.0;
  const Vec3 r = reflect(v, n_f_);
  return std::max(0.0, mean(flake_flip_flop_tint(v, r, rho_f_, f_f_, rho_ff_))) * std::max(r.z, 0.0);
}

}  // namespace dspbr
