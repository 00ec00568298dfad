// The shader library's C++ compile (shaders/dspbr.h, float) behind the reference's Bsdf interface
// (double in and out, float inside): one prepared DspbrBsdf per material, so that the validation's
// checks (white furnace, chi-square, stability, reciprocity) run on the library as they run on the
// reference (`dspbr validate`, section "The shader library"; the shader tests).
#pragma once
#include <cstdint>

#include "dspbr.h"
#include "dspbr/bsdf/bsdf.h"
#include "dspbr/bsdf/lobe_assembly.h"
#include "dspbr/material.h"

namespace dspbr::shader {

class ShaderBsdf : public Bsdf {
 public:
  ShaderBsdf(const Material& m, const BsdfOptions& o);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override;
  Rgb emission(const Vec3& v) const;
  const dspbr_shader::DspbrBsdf& prepared() const { return b_; }

 private:
  dspbr_shader::DspbrBsdf b_;
};

}  // namespace dspbr::shader
