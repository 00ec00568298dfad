// Cut-out (spec "Cut-Out"): a BSDF seen through a mask of opacity alpha. The inner mixture is
// scaled by alpha, and a pass-through Dirac l = -v of weight 1 - alpha joins its lobe selection
// (selection weight 1 - alpha; bsdf/lobe_mixture.h for the rest of the selection rule). The
// pass-through's selection interval sits before the flake lobe (the last in the mixture's order).
#pragma once
#include "dspbr/bsdf/lobe_mixture.h"

namespace dspbr {

class CutOut {
 public:
  CutOut() = default;
  CutOut(LobeMixture inner, double alpha);

  Rgb eval(const Vec3& v, const Vec3& l) const { return inner_.eval(v, l, alpha_); }
  double pdf(const Vec3& v, const Vec3& l) const;
  BsdfSample sample(const Vec3& v, const Vec3& u) const;
  // Total selection probability of the delta lobes and the pass-through for v.
  double delta_probability(const Vec3& v) const;
  uint32_t flags() const;
  const LobeMixture& inner() const { return inner_; }
  double alpha() const { return alpha_; }

 private:
  static constexpr int kMaxSlots = LobeMixture::kMaxLobes + 1;
  // Selection probabilities in selection order (the inner lobes, the pass-through at slot
  // pass_slot when alpha < 1), and those of the inner lobes alone (inner order).
  struct Selection {
    double slot[kMaxSlots];
    double inner[LobeMixture::kMaxLobes];
    int slots = 0, pass = -1;
  };
  Selection select(const Vec3& v) const;
  int inner_index(int slot, int pass) const { return pass >= 0 && slot > pass ? slot - 1 : slot; }

  LobeMixture inner_;
  double alpha_ = 1;
  int pass_slot_ = 0;  // index of the first flake lobe, or the number of lobes
};

}  // namespace dspbr
