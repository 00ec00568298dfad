// The HLSL side of the shader library's common subset (shaders/README.md, "The common subset"):
// the GLSL names the body uses for HLSL's (vec3 is float3, mix is lerp) and the keywords that
// differ between C++, GLSL and HLSL.
#define vec3 float3
#define mix lerp
#define DSPBR_FN
#define DSPBR_CONST static const
#define DSPBR_IN(T) T
#define DSPBR_OUT(T) out T
#define DSPBR_INOUT(T) inout T
#define dspbr_atan2(y, x) atan2(y, x)
// GLSL's umulExtended (HLSL has no 32 x 32 -> 64 product): from 16-bit halves.
void dspbr_umul_extended(uint a, uint b, out uint hi, out uint lo) {
  uint a0 = a & 0xFFFFu, a1 = a >> 16u, b0 = b & 0xFFFFu, b1 = b >> 16u;
  uint p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  uint mid = (p00 >> 16u) + (p01 & 0xFFFFu) + (p10 & 0xFFFFu);
  hi = p11 + (p01 >> 16u) + (p10 >> 16u) + (mid >> 16u);
  lo = (p00 & 0xFFFFu) | (mid << 16u);
}
