// Energy compensation of the transparent core (beyond DSPBR 2025x, whose spec leaves it to "a
// future revision"; docs/bsdf.md, "Transmission compensation"). A separable lobe in the spirit of
// the multiple-scattering lobe of Kulla & Conty 2017 ("Revisiting physically based shading at
// Imageworks", dielectrics), towards the same hemisphere (reflection) or the other (transmission):
//   f(v, l) = c (1 - E_v(|v.n|)) (1 - E_l(|l.n|)) / (pi (1 - E_l,avg))
// with E_v the albedo of the uncompensated core on v's side, E_l the one on l's side (the same
// function for reflection and thin-walled transmission; the other side's for volumetric
// transmission), E_l,avg = 2 Integral E_l mu dmu. Its directional albedo is c (1 - E_v(v.n))
// exactly. Cosine-weighted sampling of l in the lobe's hemisphere.
#pragma once
#include <functional>

#include "dspbr/bsdf/lobe.h"

namespace dspbr {

class TransmissionCompensation : public Lobe {
 public:
  using AlbedoFn = std::function<double(double cos_theta)>;
  // transmission: l in the lower hemisphere; c: colour (split fraction times tint); e_l_avg: the
  // cosine average of e_l. The lobe is zero when 1 - e_l_avg < kMinMissingEnergy (multiscatter.h).
  TransmissionCompensation(bool transmission, const Rgb& c, AlbedoFn e_v, AlbedoFn e_l, double e_l_avg);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override;
  double sampling_weight(const Vec3& v) const override;

 private:
  double missing_v(double c) const;  // 1 - E_v, clamped to [0, 1]
  double missing_l(double c) const;  // 1 - E_l, clamped to [0, 1]
  bool transmission_;
  Rgb c_;
  AlbedoFn e_v_, e_l_;
  double inv_norm_;  // 1 / (pi (1 - E_l,avg)), 0 when nothing is missing
};

}  // namespace dspbr
