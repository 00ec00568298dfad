// Helmholtz reciprocity of a BSDF (Veach 1997, ch. 5-6):
//  - reflection (v, l on the same side):   f(v, l) = f(l, v);
//  - refraction (v, l on opposite sides):  f(v, l) / eta_v^2 = f(l, v) / eta_l^2, where eta_x is the
//    index of refraction of the medium that direction x lies in (radiance BSDF: radiance is
//    compressed by (eta_t/eta_i)^2 when crossing into a denser medium).
// The check draws random direction pairs and reports the maximum relative deviation
// |a - b| / max(a, b) per kind of pair. The plain symmetry f(v,l) = f(l,v) of transmission pairs is
// reported as well, so that a BSDF following a different convention is recognised.
#pragma once
#include <cstddef>
#include <cstdint>

#include "dspbr/bsdf/bsdf.h"

namespace dspbr::validate {

struct ReciprocityStats {
  std::size_t pairs = 0;        // pairs evaluated with max(a, b) above the floor
  double max_rel_dev = 0;       // max over pairs and channels of |a - b| / max(a, b)
  Vec3 worst_v, worst_l;        // the pair where it happens
  double worst_a = 0, worst_b = 0;
};

struct ReciprocityResult {
  ReciprocityStats reflection_upper;     // v.z > 0, l.z > 0
  ReciprocityStats reflection_lower;     // v.z < 0, l.z < 0 (volumetric: viewer inside)
  ReciprocityStats transmission_eta2;    // opposite sides, eta^2 rule
  ReciprocityStats transmission_plain;   // opposite sides, plain symmetry (for information)
  ReciprocityStats transmission_adjoint; // opposite sides, f(v,l) / eta_l^2 = f(l,v) / eta_v^2 (the
                                         // adjoint rule: eta^2 of the light's medium in f(v, l))
};

struct ReciprocitySettings {
  std::size_t pairs = 20000;   // random pairs per kind
  double eta_above = 1.0;      // index of refraction of the medium on the +z side
  double eta_below = 1.0;      // ... on the -z side (the material's IOR for volumetric boundaries)
  // Pairs where both values are below this are skipped (relative deviation meaningless there).
  double floor = 1e-12;
  uint64_t seed = 1;
};

ReciprocityResult reciprocity_check(const Bsdf& bsdf, const ReciprocitySettings& s);

}  // namespace dspbr::validate
