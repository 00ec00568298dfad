// The DSPBR 2025x BSDF for GLSL 450 (Vulkan, OpenGL 4.5): the shader library's body
// (shaders/dspbr/*.glsl, the same source the C++ and HLSL entries compile). The including shader
// enables `#extension GL_GOOGLE_include_directive : require` and puts this folder and the
// generated lookups' folder on the include path; the tables are textures (bindings:
// dspbr_lookup.glsl) unless DSPBR_LOOKUP_ARRAYS is defined.
// Usage: docs/renderer.md.
#ifndef DSPBR_GLSL_INCLUDED
#define DSPBR_GLSL_INCLUDED
// The tables: textures unless DSPBR_LOOKUP_ARRAYS asks for constant arrays (slow to compile on
// some drivers: docs/renderer.md, "Tables").
// DSPBR_USE_FITS: the LUT-free fits instead (fits/dspbr_fits.glsl on the include path; no table).
#ifdef DSPBR_USE_FITS
#include "dspbr_fits.glsl"
#else
#if !defined(DSPBR_LOOKUP_ARRAYS) && !defined(DSPBR_LOOKUP_TEXTURES)
#define DSPBR_LOOKUP_TEXTURES
#endif
#include "dspbr_lookup.glsl"
#endif
#include "dspbr/interop.glsl"
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
