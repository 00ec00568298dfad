// The flake layer of GlitteryCore at one shading point: c_f(v, l) B_f(v, l; r_f, n_f) (spec "Flakes",
// "Flake BSDF", "Flip-Flop Effect"), built on the flake texture, cone BSDF and tint of flakes.h.
// In the core shading frame (n_f is relative to it). Sampling: uniform in the cone around
// reflect(v, n_f). A mirror flake (r_f ~ 0, flake_cone_is_delta) is a Dirac whose weight is the
// limit of the cone's reflectance, c_f |l.z| (the cone BSDF has no cosine inside it).
#pragma once
#include "dspbr/bsdf/flakes.h"
#include "dspbr/bsdf/lobe.h"

namespace dspbr {

class FlakeLobe : public Lobe {
 public:
  FlakeLobe(const Vec3& flake_normal, const Material& m);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override { return kLobeReflection | (delta_ ? kLobeDelta : kLobeGlossy); }
  double sampling_weight(const Vec3& v) const override;
  bool is_delta() const override { return delta_; }

 private:
  Vec3 n_f_;
  double cos_cone_;
  bool delta_;
  Rgb rho_f_, rho_ff_;
  double f_f_;
};

}  // namespace dspbr
