// Generated lookup code for the renderer layout (tables/renderer_luts.h): the same functions in
// three dialects, written by `dspbr lut` next to the tables (docs/luts.md, "Using the tables in
// your renderer"):
//   dspbr_lookup.h     C99 / C++, tables embedded, only <math.h>
//   dspbr_lookup.glsl  GLSL (4.50 / ES 3.00): tables as constant arrays, or textures with
//                      #define DSPBR_LOOKUP_TEXTURES (bindings and packing in the file's header)
//   dspbr_lookup.hlsl  HLSL (SM 5+): the same, Texture2D with DSPBR_LOOKUP_TEXTURES
// The function bodies of the three are one text (GLSL syntax; C spells the math functions and
// casts its own way), so what the shaders compute is what the C header computes.
//
// Functions (cos theta first everywhere):
//   float dspbr_ggx_E(float cos_theta, float roughness)            E_m
//   float dspbr_ggx_E_avg(float roughness)                         E_m,avg
//   float dspbr_ggx_E_avg_missing(float roughness)                 1 - E_m,avg (no cancellation)
//   float dspbr_ggx_beta(float cos_theta, float roughness)         beta = B / E_m (Schlick moment)
//   float dspbr_base_E(float cos_theta, float roughness, float f0) E (Base_E)
//   float dspbr_base_E_avg(float roughness, float f0)              E_avg (Base_E_avg)
//   float dspbr_base_E_avg_given(float roughness, float f0, float missing)   the same, given
//                                                                  missing = 1 - E_m,avg(roughness)
//   float dspbr_sheen_E(float cos_theta, float alpha_b)            E_b, main sheen
//   float dspbr_sheen_ash_E(float cos_theta, float alpha_b)        E_b, alternative sheen
//   float dspbr_fresnel_ms(float f0, float f90, float e_avg)       F_ms (per colour channel)
//   float dspbr_ms_lobe(float cos_v, float cos_l, float roughness) M_r,ms / F_ms
//   float dspbr_diffuse_bc(float cos_v, float cos_l, float roughness, float f0)   B_c / rho
//   float dspbr_sheen_layer_scale(float cos_v, float cos_l, float alpha_b, float rho_hat)
//   float dspbr_sheen_ash_layer_scale(...)                          the same, alternative sheen
//   DSPBR_LOOKUP_FLOATS                                            stored table values
#pragma once
#include <string>

#include "dspbr/tables/renderer_luts.h"

namespace dspbr {

enum class LookupDialect { C, Glsl, Hlsl };

// The text of the generated file for `luts` in `dialect`. `provenance` is one line written into
// the file's header comment (e.g. the version and command that made it).
std::string lookup_code(const RendererLuts& luts, LookupDialect dialect, const std::string& provenance);

// File name of a dialect: dspbr_lookup.h / .glsl / .hlsl.
const char* lookup_file_name(LookupDialect dialect);

// The rough-glass lookups beyond DSPBR 2025x (requires luts.has_glass()), a second file per dialect
// (dspbr_glass_lookup.h / .glsl / .hlsl) to include after the first; its textures take the
// bindings after the first file's six. Functions (inside, transmission: 0 or 1):
//   float dspbr_glass_E(float cos_theta, float roughness, float ior, int inside)     E_g
//   float dspbr_glass_E_avg(float roughness, float ior, int inside)                  E_g,avg
//   float dspbr_glass_core_E(...), dspbr_glass_core_E_avg(...)   E_g + F_ms (1 - E_m): the white core
//   float dspbr_glass_transmission_share(float roughness, float ior, int inside)    x_o or x_i
//   float dspbr_glass_compensation(float cos_v, float cos_l, float roughness, float ior, int inside,
//                                  int transmission)             the compensation lobe per unit colour
//   float dspbr_thin_glass_compensation(float cos_v, float cos_l, float roughness, float ior,
//                                       int transmission)        the same, thin-walled
//   DSPBR_GLASS_LOOKUP_FLOATS                                    stored table values
std::string glass_lookup_code(const RendererLuts& luts, LookupDialect dialect, const std::string& provenance);
const char* glass_lookup_file_name(LookupDialect dialect);

// The thin film's spectral sensitivity (bsdf/thin_film.h, ThinFilmSensitivity) for the shader
// library's C++ compile, dspbr_thin_film_lookup.h (C99 / C++): DSPBR_THIN_FILM_S_SAMPLES,
// _STEP, _X_END, dspbr_thin_film_S_nu[3] and dspbr_thin_film_S_at(k, i) (sample k, value i of the
// six), in float. Not a table of `dspbr lut`'s settings: the same for every run.
std::string thin_film_lookup_code();
const char* thin_film_lookup_file_name();

}  // namespace dspbr
