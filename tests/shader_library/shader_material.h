// Host-side helpers of the shader-library tests (tests/shader_library/): the reference material
// (dspbr::Material) as the shader library's DspbrMaterial, field by field (the same names), its
// packing into the float records the device kernels read (kernel_common.glsl, in pack_record's
// order), the verdict on a set of results, and the library behind the reference's Bsdf interface.
#pragma once
#include <string>
#include <vector>

#include "dspbr.h"
#include "dspbr/bsdf/bsdf.h"
#include "dspbr/bsdf/lobe_assembly.h"
#include "dspbr/conformance/vector.h"
#include "dspbr/conformance/vector_set.h"
#include "dspbr/material.h"

namespace shader_test {

dspbr_shader::DspbrMaterial to_shader_material(const dspbr::Material& m);
dspbr_shader::DspbrOptions to_shader_options(const dspbr::BsdfOptions& o);

// One vector's record for the device kernels: the material fields the BSDF reads, the options,
// v and l (kRecordFloats floats).
constexpr int kRecordFloats = 64;
void pack_record(const dspbr::conformance::Vector& v, float* out);

// Per-vector results of an implementation and the verdict against each vector's tolerances:
// f cos (per channel) and the pdf. Prints a line per group and the failures (at most `show`);
// returns the number of failing vectors among the supported ones.
struct Outcome {
  dspbr_shader::vec3 f_cos;
  float pdf;
};
int judge(const std::vector<dspbr::conformance::Vector>& vectors, const std::vector<Outcome>& results,
          const std::string& what, int show = 12);

}  // namespace shader_test

namespace shader_test {

// The shader library's C++ compile behind the reference's Bsdf interface (double in and out,
// float inside), so that the validation's checks (chi-square, stability, reciprocity) run on it.
class ShaderBsdf : public dspbr::Bsdf {
 public:
  ShaderBsdf(const dspbr::Material& m, const dspbr::BsdfOptions& o);
  dspbr::Rgb eval(const dspbr::Vec3& v, const dspbr::Vec3& l) const override;
  double pdf(const dspbr::Vec3& v, const dspbr::Vec3& l) const override;
  dspbr::BsdfSample sample(const dspbr::Vec3& v, const dspbr::Vec3& u) const override;
  uint32_t flags() const override;
  dspbr::Rgb emission(const dspbr::Vec3& v) const;
  const dspbr_shader::DspbrBsdf& prepared() const { return b_; }

 private:
  dspbr_shader::DspbrBsdf b_;
};

}  // namespace shader_test
