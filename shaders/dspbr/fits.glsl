// DSPBR_USE_FITS: the body's table reads over the LUT-free fits of fits/dspbr_fits.* (docs/fits.md)
// instead of the generated lookups: no texture to bind, no table in memory, the fits' accuracy
// (docs/renderer.md, "Tables or fits"). Each function has the name and meaning of the lookup it
// replaces (src/dspbr/lutgen/lookup_codegen.h).

// E_m(mu; r).
DSPBR_FN float dspbr_ggx_E(float cos_theta, float roughness) { return dspbr_fit_ggx_E(cos_theta, roughness); }
// 1 - E_m(mu; r) (the fits' own precision: no better than 1 - E_m).
DSPBR_FN float dspbr_ggx_E_missing(float cos_theta, float roughness) {
  return clamp(1.0f - dspbr_fit_ggx_E(cos_theta, roughness), 0.0f, 1.0f);
}
// 1 - E_m,avg(r) and E_m,avg(r).
DSPBR_FN float dspbr_ggx_E_avg_missing(float roughness) { return dspbr_fit_ggx_E_avg_loss(roughness); }
DSPBR_FN float dspbr_ggx_E_avg(float roughness) { return dspbr_fit_ggx_E_avg(roughness); }
// beta = B / E_m, B the Schlick moment (the fit's E5); 0 where E_m is.
DSPBR_FN float dspbr_ggx_beta(float cos_theta, float roughness) {
  float e = dspbr_fit_ggx_E(cos_theta, roughness);
  return e > 0.0f ? dspbr_fit_detail_ggx_E5(cos_theta, roughness) / e : 0.0f;
}
// 1 - E_m and beta at once.
struct DspbrGgxMissingBeta {
  float missing;
  float beta;
};
DSPBR_FN DspbrGgxMissingBeta dspbr_lut_ggx_missing_beta(float cos_theta, float roughness, int with_beta) {
  DspbrGgxMissingBeta a;
  a.missing = dspbr_ggx_E_missing(cos_theta, roughness);
  a.beta = with_beta != 0 ? dspbr_ggx_beta(cos_theta, roughness) : 0.0f;
  return a;
}
DSPBR_FN DspbrGgxMissingBeta dspbr_ggx_E_missing_beta(float cos_theta, float roughness) {
  return dspbr_lut_ggx_missing_beta(cos_theta, roughness, 1);
}
// E_avg(r, f0); the lookups' form given 1 - E_m,avg(r) as well, which the fit of E_avg does not read.
DSPBR_FN float dspbr_base_E_avg(float roughness, float f0) { return dspbr_fit_base_E_avg(roughness, clamp(f0, 0.0f, 1.0f)); }
DSPBR_FN float dspbr_base_E_avg_given(float roughness, float f0, float /* 1 - E_m,avg */) { return dspbr_base_E_avg(roughness, f0); }
// E_b(mu; alpha_b) of the two sheen models.
DSPBR_FN float dspbr_sheen_E(float cos_theta, float alpha_b) { return dspbr_fit_sheen_E(cos_theta, alpha_b); }
DSPBR_FN float dspbr_sheen_ash_E(float cos_theta, float alpha_b) { return dspbr_fit_sheen_ash_E(cos_theta, alpha_b); }
// F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg = 20/21 f0 + 1/21 f90 (spec eq. multiscatter),
// clamped as the lookups' dspbr_fresnel_ms (the fits give it for f90 = 1 only).
DSPBR_FN float dspbr_fresnel_ms(float f0, float f90, float e_avg) {
  float e = clamp(e_avg, 0.0f, 1.0f);
  float fa = clamp(f0, 0.0f, 1.0f) * (20.0f / 21.0f) + clamp(f90, 0.0f, 1.0f) * (1.0f / 21.0f);
  float d = 1.0f - fa * (1.0f - e);
  return d > 0.0f ? fa * fa * e / d : 1.0f;
}
