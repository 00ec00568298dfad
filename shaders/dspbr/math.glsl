// Small helpers of the shader library (common subset: shaders/README.md): constants, colour
// reductions, Schlick's Fresnel and its variants (spec "Fresnel", "Energy Preservation"), frames.

DSPBR_CONST float dspbr_pi = 3.14159265358979f;
DSPBR_CONST float dspbr_inv_pi = 0.318309886183791f;

DSPBR_FN vec3 dspbr_splat(float x) { return vec3(x, x, x); }
DSPBR_FN float dspbr_mean(vec3 c) { return (c.x + c.y + c.z) * (1.0f / 3.0f); }
DSPBR_FN float dspbr_max3(vec3 c) { return max(c.x, max(c.y, c.z)); }
DSPBR_FN vec3 dspbr_max3v(vec3 a, vec3 b) { return vec3(max(a.x, b.x), max(a.y, b.y), max(a.z, b.z)); }
// x when it is a finite number, else d (NaN and Inf inputs get a defined value).
DSPBR_FN float dspbr_finite_or(float x, float d) { return (isnan(x) || isinf(x)) ? d : x; }
// x clamped to [lo, hi]; NaN gives lo (a comparison with NaN is false).
DSPBR_FN float dspbr_clamp_nan(float x, float lo, float hi) { return x >= lo ? (x <= hi ? x : hi) : lo; }

// Schlick's weight (1 - |cos|)^5 (spec "Fresnel").
DSPBR_FN float dspbr_schlick_weight(float c) {
  float m = 1.0f - min(1.0f, abs(c));
  float m2 = m * m;
  return m2 * m2 * m;
}
// F(cos; f0, f90) = f0 + (f90 - f0) (1 - |cos|)^5 (spec "Fresnel").
DSPBR_FN vec3 dspbr_schlick(float c, vec3 f0, vec3 f90) { return f0 + (f90 - f0) * dspbr_schlick_weight(c); }
DSPBR_FN float dspbr_schlick1(float c, float f0, float f90) { return f0 + (f90 - f0) * dspbr_schlick_weight(c); }
// F_0 = ((eta_i - eta_o) / (eta_i + eta_o))^2 (spec "Dielectric BSDF for Transparent Surfaces").
DSPBR_FN float dspbr_f0_from_ior(float eta_i, float eta_o) {
  float r = (eta_i - eta_o) / (eta_i + eta_o);
  return r * r;
}
// sin^2 of the transmitted angle, Snell's law (spec "Fresnel").
DSPBR_FN float dspbr_sin2_transmitted(float c, float eta_i, float eta_o) {
  float e = eta_i / eta_o;
  return e * e * max(0.0f, 1.0f - c * c);
}
// F_d: Schlick on the side of the denser medium, 1 under total internal reflection (spec "Fresnel").
DSPBR_FN vec3 dspbr_schlick_d(float c, vec3 f0, vec3 f90, float eta_i, float eta_o) {
  if (eta_o >= eta_i) return dspbr_schlick(c, f0, f90);
  float s2 = dspbr_sin2_transmitted(c, eta_i, eta_o);
  if (s2 >= 1.0f) return dspbr_splat(1.0f);
  return dspbr_schlick(sqrt(1.0f - s2), f0, f90);
}
// F_ms per channel (spec eq. multiscatter; dspbr_fresnel_ms of the generated lookups).
DSPBR_FN vec3 dspbr_fresnel_ms3(vec3 f0, vec3 f90, float e_avg) {
  return vec3(dspbr_fresnel_ms(f0.x, f90.x, e_avg), dspbr_fresnel_ms(f0.y, f90.y, e_avg),
              dspbr_fresnel_ms(f0.z, f90.z, e_avg));
}
// F_c(cos) = 0.04 + 0.96 (1 - |cos|)^5, the clearcoat's Fresnel (spec "Clearcoat", eta = 1.5).
DSPBR_FN float dspbr_clearcoat_fresnel(float c) { return dspbr_schlick1(c, 0.04f, 1.0f); }

