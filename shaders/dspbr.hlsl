// The DSPBR 2025x BSDF for HLSL (Shader Model 6; here compiled to SPIR-V by glslang's HLSL front
// end): the shader library's body (shaders/dspbr/*.glsl, the same source the C++ and GLSL entries
// compile). Include path: this folder and the generated lookups' folder; the tables are
// textures (registers: dspbr_lookup.hlsl) unless DSPBR_LOOKUP_ARRAYS is defined. Usage: docs/renderer.md.
#ifndef DSPBR_HLSL_INCLUDED
#define DSPBR_HLSL_INCLUDED
// The tables: textures unless DSPBR_LOOKUP_ARRAYS asks for constant arrays (slow to compile on
// some drivers: docs/renderer.md, "Tables").
// DSPBR_USE_FITS: the LUT-free fits instead (fits/dspbr_fits.hlsl on the include path; no table).
#ifdef DSPBR_USE_FITS
#include "dspbr_fits.hlsl"
#else
#if !defined(DSPBR_LOOKUP_ARRAYS) && !defined(DSPBR_LOOKUP_TEXTURES)
#define DSPBR_LOOKUP_TEXTURES
#endif
#include "dspbr_lookup.hlsl"
#endif
#include "dspbr/interop.hlsl"
#include "dspbr/features.glsl"
#ifdef DSPBR_USE_FITS
#include "dspbr/fits.glsl"
#endif
#include "dspbr/math.glsl"
#include "dspbr/material.glsl"
#include "dspbr/gltf.glsl"
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
