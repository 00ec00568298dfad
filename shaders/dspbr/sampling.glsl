// Direction sampling in a lobe's local frame (n = +z) and the refraction of Snell's law, as in the
// reference (src/dspbr/bsdf/sampling.h, src/dspbr/vec3.h).

// Concentric map of [0,1)^2 to the unit disk (Shirley & Chiu 1997), then Malley's method:
// cosine-weighted upper hemisphere, pdf = max(0, z) / pi.
DSPBR_FN vec3 dspbr_sample_cosine_hemisphere(float u1, float u2) {
  float a = 2.0f * u1 - 1.0f, b = 2.0f * u2 - 1.0f;
  float x = 0.0f, y = 0.0f;
  if (a != 0.0f || b != 0.0f) {
    float r, phi;
    if (abs(a) > abs(b)) {
      r = a;
      phi = (dspbr_pi / 4.0f) * (b / a);
    } else {
      r = b;
      phi = dspbr_pi / 2.0f - (dspbr_pi / 4.0f) * (a / b);
    }
    x = r * cos(phi);
    y = r * sin(phi);
  }
  return vec3(x, y, sqrt(max(0.0f, 1.0f - x * x - y * y)));
}
DSPBR_FN float dspbr_cosine_hemisphere_pdf(vec3 w) { return max(0.0f, w.z) * dspbr_inv_pi; }
// Uniform upper hemisphere: pdf = 1 / (2 pi) for z > 0.
DSPBR_FN vec3 dspbr_sample_uniform_hemisphere(float u1, float u2) {
  float z = u1, r = sqrt(max(0.0f, 1.0f - z * z)), phi = 2.0f * dspbr_pi * u2;
  return vec3(r * cos(phi), r * sin(phi), z);
}
DSPBR_FN float dspbr_uniform_hemisphere_pdf(vec3 w) { return w.z > 0.0f ? 0.5f * dspbr_inv_pi : 0.0f; }
// Mirror reflection of v about n (both unit, pointing away from the surface).
DSPBR_FN vec3 dspbr_reflect(vec3 v, vec3 n) { return n * (2.0f * dot(v, n)) - v; }
// Refraction of v (v.h > 0) through the facet h, eta = eta_i / eta_o (Walter et al. 2007 eq. 40);
// false under total internal reflection. sin theta_t is formed as eta sin theta_i (eta^2 overflows
// a float beyond eta ~1e19, and eta^2 (1 - cos^2) is then NaN at normal incidence), and for
// eta > 1 the direction as (its expression) / eta: normalize takes any length.
DSPBR_FN bool dspbr_refract(vec3 v, vec3 h, float eta, DSPBR_OUT(vec3) l) {
  float cos_i = dot(v, h);
  float sin_t = eta * sqrt(max(0.0f, 1.0f - cos_i * cos_i));
  l = vec3(0.0f, 0.0f, 0.0f);
  if (!(sin_t < 1.0f)) return false;
  float cos_t = sqrt(1.0f - sin_t * sin_t);
  l = eta > 1.0f ? normalize(h * (cos_i - cos_t / eta) - v) : normalize(h * (eta * cos_i - cos_t) - v * eta);
  return true;
}
