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
