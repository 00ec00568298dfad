// The DSPBR 2025x core BRDF of an opaque material in GLSL, energy-compensated with the generated
// lookups (include after luts/dspbr_lookup.glsl): the spec's ThinCore ("Putting It All
// Together") with transparency t = 0 and translucency l = 0, i.e. metallic m times the metallic
// BSDF plus (1 - m) times the opaque dielectric BSDF, isotropic, specular tint rho_s = 1:
//   f = M_r F(rho_s,r,0, rho_s,r,90) + M_r,ms F_ms(rho_s,r,0, rho_s,r,90) + rho_d [B_u (1 - s) + s B_c(F_0)]
// Used by examples/vulkan/sphere.comp; the reference is the C++ BSDF (dspbr::MaterialBsdf).
// Rough surfaces only (r > 0): at r = 0 M_r is a Dirac, which a renderer samples, not evaluates.
#ifndef DSPBR_CORE_GLSL
#define DSPBR_CORE_GLSL

struct DspbrCoreMaterial {
  vec3 albedo;      // rho
  float metallic;   // m
  float roughness;  // r (alpha = r^2)
  float specular;   // s
  float ior;        // eta
};

const float kDspbrPi = 3.14159265358979;

// D(h; alpha) = alpha^2 / (pi ((h.n)^2 (alpha^2 - 1) + 1)^2), written with sin^2 = |n x h|^2 so
// that float keeps the peak (spec "Microfacet BSDF", isotropic GTR gamma = 2).
float dspbr_D(vec3 n, vec3 h, float alpha) {
  float cos_h = dot(n, h);
  if (cos_h <= 0.0) return 0.0;
  vec3 s = cross(n, h);
  float a2 = alpha * alpha, denom = cos_h * cos_h * a2 + dot(s, s);
  return a2 / (kDspbrPi * denom * denom);
}

// Smith Lambda(x) = (-1 + sqrt(1 + 1/a^2)) / 2 with 1/a^2 = alpha^2 (1/(x.n)^2 - 1), written
// x / (2 (1 + sqrt(1 + x))) (spec "Microfacet BSDF", [Hei14]).
float dspbr_Lambda(float cos_x, float alpha) {
  float c2 = cos_x * cos_x;
  float inv_a2 = alpha * alpha * max(1.0 - c2, 0.0) / c2;
  return inv_a2 / (2.0 * (1.0 + sqrt(1.0 + inv_a2)));
}

// M_r = D(h) G(v, l, h) / (4 |v.n| |l.n|), G = 1 / (1 + Lambda(v) + Lambda(l)) height-correlated
// (spec "Microfacet BSDF").
float dspbr_M_r(vec3 n, vec3 h, float cos_v, float cos_l, float alpha) {
  float g = 1.0 / (1.0 + dspbr_Lambda(cos_v, alpha) + dspbr_Lambda(cos_l, alpha));
  return dspbr_D(n, h, alpha) * g / (4.0 * cos_v * cos_l);
}

// Schlick F(cos; f0, f90) = f0 + (f90 - f0) (1 - |cos|)^5 (spec "Fresnel").
vec3 dspbr_F(float cos_theta, vec3 f0, vec3 f90) {
  float m = 1.0 - min(abs(cos_theta), 1.0), m2 = m * m;
  return f0 + (f90 - f0) * (m2 * m2 * m);
}

// f(v, l) of the core (without the cosine); n, v, l unit vectors, 0 unless both above the surface.
vec3 dspbr_core_brdf(DspbrCoreMaterial mat, vec3 n, vec3 v, vec3 l) {
  float cos_v = dot(n, v), cos_l = dot(n, l);
  if (cos_v <= 0.0 || cos_l <= 0.0) return vec3(0.0);
  float m = mat.metallic, s = mat.specular, r = mat.roughness;
  // F_0 = ((eta_i - eta_o) / (eta_i + eta_o))^2, eta_i = 1 (spec "Dielectric BSDF for Transparent Surfaces").
  float f0 = (1.0 - mat.ior) / (1.0 + mat.ior);
  f0 *= f0;
  // rho_s,r,0 = (1 - m) F_0 s rho_s + m rho, rho_s,r,90 = (1 - m) s + m (spec "Putting It All Together").
  vec3 rho_sr0 = vec3((1.0 - m) * f0 * s) + m * mat.albedo;
  vec3 rho_sr90 = vec3((1.0 - m) * s + m);
  vec3 h = normalize(v + l);
  // M_r F(cos theta_r = h.v; rho_s,r,0, rho_s,r,90) (spec "Metallic BSDF").
  vec3 f = dspbr_M_r(n, h, cos_v, cos_l, r * r) * dspbr_F(dot(h, v), rho_sr0, rho_sr90);
  // M_r,ms F_ms, F_ms per channel from E_m,avg (spec eq. multiscatter, [KC17]).
  float e_m_avg = dspbr_ggx_E_avg(r);
  vec3 f_ms = vec3(dspbr_fresnel_ms(rho_sr0.r, rho_sr90.r, e_m_avg), dspbr_fresnel_ms(rho_sr0.g, rho_sr90.g, e_m_avg),
                   dspbr_fresnel_ms(rho_sr0.b, rho_sr90.b, e_m_avg));
  f += f_ms * dspbr_ms_lobe(cos_v, cos_l, r);
  // rho_d [B_u (1 - s) + s B_c(F_0 rho_s)], rho_d = rho (1 - m), B_u = 1 / pi (spec eq. diffuse),
  // B_c from E(mu; r, f_0,max) (spec eq. b_c).
  float b = (1.0 - s) / kDspbrPi + s * dspbr_diffuse_bc(cos_v, cos_l, r, f0);
  return f + mat.albedo * ((1.0 - m) * b);
}

#endif
