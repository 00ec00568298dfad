// Anisotropic GGX (GTR gamma = 2) and its height-correlated Smith masking-shadowing (spec
// "Microfacet BSDF"; Heitz 2014; visible normals: Heitz 2018), as in the reference
// (src/dspbr/ggx.h). Directions in the lobe's local frame (n = +z).

// alpha below which the distribution is a mirror (Dirac lobes), and the smallest alpha of a rough
// axis (the reference's kDeltaAlpha, kMinAlpha).
DSPBR_CONST float dspbr_delta_alpha = 1e-10f;

struct DspbrGgx {
  float au;
  float av;
  bool mirror;  // effectively smooth: eval = pdf = 0, sample along the mirror direction
};

DSPBR_FN DspbrGgx dspbr_ggx(float alpha_u, float alpha_v) {
  DspbrGgx g;
  g.mirror = !(max(alpha_u, alpha_v) >= dspbr_delta_alpha);
  g.au = g.mirror ? alpha_u : max(alpha_u, dspbr_delta_alpha);
  g.av = g.mirror ? alpha_v : max(alpha_v, dspbr_delta_alpha);
  return g;
}

// D(w_m) = 1 / (pi a_u a_v ((w_m.t/a_u)^2 + (w_m.b/a_v)^2 + (w_m.n)^2)^2) for w_m.n > 0 (spec
// "Microfacet BSDF"; no cancellation near the peak in float).
DSPBR_FN float dspbr_ggx_D(DspbrGgx g, vec3 wm) {
  if (!(wm.z > 0.0f)) return 0.0f;
  float x = wm.x / g.au, y = wm.y / g.av;
  float denom = x * x + y * y + wm.z * wm.z;
  return 1.0f / (dspbr_pi * g.au * g.av * denom * denom);
}

// Smith Lambda(w) = (-1 + sqrt(1 + 1/a^2)) / 2, 1/a^2 = ((w.t a_u)^2 + (w.b a_v)^2) / (w.n)^2
// (Heitz 2014); +inf at grazing (G = 0 there, never a 1/cos growth).
DSPBR_FN float dspbr_ggx_Lambda(DspbrGgx g, vec3 w) {
  float tan2_alpha2 = w.x * w.x * g.au * g.au + w.y * w.y * g.av * g.av;
  if (!(tan2_alpha2 > 0.0f)) return 0.0f;
  float cos2 = w.z * w.z;
  float x = tan2_alpha2 / cos2;  // +inf for cos2 = 0
  float s = sqrt(1.0f + x);
  // x / (2 (1 + s)) keeps small x exact; (s - 1) / 2 keeps large and infinite x finite or +inf.
  return x < 1e6f ? x / (2.0f * (1.0f + s)) : 0.5f * (s - 1.0f);
}
DSPBR_FN float dspbr_ggx_G1(DspbrGgx g, vec3 w) { return 1.0f / (1.0f + dspbr_ggx_Lambda(g, w)); }
// G2(v, l) = 1 / (1 + Lambda(v) + Lambda(l)) (spec "Microfacet BSDF", Heitz 2014 eq. 99).
DSPBR_FN float dspbr_ggx_G2(DspbrGgx g, vec3 v, vec3 l) {
  return 1.0f / (1.0f + dspbr_ggx_Lambda(g, v) + dspbr_ggx_Lambda(g, l));
}
// Visible normals D_w(w_m) = G1(w) max(0, w.w_m) D(w_m) / w.n (Heitz 2018 eq. 1).
DSPBR_FN float dspbr_ggx_D_visible(DspbrGgx g, vec3 w, vec3 wm) {
  if (!(w.z > 0.0f)) return 0.0f;
  float c = dot(w, wm);
  if (!(c > 0.0f)) return 0.0f;
  return dspbr_ggx_G1(g, w) * c * dspbr_ggx_D(g, wm) / w.z;
}
// A visible normal for w.n > 0 (Heitz 2018, listing 1: stretch, sample the projected hemisphere,
// unstretch); (u1, u2) in [0, 1)^2.
DSPBR_FN vec3 dspbr_ggx_sample_wm(DspbrGgx g, vec3 w, float u1, float u2) {
  vec3 vh = normalize(vec3(g.au * w.x, g.av * w.y, w.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lensq > 0.0f ? vec3(-vh.y, vh.x, 0.0f) / sqrt(lensq) : vec3(1.0f, 0.0f, 0.0f);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u1);
  float phi = 2.0f * dspbr_pi * u2;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * p2;
  vec3 nh = t1 * p1 + t2 * p2 + vh * sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2));
  return normalize(vec3(g.au * nh.x, g.av * nh.y, max(0.0f, nh.z)));
}
// M_r = D(h) G2(v, l) / (4 v.n l.n) with h = normalize(v + l), v.n, l.n > 0 (spec "Microfacet BSDF").
DSPBR_FN float dspbr_ggx_M_r(DspbrGgx g, vec3 v, vec3 l, vec3 h) {
  return dspbr_ggx_D(g, h) * dspbr_ggx_G2(g, v, l) / (4.0f * v.z * l.z);
}
// Density of l = reflect(v, h), h ~ D_v: D_v(h) / (4 v.h); 0 below the horizon (Heitz 2018).
DSPBR_FN float dspbr_ggx_reflection_pdf(DspbrGgx g, vec3 v, vec3 l) {
  if (g.mirror || !(v.z > 0.0f) || !(l.z > 0.0f)) return 0.0f;
  vec3 s = v + l;
  float len = length(s);
  if (!(len > 0.0f)) return 0.0f;
  vec3 h = s / len;
  float vh = dot(v, h);
  if (!(h.z > 0.0f) || !(vh > 0.0f)) return 0.0f;
  return dspbr_ggx_D_visible(g, v, h) / (4.0f * vh);
}
