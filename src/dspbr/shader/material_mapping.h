// The reference's material and options (dspbr::Material, dspbr::BsdfOptions) as the shader
// library's DspbrMaterial and DspbrOptions, field by field (the same names; double -> float, an
// infinite attenuation distance -> FLT_MAX as material.glsl's default): how a C++ host hands the
// project's materials to the shader library (`dspbr conformance run`, the shader tests, the
// benchmarks).
#pragma once
#include "dspbr.h"
#include "dspbr/bsdf/lobe_assembly.h"
#include "dspbr/material.h"

namespace dspbr::shader {

dspbr_shader::DspbrMaterial to_shader_material(const Material& m);
dspbr_shader::DspbrOptions to_shader_options(const BsdfOptions& o);

}  // namespace dspbr::shader
