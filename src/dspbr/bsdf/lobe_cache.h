// Per-call memo of the table values that several lobes of one mixture read at the same cosine:
// the E_m part of the core's table slices (tables/albedo_slice.h), read at v.n and l.n by both the
// multiple-scattering lobe and the diffuse base (one warp and one E_m lookup per direction instead
// of two; the first of them computes both directions' parts side by side, albedos). LobeMixture
// makes one per eval / selection on the stack; a lobe evaluated alone uses an empty one, so the
// values are the same either way. Keyed by the slice's E_m identity and the cosine, so a hit
// returns exactly what the slice computes.
#pragma once
#include <algorithm>

#include "dspbr/tables/albedo_slice.h"

namespace dspbr {

// 1 - E of an albedo read from a table, clamped to [0, 1] (table noise can put E a hair above 1).
inline double missing_energy(double e) { return std::clamp(1.0 - e, 0.0, 1.0); }

class LobeCache {
 public:
  LobeCache() {}  // entries_ stay uninitialised: only the first n_ are read

  // slice(cos_theta), its E_m part computed once per (E_m identity, cos_theta).
  double albedo(const AlbedoSlice& slice, double cos_theta) {
    const AlbedoSlice::EmKey key = slice.e_m_key();
    if (!key.fingerprint) return slice(cos_theta);
    for (int k = 0; k < n_; ++k) {
      const Entry& e = entries_[k];
      if (e.fingerprint == key.fingerprint && e.roughness == key.roughness && e.cos_theta == cos_theta)
        return slice.from_e_m_part(cos_theta, {e.x, e.e_m});
    }
    const AlbedoSlice::EmPart part = slice.e_m_part(cos_theta);
    remember(key, cos_theta, part);
    return slice.from_e_m_part(cos_theta, part);
  }

  // slice(cos_a), slice(cos_b), the E_m parts computed side by side when neither is memoised yet.
  void albedos(const AlbedoSlice& slice, double cos_a, double cos_b, double out[2]) {
    const AlbedoSlice::EmKey key = slice.e_m_key();
    if (!key.fingerprint || n_ != 0) {
      out[0] = albedo(slice, cos_a);
      out[1] = albedo(slice, cos_b);
      return;
    }
    AlbedoSlice::EmPart part[2];
    slice.e_m_parts(cos_a, cos_b, part);
    remember(key, cos_a, part[0]);
    remember(key, cos_b, part[1]);
    out[0] = slice.from_e_m_part(cos_a, part[0]);
    out[1] = slice.from_e_m_part(cos_b, part[1]);
  }

 private:
  // An EmKey, the cosine and its EmPart, as plain members (no per-call zeroing of the memo).
  struct Entry {
    uint64_t fingerprint;
    double roughness, cos_theta, x, e_m;
  };
  static constexpr int kEntries = 4;
  // Keeps an E_m part while there is room (a full memo computes later parts again).
  void remember(const AlbedoSlice::EmKey& key, double cos_theta, const AlbedoSlice::EmPart& part) {
    if (n_ < kEntries) entries_[n_++] = {key.fingerprint, key.roughness, cos_theta, part.x, part.e_m};
  }
  Entry entries_[kEntries];
  int n_ = 0;
};

}  // namespace dspbr
