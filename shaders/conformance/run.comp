// `dspbr conformance run --glsl FILE` compiles this entry (glslangValidator -V) with the user's file
// as "dspbr_conformance_user" (written by the kit: a #line naming FILE, then FILE's text), the
// shader library and the lookups on the include path. Bindings: 0 the vector records, 1 the
// results, the tables from 2 (texture mode); push constant: the vector count of the batch.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_GOOGLE_cpp_style_line_directive : require
layout(local_size_x = 64) in;
#define DSPBR_LOOKUP_TEXTURES
#define DSPBR_LOOKUP_BINDING_BASE 2
#include "dspbr.glsl"
layout(std430, set = 0, binding = 0) readonly buffer DspbrConformanceRecords { float rec[]; };
layout(std430, set = 0, binding = 1) writeonly buffer DspbrConformanceResults { float res[]; };
layout(push_constant) uniform DspbrConformancePush { uint count; } dspbr_conformance_push;
#include "conformance/kit.glsl"
#include "dspbr_conformance_user"
#include "conformance/kit_driver.glsl"
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < dspbr_conformance_push.count) dspbr_conformance_run(i);
}