// An orthonormal frame (t, b, n); local coordinates: t = +x, b = +y, n = +z.
struct DspbrFrame {
  vec3 t;
  vec3 b;
  vec3 n;
};
DSPBR_FN vec3 dspbr_to_local(DspbrFrame f, vec3 w) { return vec3(dot(w, f.t), dot(w, f.b), dot(w, f.n)); }
DSPBR_FN vec3 dspbr_to_world(DspbrFrame f, vec3 w) { return f.t * w.x + f.b * w.y + f.n * w.z; }
DSPBR_FN DspbrFrame dspbr_identity_frame() {
  DspbrFrame f;
  f.t = vec3(1.0f, 0.0f, 0.0f);
  f.b = vec3(0.0f, 1.0f, 0.0f);
  f.n = vec3(0.0f, 0.0f, 1.0f);
  return f;
}
// Whether f is the identity exactly (then dspbr_to_local(f, w) is w for every finite w).
DSPBR_FN bool dspbr_is_identity_frame(DspbrFrame f) {
  return f.t.x == 1.0f && f.t.y == 0.0f && f.t.z == 0.0f && f.b.x == 0.0f && f.b.y == 1.0f && f.b.z == 0.0f && f.n.x == 0.0f &&
         f.n.y == 0.0f && f.n.z == 1.0f;
}
// Frame around a unit normal (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
DSPBR_FN DspbrFrame dspbr_frame_from_normal(vec3 n) {
  float sgn = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (sgn + n.z);
  float b = n.x * n.y * a;
  DspbrFrame f;
  f.n = n;
  f.t = vec3(1.0f + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
  f.b = vec3(b, sgn + n.y * n.y * a, -n.y);
  return f;
}
// Frame from a unit normal and a tangent not necessarily orthogonal to it (Gram-Schmidt); a
// tangent parallel to the normal falls back to dspbr_frame_from_normal.
DSPBR_FN DspbrFrame dspbr_frame_from_normal_tangent(vec3 n, vec3 tangent) {
  vec3 t = tangent - n * dot(n, tangent);
  float len = length(t);
  if (!(len > 1e-6f)) return dspbr_frame_from_normal(n);
  DspbrFrame f;
  f.n = n;
  f.t = t / len;
  f.b = cross(n, f.t);
  return f;
}
// A direction given to eval, pdf, sample or emission made unit (the renderer's need not be: the
// lobes assume it, and a volume of ior 1e20 seen along v of length 2.8 sampled NaN weights; the
// tenth fresh tester's pass); a zero, NaN or infinite one is the zero vector, which has no value.
// A direction whose squared length is within 1e-5 of 1 (every unit vector rounded to float, ~3e-7)
// is used as it is: renormalising it would move it by an ulp, and a sample's direction handed back
// to pdf must give the density the sample reported (sharp lobes differ within an ulp).
DSPBR_CONST float dspbr_unit_tolerance = 1e-5f;
// Any other finite non-zero one is divided by its largest |component| first, so that its squared
// length neither overflows nor underflows (the eleventh fresh tester's pass: v of length 1e20 or
// 1e-30 had no value).
// w / |w| with w divided by its largest |component| first; `otherwise` for a zero, NaN or infinite w.
DSPBR_FN vec3 dspbr_scaled_unit(vec3 w, vec3 otherwise) {
  float m = max(max(abs(w.x), abs(w.y)), abs(w.z));
  if (!(m > 0.0f) || isinf(m) || isnan(w.x + w.y + w.z)) return otherwise;
  vec3 s = w / m;
  return s / length(s);
}
DSPBR_FN vec3 dspbr_unit_direction(vec3 w) {
  if (abs(dot(w, w) - 1.0f) <= dspbr_unit_tolerance) return w;
  return dspbr_scaled_unit(w, vec3(0.0f, 0.0f, 0.0f));
}
// A material normal made unit, scaled first as a direction is (a normal map's normal of length
// below about 1e-19 was +z); a zero, NaN or infinite one is +z (the unperturbed normal).
DSPBR_FN vec3 dspbr_unit_normal(vec3 n) { return dspbr_scaled_unit(n, vec3(0.0f, 0.0f, 1.0f)); }
// The frame of a material's normal (normal, clearcoatNormal: in the shading frame, +z where nothing
// perturbs it), its tangent the shading frame's x made orthogonal (Gram-Schmidt). The unperturbed +z
// gives the identity without the square roots and divisions: the frame the general path gives (for
// an x or y of -0 the general path keeps -0 where the identity has +0: a dot product with it can
// differ only in the sign of a zero).
DSPBR_FN DspbrFrame dspbr_normal_frame(vec3 normal) {
  if (normal.x == 0.0f && normal.y == 0.0f && normal.z == 1.0f) return dspbr_identity_frame();
  return dspbr_frame_from_normal_tangent(dspbr_unit_normal(normal), vec3(1.0f, 0.0f, 0.0f));
}
