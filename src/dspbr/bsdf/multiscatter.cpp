#include "dspbr/bsdf/multiscatter.h"

#include <algorithm>

#include "dspbr/bsdf/sampling.h"

namespace dspbr {

MultiScatterReflection::MultiScatterReflection(double r_uv, const Rgb& f_ms, const LutSet& luts)
    : f_ms_(f_ms), e_m_(AlbedoSlice::E_m(luts, r_uv)) {
  const double missing_avg = luts.missing_E_m_avg(r_uv);
  inv_norm_ = missing_avg > kMinMissingEnergy ? 1.0 / (kPi * missing_avg) : 0.0;
}

double MultiScatterReflection::missing(double cos_theta) const {
  LobeCache none;
  return missing(cos_theta, none);
}

Rgb MultiScatterReflection::eval(const Vec3& v, const Vec3& l) const {
  LobeCache none;
  return eval(v, l, none);
}

double MultiScatterReflection::pdf(const Vec3& v, const Vec3& l) const {
  return v.z > 0 ? cosine_hemisphere_pdf(l) : 0.0;
}

BsdfSample MultiScatterReflection::sample(const Vec3& v, const Vec3& u) const {
  BsdfSample s;
  if (v.z <= 0) return s;
  s.l = sample_cosine_hemisphere(u.y, u.z);
  return make_sample(*this, v, s.l, kLobeReflection | kLobeDiffuse);
}

double MultiScatterReflection::sampling_weight(const Vec3& v) const {
  LobeCache none;
  return sampling_weight(v, none);
}

double MultiScatterReflection::sampling_weight(const Vec3& v, LobeCache& cache) const {
  if (v.z <= 0 || inv_norm_ == 0) return 0.0;
  return std::max(0.0, mean(f_ms_)) * missing(v.z, cache);
}

}  // namespace dspbr
