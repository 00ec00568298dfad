// The GLSL side of the shader library's common subset (shaders/README.md, "The common subset"):
// GLSL 450 already has every type and built-in the body uses; this file only names the keywords
// that differ between C++, GLSL and HLSL, and built-ins HLSL lacks.
#define DSPBR_FN
#define DSPBR_CONST const
#define DSPBR_IN(T) T
#define DSPBR_OUT(T) out T
#define DSPBR_INOUT(T) inout T
#define dspbr_atan2(y, x) atan(y, x)
#define dspbr_umul_extended(a, b, hi, lo) umulExtended(a, b, hi, lo)
