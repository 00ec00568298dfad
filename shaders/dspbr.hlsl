// The DSPBR 2025x BSDF for HLSL (Shader Model 6; here compiled to SPIR-V by glslang's HLSL front
// end): the shader library's body (shaders/dspbr/*.glsl, the same source the C++ and GLSL entries
// compile). Include path: this folder and the generated lookups' folder; the tables are
// textures when DSPBR_LOOKUP_TEXTURES is defined (registers: dspbr_lookup.hlsl), constant arrays
// otherwise. Usage: docs/renderer.md.
#ifndef DSPBR_HLSL_INCLUDED
#define DSPBR_HLSL_INCLUDED
#include "dspbr_lookup.hlsl"
#include "dspbr/interop.hlsl"
#include "dspbr/math.glsl"
#include "dspbr/material.glsl"
#include "dspbr/ggx.glsl"
#include "dspbr/sheen.glsl"
#include "dspbr/sampling.glsl"
#include "dspbr/thin_film.glsl"
#include "dspbr/flakes.glsl"
#include "dspbr/volume.glsl"
#include "dspbr/prepare.glsl"
#include "dspbr/lobes.glsl"
#include "dspbr/bsdf.glsl"
#endif
