// What a volumetric material gives the renderer's integrator besides the BSDF (spec "Volume",
// "Dispersion"), as the reference computes it (src/dspbr/bsdf/volume.cpp, dispersion.cpp): the
// medium's coefficients per unit of attenuationDistance, the Henyey-Greenstein anisotropy, and the
// IOR at a wavelength.

// Stands for +inf: an opaque channel's sigma_t (attenuationDistance 0 or attenuation colour 0);
// attenuationDistance >= this is "no attenuation" (the material's default).
DSPBR_CONST float dspbr_float_max = 3.402823466e38f;

struct DspbrVolume {
  vec3 sigma_t;  // attenuation coefficient -log(a) / d (1 / mean free path)
  vec3 sigma_a;  // absorption sigma_t (1 - rho_ss)
  vec3 sigma_s;  // scattering sigma_t rho_ss
  vec3 rho_ss;   // single-scattering albedo from subsurfaceColor ([KC17] inversion)
  float g;       // Henyey-Greenstein anisotropy (subsurfaceAnisotropy)
};

DSPBR_FN float dspbr_volume_sigma_t(float a, float d) {
  if (d >= dspbr_float_max) return 0.0f;
  if (!(d > 0.0f) || !(a > 0.0f)) return dspbr_float_max;
  if (a >= 1.0f) return 0.0f;
  return -log(a) / d;  // spec "Volume": sigma_t = -log(a) / d
}
// [KC17] albedo inversion as printed in the spec's "Volume" section; 0 and 1 exact.
DSPBR_FN float dspbr_volume_rho_ss(float rho_ms) {
  float r = clamp(rho_ms, 0.0f, 1.0f);
  if (r == 0.0f || r == 1.0f) return r;
  float t = 4.09712f + 4.20863f * r - sqrt(9.59217f + 41.6808f * r + 17.7126f * r * r);
  return clamp(1.0f - t * t, 0.0f, 1.0f);
}
// x * y for y in [0, 1] with inf * 0 = 0 (an opaque, purely absorbing channel scatters nothing) and
// inf * y = inf (x = dspbr_float_max stands for +inf).
DSPBR_FN float dspbr_mul_inf0(float x, float y) {
  if (x == 0.0f || y == 0.0f) return 0.0f;
  return x >= dspbr_float_max ? dspbr_float_max : x * y;
}

DSPBR_FN DspbrVolume dspbr_volume(DSPBR_IN(DspbrMaterial) m) {
  DspbrVolume v;
  v.sigma_t = vec3(dspbr_volume_sigma_t(m.attenuationColor.x, m.attenuationDistance),
                   dspbr_volume_sigma_t(m.attenuationColor.y, m.attenuationDistance),
                   dspbr_volume_sigma_t(m.attenuationColor.z, m.attenuationDistance));
  v.rho_ss = vec3(dspbr_volume_rho_ss(m.subsurfaceColor.x), dspbr_volume_rho_ss(m.subsurfaceColor.y),
                  dspbr_volume_rho_ss(m.subsurfaceColor.z));
  v.sigma_a = vec3(dspbr_mul_inf0(v.sigma_t.x, 1.0f - v.rho_ss.x), dspbr_mul_inf0(v.sigma_t.y, 1.0f - v.rho_ss.y),
                   dspbr_mul_inf0(v.sigma_t.z, 1.0f - v.rho_ss.z));
  v.sigma_s = vec3(dspbr_mul_inf0(v.sigma_t.x, v.rho_ss.x), dspbr_mul_inf0(v.sigma_t.y, v.rho_ss.y),
                   dspbr_mul_inf0(v.sigma_t.z, v.rho_ss.z));
  v.g = clamp(m.subsurfaceAnisotropy, -1.0f, 1.0f);
  return v;
}

// eta(lambda) = eta_d + (eta_d - 1) / nu_d (523655 / lambda^2 - 1.5168), at least 1 (spec
// "Dispersion", Cauchy through the d line); the ior itself for nu_d = 0 or no wavelength.
DSPBR_FN float dspbr_dispersion_ior(float ior, float abbe_number, float lambda_nm) {
  if (!(abbe_number > 0.0f) || !(lambda_nm > 0.0f) || abbe_number >= dspbr_float_max) return ior;
  // At most the largest float (the library's +inf, shaders/README.md): the sum overflows for iors
  // near it.
  return min(max(ior + (ior - 1.0f) / abbe_number * (523655.0f / (lambda_nm * lambda_nm) - 1.5168f), 1.0f), dspbr_float_max);
}
