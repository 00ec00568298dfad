#include "dspbr/bsdf/cut_out.h"

#include <algorithm>
#include <cmath>

namespace dspbr {

CutOut::CutOut(LobeMixture inner, double alpha) : inner_(std::move(inner)), alpha_(std::clamp(alpha, 0.0, 1.0)) {
  pass_slot_ = inner_.size();
  for (int k = 0; k < inner_.size(); ++k)
    if (inner_.layer(k) == LobeMixture::Layer::Flake) {
      pass_slot_ = k;
      break;
    }
}

CutOut::Selection CutOut::select(const Vec3& v) const {
  Selection s;
  const int n = inner_.size();
  double w[LobeMixture::kMaxLobes];
  inner_.selection_weights(v, alpha_, w);
  s.pass = alpha_ < 1 ? pass_slot_ : -1;
  s.slots = n + (s.pass >= 0 ? 1 : 0);
  bool present[kMaxSlots];
  for (int j = 0; j < s.slots; ++j) {
    // A lobe scaled by a zero opacity stays at 0; the pass-through only when alpha < 1.
    const bool pass = j == s.pass;
    s.slot[j] = pass ? 1.0 - alpha_ : w[inner_index(j, s.pass)];
    present[j] = pass ? true : alpha_ > 0;
  }
  select_lobes(s.slot, present, s.slots);
  for (int j = 0; j < s.slots; ++j)
    if (j != s.pass) s.inner[inner_index(j, s.pass)] = s.slot[j];
  return s;
}

double CutOut::pdf(const Vec3& v, const Vec3& l) const { return inner_.pdf(v, l, select(v).inner); }

double CutOut::delta_probability(const Vec3& v) const {
  const Selection s = select(v);
  double p = 0;
  for (int j = 0; j < s.slots; ++j)
    if (j == s.pass || inner_.lobe(inner_index(j, s.pass)).is_delta()) p += s.slot[j];
  return p;
}

BsdfSample CutOut::sample(const Vec3& v, const Vec3& u) const {
  BsdfSample out;
  const Selection s = select(v);
  // Choose a slot with u.x and rescale u.x to [0, 1) inside the chosen interval.
  // (Rounding of the cumulative sum: u.x beyond it picks the last slot with a non-zero probability.)
  const int n = s.slots;
  int k = n, last = n;
  double cum = 0, cum_last = 0;
  for (int j = 0; j < n; ++j) {
    if (!(s.slot[j] > 0)) continue;
    if (u.x < cum + s.slot[j]) {
      k = j;
      break;
    }
    last = j;
    cum_last = cum;
    cum += s.slot[j];
  }
  if (k == n) {
    if (last == n) return out;  // nothing to sample
    k = last;
    cum = cum_last;
  }
  const double p = s.slot[k];
  if (k == s.pass) {  // pass-through: l = -v, weight (1 - alpha) / P
    out.l = -v;
    out.weight = Rgb((1.0 - alpha_) / p);
    out.pdf = p;
    out.flags = kLobeTransmission | kLobeDelta;
    out.valid = true;
    return out;
  }
  const double ux = std::clamp((u.x - cum) / p, 0.0, std::nextafter(1.0, 0.0));
  return inner_.sample_lobe(inner_index(k, s.pass), v, {ux, u.y, u.z}, alpha_, s.inner);
}

uint32_t CutOut::flags() const {
  return inner_.flags() | (alpha_ < 1 ? uint32_t(kLobeTransmission | kLobeDelta) : 0u);
}

}  // namespace dspbr
