// Per-call memo of the table values that several lobes of one mixture read at the same cosine:
// the E_m part of the core's table slices (lut/albedo_slice.h), read at v.n and l.n by both the
// multiple-scattering lobe and the diffuse base (one warp and one E_m lookup per direction instead
// of two). LobeMixture makes one per eval / selection on the stack; a lobe evaluated alone uses an
// empty one, so the values are the same either way. Keyed by the slice's E_m identity and the
// cosine, so a hit returns exactly what the slice computes.
#pragma once
#include <array>

#include "dspbr/lut/albedo_slice.h"

namespace dspbr {

class LobeCache {
 public:
  // slice(cos_theta), its E_m part computed once per (E_m identity, cos_theta).
  double albedo(const AlbedoSlice& slice, double cos_theta) {
    const AlbedoSlice::EmKey key = slice.e_m_key();
    if (!key.fingerprint) return slice(cos_theta);
    for (int k = 0; k < n_; ++k)
      if (entries_[size_t(k)].key == key && entries_[size_t(k)].cos_theta == cos_theta)
        return slice.from_e_m_part(cos_theta, entries_[size_t(k)].part);
    const AlbedoSlice::EmPart part = slice.e_m_part(cos_theta);
    if (n_ < int(entries_.size())) entries_[size_t(n_++)] = {key, cos_theta, part};
    return slice.from_e_m_part(cos_theta, part);
  }

 private:
  struct Entry {
    AlbedoSlice::EmKey key;
    double cos_theta;
    AlbedoSlice::EmPart part;
  };
  std::array<Entry, 4> entries_;
  int n_ = 0;
};

}  // namespace dspbr
