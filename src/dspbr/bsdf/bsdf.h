// The BSDF interface every DSPBR lobe and the full material implement (pbrt-v4 / Mitsuba 3 style).
//
// Conventions (all lobes, all tools):
// - Directions are unit vectors in the local shading frame: tangent = +x, bitangent = +y,
//   normal = +z. Both v (towards the viewer) and l (towards the light) point AWAY from the
//   surface. v may lie below the surface (v.z < 0: the viewer is inside a volumetric object).
// - eval(v, l) returns f(v, l) WITHOUT the cosine factor |l.n|, for the non-delta lobes only.
// - pdf(v, l) is the solid-angle density with which sample(v, .) produces l through its
//   non-delta lobes. It integrates over the sphere to 1 - P(delta lobes) - P(failed samples).
// - sample(v, u) draws l. For a non-delta sample: pdf = pdf(v, l) (the full mixture density) and
//   weight = eval(v, l) |l.n| / pdf. For a delta sample (perfectly smooth lobe): flags has Delta,
//   pdf is the discrete probability of choosing that lobe, and weight = (lobe reflectance or
//   transmittance, Fresnel included) / pdf. A sample that fails (absorbed, below the horizon)
//   has valid = false.
#pragma once
#include <cmath>
#include <cstdint>

#include "dspbr/vec3.h"

namespace dspbr {

enum LobeFlags : uint32_t {
  kLobeNone = 0,
  kLobeReflection = 1u << 0,
  kLobeTransmission = 1u << 1,
  kLobeDelta = 1u << 2,    // perfectly smooth: pdf is a Dirac in solid angle
  kLobeGlossy = 1u << 3,
  kLobeDiffuse = 1u << 4,
};

struct BsdfSample {
  Vec3 l;             // sampled direction (unit, local frame)
  Rgb weight;         // f |cos| / pdf (non-delta), reflectance / probability (delta)
  double pdf = 0;     // solid-angle density (non-delta) or discrete probability (delta)
  uint32_t flags = kLobeNone;
  bool valid = false;
};

class Bsdf {
 public:
  virtual ~Bsdf() = default;
  virtual Rgb eval(const Vec3& v, const Vec3& l) const = 0;
  virtual double pdf(const Vec3& v, const Vec3& l) const = 0;
  // u: three independent uniform numbers in [0, 1) (lobe choice + 2D direction).
  virtual BsdfSample sample(const Vec3& v, const Vec3& u) const = 0;
  // Union of the flags of the lobes this BSDF can produce (for reports and masks).
  virtual uint32_t flags() const = 0;
};

// The non-delta sample of `bsdf` in direction l, by the conventions above: pdf = bsdf.pdf(v, l),
// weight = eval(v, l) |l.n| / pdf; invalid (a failed sample) where the pdf is 0.
inline BsdfSample make_sample(const Bsdf& bsdf, const Vec3& v, const Vec3& l, uint32_t flags) {
  BsdfSample s;
  s.l = l;
  s.pdf = bsdf.pdf(v, l);
  if (!(s.pdf > 0)) return s;
  s.weight = bsdf.eval(v, l) * (std::abs(l.z) / s.pdf);
  s.flags = flags;
  s.valid = true;
  return s;
}

}  // namespace dspbr
