// A stand-in for fits/dspbr_fits.hpp under which every table read of the shader library is free:
// each dspbr_fit_* the library reads (shaders/dspbr/fits.glsl) returns one value loaded from a
// global array, which the compiler cannot fold, and does nothing else. dspbr_bench_shader_null
// (CMakeLists.txt) compiles bench/bench_shader.cpp over it (DSPBR_USE_FITS, this folder first on
// the include path): the cost of prepare + eval with lookups of one load each, a floor that no
// lookup, however fast, goes below (docs/design/renderer.md). Not DSPBR: the values are
// placeholders in the range of the real ones (E_m 0.9, E_m,avg 0.95, ...), so that every branch
// a real material takes is taken.
#pragma once

inline float dspbr_null_table[6] = {0.9f, 0.05f, 0.95f, 0.04f, 0.9f, 0.2f};

inline float dspbr_fit_ggx_E(float, float) { return dspbr_null_table[0]; }
inline float dspbr_fit_ggx_E_avg_loss(float) { return dspbr_null_table[1]; }
inline float dspbr_fit_ggx_E_avg(float) { return dspbr_null_table[2]; }
inline float dspbr_fit_detail_ggx_E5(float, float) { return dspbr_null_table[3]; }
inline float dspbr_fit_base_E_avg(float, float) { return dspbr_null_table[4]; }
inline float dspbr_fit_sheen_E(float, float) { return dspbr_null_table[5]; }
inline float dspbr_fit_sheen_ash_E(float, float) { return dspbr_null_table[5]; }
