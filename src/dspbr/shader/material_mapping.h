// The reference's material and options (dspbr::Material, dspbr::BsdfOptions) as the shader
// library's DspbrMaterial and DspbrOptions, field by field (the same names; double -> float, an
// infinite attenuation distance -> FLT_MAX as material.glsl's default): how a C++ host hands the
// project's materials to the shader library (`dspbr conformance run`, the shader tests, the
// benchmarks), and one evaluation's inputs as the shader kernels read them.
#pragma once
#include <cstddef>

#include "dspbr.h"
#include "dspbr/bsdf/lobe_assembly.h"
#include "dspbr/material.h"

namespace dspbr::shader {

dspbr_shader::DspbrMaterial to_shader_material(const Material& m);
dspbr_shader::DspbrOptions to_shader_options(const BsdfOptions& o);

// One evaluation's inputs as the kernels read them (shaders/conformance/kit_driver.glsl, the
// record of DSPBR_CONFORMANCE_RECORD_FLOATS floats; tests/shader_library/kernel_common.glsl): the
// material as DSPBR_MATERIAL_PACK writes it, then the sheen model, the object area, the position,
// the object normal, v and l, as floats.
constexpr std::size_t kShaderInputFloats = std::size_t(dspbr_shader::DSPBR_MATERIAL_FLOATS) + 14;
void pack_shader_inputs(const Material& m, const BsdfOptions& o, const Vec3& v, const Vec3& l, float* out);

}  // namespace dspbr::shader
