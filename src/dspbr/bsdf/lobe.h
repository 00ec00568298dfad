// A single BSDF lobe of the reference material, in its own local frame (its normal = +z).
// Besides the Bsdf interface (eval without cosine, pdf, sample; see bsdf.h) a lobe reports a rough
// estimate of its directional albedo for v, used by MaterialBsdf only to choose which lobe to
// sample (any positive value keeps the estimator unbiased; closer to the albedo = less noise).
//
// Lobes are evaluated with v in the upper hemisphere (v.z > 0): MaterialBsdf mirrors the
// configuration for a viewer below the surface (see material_bsdf.h). A lobe returns 0 for
// v.z <= 0.
#pragma once
#include "dspbr/bsdf/bsdf.h"
#include "dspbr/bsdf/cosine_factor.h"
#include "dspbr/bsdf/lobe_cache.h"

namespace dspbr {

class Lobe : public Bsdf {
 public:
  using Bsdf::eval;
  // Estimate of the lobe's directional albedo for v (>= 0); 0 only when the lobe is zero for v.
  virtual double sampling_weight(const Vec3& v) const = 0;
  // True when the lobe is a Dirac (perfectly smooth): eval and pdf are 0, sample has kLobeDelta.
  virtual bool is_delta() const { return false; }
  // eval and sampling_weight with the per-call memo of the mixture (bsdf/lobe_cache.h); the same
  // values as without. Lobes that read the core's table slices override these.
  virtual Rgb eval(const Vec3& v, const Vec3& l, LobeCache&) const { return eval(v, l); }
  virtual double sampling_weight(const Vec3& v, LobeCache&) const { return sampling_weight(v); }
};

}  // namespace dspbr
