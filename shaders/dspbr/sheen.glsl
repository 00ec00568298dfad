// Sheen: the Charlie distribution with the spec's Smith Lambda fit, or the alternative visibility
// (spec "Sheen"; Conty Estevez & Kulla 2017; [NP13]), as in the reference (src/dspbr/sheen.h).

// Smallest alpha_b (D_b is undefined at 0; the reference's kMinAlphaB).
DSPBR_CONST float dspbr_min_alpha_b = 0.00390625f;  // 1/256

// D_b(h) = (2 + 1/alpha_b) sin^(1/alpha_b)(theta_h) / (2 pi) (spec "Sheen"), h a unit vector.
// sin^2 = h.x^2 + h.y^2, not 1 - cos^2: near h = n the difference loses the digits (in float,
// 4e-3 of D_b at theta_h = 0.004 for alpha_b = 1).
DSPBR_FN float dspbr_charlie_D(vec3 h, float alpha_b) {
  if (!(h.z > 0.0f)) return 0.0f;
  float inv_a = 1.0f / alpha_b;
  float sin2 = min(1.0f, h.x * h.x + h.y * h.y);
  return (2.0f + inv_a) * pow(sin2, 0.5f * inv_a) / (2.0f * dspbr_pi);
}

// The fit row p(alpha_b) = (1 - w) p0 + w p1, w = c0 / (1 + c1 alpha_b^c2) + c3 (spec Tables
// sheen-lambda-fit and -w, read as docs/sheen_lambda.md records).
struct DspbrSheenLambda {
  float p0;
  float p1;
  float p2;
  float p3;
  float p4;
  float l_half;  // L(0.5)
};
DSPBR_FN float dspbr_sheen_L(DspbrSheenLambda s, float x) {
  return s.p0 / (1.0f + s.p1 * pow(x, s.p2)) + s.p3 * x + s.p4;
}
DSPBR_FN DspbrSheenLambda dspbr_sheen_lambda_fit(float alpha_b) {
  float w = -1.59612f / (1.0f + 0.20375f * pow(alpha_b, -0.55825f)) + 1.32805f;
  DspbrSheenLambda s;
  s.p0 = (1.0f - w) * 11.9095f + w * 13.7000f;
  s.p1 = (1.0f - w) * 4.68753f + w * 2.92754f;
  s.p2 = (1.0f - w) * 0.33467f + w * 0.28670f;
  s.p3 = (1.0f - w) * -2.22664f + w * -0.81757f;
  s.p4 = (1.0f - w) * -1.76591f + w * -1.22466f;
  s.l_half = 0.0f;
  s.l_half = dspbr_sheen_L(s, 0.5f);
  return s;
}
// The row of a BSDF without sheen (never read; every field set, so the prepared value is defined).
DSPBR_FN DspbrSheenLambda dspbr_sheen_lambda_unused() {
  DspbrSheenLambda s;
  s.p0 = 0.0f;
  s.p1 = 0.0f;
  s.p2 = 0.0f;
  s.p3 = 0.0f;
  s.p4 = 0.0f;
  s.l_half = 0.0f;
  return s;
}
// Lambda(cos) = exp(L(|cos|)) below 0.5, exp(2 L(0.5) - L(1 - |cos|)) above (spec "Sheen").
DSPBR_FN float dspbr_sheen_Lambda(DspbrSheenLambda s, float c) {
  float x = min(1.0f, abs(c));
  if (x < 0.5f) return exp(dspbr_sheen_L(s, x));
  return exp(2.0f * s.l_half - dspbr_sheen_L(s, 1.0f - x));
}
// M_b = D_b G_b / (4 v.n l.n), G_b = 1 / (1 + Lambda(v) + Lambda(l)) (spec "Sheen"); v.n, l.n > 0.
DSPBR_FN float dspbr_sheen_brdf(vec3 v, vec3 l, float alpha_b, DspbrSheenLambda s) {
  vec3 h = normalize(v + l);
  if (!(dot(v, h) > 0.0f) || !(dot(l, h) > 0.0f)) return 0.0f;
  float g = 1.0f / (1.0f + dspbr_sheen_Lambda(s, v.z) + dspbr_sheen_Lambda(s, l.z));
  return dspbr_charlie_D(h, alpha_b) * g / (4.0f * v.z * l.z);
}
// The alternative: M_b = D_b / (4 (v.n + l.n - v.n l.n)) (spec "Sheen", [NP13]).
DSPBR_FN float dspbr_sheen_brdf_ash(vec3 v, vec3 l, float alpha_b) {
  vec3 h = normalize(v + l);
  return dspbr_charlie_D(h, alpha_b) / (4.0f * (v.z + l.z - v.z * l.z));
}
