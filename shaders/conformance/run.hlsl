// `dspbr conformance run --hlsl FILE` compiles this entry (glslangValidator -D -V -S comp -e main)
// with the user's file as "dspbr_conformance_user" (written by the kit: a #line naming FILE, then
// FILE's text), the shader library and the lookups on the include path. Registers: u0 the vector
// records, u1 the results, the tables t0.. at bindings 2.. (texture mode; the compile shifts them:
// --shift-texture-binding 2); push constant: the vector count.
#define DSPBR_LOOKUP_TEXTURES
#include "dspbr.hlsl"
[[vk::binding(0, 0)]] RWStructuredBuffer<float> rec : register(u0);
[[vk::binding(1, 0)]] RWStructuredBuffer<float> res : register(u1);
struct DspbrConformancePush { uint count; };
[[vk::push_constant]] ConstantBuffer<DspbrConformancePush> dspbr_conformance_push;
#include "conformance/kit.glsl"
#include "dspbr_conformance_user"
#include "conformance/kit_driver.glsl"
[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  if (id.x < dspbr_conformance_push.count) dspbr_conformance_run(id.x);
}
