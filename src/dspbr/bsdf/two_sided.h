// Two-sided evaluation (Mitsuba's twosided, generalised to volume boundaries): for a viewer on the
// back side, f(v, l) = f_back(-v, -l): the back face is the same surface seen from the other side
// (its shading normal is -n, its tangent -t; GGX is symmetric under that half turn). This keeps
// f(v, l) = f(l, v) for thin-walled transmission with normal maps. The back side is v.n < 0
// (shading normal n) for thin-walled materials and v.z < 0 (geometric: inside the object) for
// volume boundaries. Side: anything with eval, pdf, sample, delta_probability and flags for v on
// its front (bsdf/cut_out.h).
#pragma once
#include <array>

#include "dspbr/bsdf/bsdf.h"

namespace dspbr {

template <class Side>
class TwoSided {
 public:
  TwoSided() = default;
  // sides[0]: v on the front, sides[1]: v on the back (evaluated with -v, -l); n: the shading
  // normal that decides the side when by_shading_normal, else the geometric z.
  TwoSided(std::array<Side, 2> sides, bool by_shading_normal, const Vec3& n)
      : sides_(std::move(sides)), by_shading_normal_(by_shading_normal), n_(n) {}

  bool back_side(const Vec3& v) const { return by_shading_normal_ ? dot(v, n_) < 0 : v.z < 0; }
  const Side& side(bool back) const { return sides_[back]; }

  Rgb eval(const Vec3& v, const Vec3& l) const {
    const bool back = back_side(v);
    return back ? sides_[1].eval(-v, -l) : sides_[0].eval(v, l);
  }
  double pdf(const Vec3& v, const Vec3& l) const {
    const bool back = back_side(v);
    return back ? sides_[1].pdf(-v, -l) : sides_[0].pdf(v, l);
  }
  double delta_probability(const Vec3& v) const {
    const bool back = back_side(v);
    return back ? sides_[1].delta_probability(-v) : sides_[0].delta_probability(v);
  }
  BsdfSample sample(const Vec3& v, const Vec3& u) const {
    const bool back = back_side(v);
    BsdfSample s = sides_[back].sample(back ? -v : v, u);
    if (back && s.valid) s.l = -s.l;
    return s;
  }
  uint32_t flags() const { return sides_[0].flags() | sides_[1].flags(); }

 private:
  std::array<Side, 2> sides_;
  bool by_shading_normal_ = true;
  Vec3 n_{0, 0, 1};
};

}  // namespace dspbr
