// The shader library (HLSL entry, texture mode) over conformance vectors on a Vulkan device
// (shader_vk_conformance): register u0 the records, u1 the results, the tables from t2; push
// constants: the invocation count and the mode (kernel_common.glsl).
#define DSPBR_LOOKUP_TEXTURES
#include "dspbr.hlsl"
[[vk::binding(0, 0)]] RWStructuredBuffer<float> rec : register(u0);
[[vk::binding(1, 0)]] RWStructuredBuffer<float> res : register(u1);
struct Push { uint count; uint mode; };
[[vk::push_constant]] ConstantBuffer<Push> push;
#include "albedo.glsl"
#include "kernel_common.glsl"
[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  if (id.x < push.count) dspbr_test_run(id.x, push.mode);
}
