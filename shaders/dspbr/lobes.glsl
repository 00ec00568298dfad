// The lobes of a prepared BSDF, each in its own frame with v on its front (v.z > 0 of the side's
// coordinates; bsdf.glsl mirrors a viewer on the back): eval (f without the cosine), pdf, a
// direction sample and the selection weight (a rough estimate of the lobe's albedo at v), as the
// reference's lobes compute them (src/dspbr/bsdf/*.cpp). eta_i: the IOR on v's side, eta_o: the
// other side (they differ from 1 only for the volumetric transmission seen from inside).

// ---- Fresnel factors of the core (spec "Putting It All Together": ThinCore / VolumetricCore,
// ThinFilmOver*) ----
// The film's R over the base IOR at a cosine on v's side: through the base from inside a volume
// (a lossless stack reflects equally from both sides at corresponding angles; 1 under total
// internal reflection).
DSPBR_FN vec3 dspbr_film(DSPBR_IN(DspbrBsdf) b, float c, float eta_base) {
  return dspbr_thin_film_reflectance(c, eta_base, b.film_thickness, b.film_ior);
}
DSPBR_FN vec3 dspbr_film_side(DSPBR_IN(DspbrBsdf) b, float c, float eta_i, float eta_o) {
  if (eta_i <= eta_o) return dspbr_film(b, c, b.eta);
  float s2 = dspbr_sin2_transmitted(c, eta_i, eta_o);
  if (s2 >= 1.0f) return dspbr_splat(1.0f);
  return dspbr_film(b, sqrt(1.0f - s2), b.eta);
}
// M_r's factor. Thin-walled: F(rho_s,r,0, rho_s,r,90); volumetric: m F(rho, 1) + (1-m)(1-t) s
// F(F_0 rho_s, 1) + (1-m) t s F_d(F_0 rho_s, 1); with a film of weight i, (1-i) that + i [m R(eta_rho)
// + (1-m)(1-t) R(eta) + (1-m) t R(eta, seen from v's side)] (docs/bsdf.md).
DSPBR_FN vec3 dspbr_core_reflection_factor(DSPBR_IN(DspbrBsdf) b, float c, float eta_i, float eta_o) {
  vec3 one = dspbr_splat(1.0f);
  vec3 f = dspbr_splat(0.0f);
  if (b.thin_walled) {
    f = dspbr_schlick(c, b.rho_sr0, b.rho_sr90);
  } else {
    if (b.w_metal > 0.0f) f = dspbr_schlick(c, b.rho, one) * b.w_metal;
    if (b.w_opaque > 0.0f) f += dspbr_schlick(c, b.f0_diel, one) * (b.w_opaque * b.specular);
    if (b.w_transp > 0.0f) f += dspbr_schlick_d(c, b.f0_diel, one, eta_i, eta_o) * (b.w_transp * b.specular);
  }
  if (DSPBR_HAS_THIN_FILM != 0 && b.film_weight > 0.0f) {
    bool transp_sees_eta = b.thin_walled || eta_i <= eta_o;
    vec3 r_eta = dspbr_splat(0.0f), r_transp = dspbr_splat(0.0f);
    if (b.w_opaque > 0.0f || (b.w_transp > 0.0f && transp_sees_eta)) r_eta = dspbr_film(b, c, b.eta);
    if (b.w_transp > 0.0f) r_transp = transp_sees_eta ? r_eta : dspbr_film_side(b, c, eta_i, eta_o);
    vec3 fr = r_eta * b.w_opaque + r_transp * b.w_transp;
    if (b.w_metal > 0.0f) fr += dspbr_film(b, c, b.film_eta_rho) * b.w_metal;
    f = f * (1.0f - b.film_weight) + fr * b.film_weight;
  }
  return f;
}
// M_t' of ThinCore: rho_t (1 - s F(F_0 rho_s, 1)); M_t of VolumetricCore: rho_t (1 - s F_d(F_0 rho_s,
// 1)); with a film (1-i) that + i rho_t (1 - R).
DSPBR_FN vec3 dspbr_core_transmission_factor(DSPBR_IN(DspbrBsdf) b, float c, float eta_i, float eta_o) {
  vec3 one = dspbr_splat(1.0f);
  vec3 f = b.thin_walled ? dspbr_schlick(c, b.f0_diel, one) : dspbr_schlick_d(c, b.f0_diel, one, eta_i, eta_o);
  vec3 t = b.rho_t * (one - f * b.specular);
  if (DSPBR_HAS_THIN_FILM != 0 && b.film_weight > 0.0f) {
    vec3 r = b.thin_walled ? dspbr_film(b, c, b.eta) : dspbr_film_side(b, c, eta_i, eta_o);
    t = t * (1.0f - b.film_weight) + b.rho_t * (one - r) * b.film_weight;
  }
  return t;
}
// The factor of a lobe built on reflection (core reflection, thin transmission, clearcoat).
DSPBR_FN vec3 dspbr_lobe_factor(DSPBR_IN(DspbrBsdf) b, int k, float c, float eta_i, float eta_o) {
  if (k == DSPBR_LOBE_CLEARCOAT) return dspbr_splat(b.clearcoat * dspbr_clearcoat_fresnel(c));
  if (k == DSPBR_LOBE_TRANSMISSION) return dspbr_core_transmission_factor(b, c, eta_i, eta_o);
  return dspbr_core_reflection_factor(b, c, eta_i, eta_o);
}
DSPBR_FN DspbrGgx dspbr_lobe_ggx(DSPBR_IN(DspbrBsdf) b, int k) { return k == DSPBR_LOBE_CLEARCOAT ? b.coat_ggx : b.ggx; }

// ---- Table reads: each table once per cosine ----
// The tables' values at one cosine c of the core frame, read once per direction and shared by the
// lobes and the layer factors: 1 - E_m(|c|; r_uv) and 1 - E(|c|; r_uv, f0_max), both clamped to
// [0, 1], from one E_m and one beta read (E = f0 E_m + (1 - f0) beta E_m + F_ms(f0, 1; E_m,avg)
// (1 - E_m), spec "Energy Preservation", F_ms from prepare), and E_b(|c|; alpha_b) of the sheen
// model clamped to [0, 1]. A value no present lobe reads is 0 and costs no fetch.
struct DspbrAlbedos {
  float missing_m;
  float missing_base;
  float sheen;
};
DSPBR_FN DspbrAlbedos dspbr_albedos(DSPBR_IN(DspbrBsdf) b, float c) {
  DspbrAlbedos a;
  a.missing_m = 0.0f;
  a.missing_base = 0.0f;
  a.sheen = 0.0f;
  float mu = abs(c);
  bool diffuse = DSPBR_HAS_OPAQUE_DIELECTRIC != 0 && dspbr_has_lobe(b, DSPBR_LOBE_DIFFUSE);
  if (diffuse || dspbr_has_lobe(b, DSPBR_LOBE_MULTISCATTER)) {
    // 1 - E_m from its own lookup: 1 - dspbr_ggx_E is rounding noise where E_m is within 1e-6 of 1
    // (roughness ~1e-3 near normal incidence; the eleventh fresh tester's pass: the multiple-
    // scattering lobe of a metal of roughness 0.001 seen at grazing was 45 % off the reference).
    // With a diffuse base, beta too, from the same coordinates and roughness taps; one call site
    // (a shader's texel fetches are counted once, and a metal's skip GGX_beta).
    DspbrGgxMissingBeta mb = dspbr_lut_ggx_missing_beta(mu, b.r_uv, diffuse ? 1 : 0);
    a.missing_m = mb.missing;
    if (diffuse) {
      float em = 1.0f - a.missing_m;
      float f0 = clamp(b.f0_max, 0.0f, 1.0f);
      float e = f0 * em + (1.0f - f0) * (mb.beta * em) + b.fms_base * (1.0f - em);
      a.missing_base = clamp(1.0f - e, 0.0f, 1.0f);
    }
  }
  if (DSPBR_HAS_SHEEN != 0 && dspbr_has_lobe(b, DSPBR_LOBE_SHEEN)) {
    float e = b.sheen_model == DSPBR_SHEEN_ASH ? dspbr_sheen_ash_E(mu, b.alpha_b) : dspbr_sheen_E(mu, b.alpha_b);
    a.sheen = clamp(e, 0.0f, 1.0f);
  }
  return a;
}

// ---- Microfacet reflection (core, clearcoat) and thin transmission (the reflection mirrored) ----
DSPBR_FN vec3 dspbr_reflection_eval(DSPBR_IN(DspbrBsdf) b, int k, vec3 v, vec3 l, float eta_i, float eta_o) {
  DspbrGgx g = dspbr_lobe_ggx(b, k);
  if (g.mirror || !(v.z > 0.0f) || !(l.z > 0.0f)) return dspbr_splat(0.0f);
  vec3 h = normalize(v + l);
  return dspbr_lobe_factor(b, k, dot(v, h), eta_i, eta_o) * dspbr_ggx_M_r(g, v, l, h);
}
// Selection weight of a lobe built on reflection: the factor at v.n and at v.n / 2.
DSPBR_FN float dspbr_reflection_weight(DSPBR_IN(DspbrBsdf) b, int k, vec3 v, float eta_i, float eta_o) {
  if (!(v.z > 0.0f)) return 0.0f;
  return max(0.0f, 0.5f * (dspbr_mean(dspbr_lobe_factor(b, k, v.z, eta_i, eta_o)) +
                           dspbr_mean(dspbr_lobe_factor(b, k, 0.5f * v.z, eta_i, eta_o))));
}

// ---- Volumetric transmission M_t (spec "Dielectric BSDF for Transparent Surfaces"; Walter 2007) ----
// The refraction half vector h_t = -(eta_i v + eta_o l) / |...|, turned towards +z; false unless v
// and l are on the two sides of the microfacet. denom = eta_i v.h + eta_o l.h, which is -|eta_i v +
// eta_o l| (or +|...| once h is turned): computed from the sum's length, not as the difference of
// the two dot products (near eta = 1 they cancel, and float would lose 1e-5 of it).
// Callers pass the IORs divided by the larger one: only their ratio matters, and eta_o^2 and
// denom^2 of the IORs themselves overflow a float beyond ior ~1e19 (+inf or 0 where the value is
// finite; the seventh fresh tester's pass).
DSPBR_FN bool dspbr_refraction_half(vec3 v, vec3 l, float eta_i, float eta_o, DSPBR_OUT(vec3) h, DSPBR_OUT(float) denom) {
  vec3 s = -(v * eta_i + l * eta_o);
  float len = length(s);
  h = vec3(0.0f, 0.0f, 1.0f);
  denom = 0.0f;
  if (!(len > 0.0f)) return false;
  h = s / len;
  denom = -len;
  if (h.z < 0.0f) {
    h = -h;
    denom = len;
  }
  return h.z > 0.0f && dot(v, h) > 0.0f && dot(l, h) < 0.0f;
}
// M_t = |l.h| |v.h| / (|l.n| |v.n|) eta_o^2 D(h) G2 / (eta_i v.h + eta_o l.h)^2, times the factor at v.h.
DSPBR_FN vec3 dspbr_volumetric_eval(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l, float eta_i, float eta_o) {
  if (dspbr_is_delta_lobe(b, DSPBR_LOBE_TRANSMISSION) || !(v.z > 0.0f) || !(l.z < 0.0f)) return dspbr_splat(0.0f);
  vec3 h;
  float denom;
  float m = max(eta_i, eta_o), ei = eta_i / m, eo = eta_o / m;
  if (!dspbr_refraction_half(v, l, ei, eo, h, denom)) return dspbr_splat(0.0f);
  float vh = dot(v, h), lh = dot(l, h);
  float g = dspbr_ggx_G2(b.ggx, v, l);
  float mt = abs(lh) * abs(vh) / (abs(l.z) * abs(v.z)) * eo * eo * dspbr_ggx_D(b.ggx, h) * g / (denom * denom);
  return dspbr_core_transmission_factor(b, vh, eta_i, eta_o) * mt;
}
// D_v(h_t) times |dh/dl| = eta_o^2 |l.h| / (eta_i v.h + eta_o l.h)^2 (Walter 2007 eq. 17).
DSPBR_FN float dspbr_volumetric_pdf(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l, float eta_i, float eta_o) {
  if (dspbr_is_delta_lobe(b, DSPBR_LOBE_TRANSMISSION) || !(v.z > 0.0f)) return 0.0f;
  vec3 h;
  float denom;
  float m = max(eta_i, eta_o), ei = eta_i / m, eo = eta_o / m;
  if (!dspbr_refraction_half(v, l, ei, eo, h, denom)) return 0.0f;
  float lh = dot(l, h);
  return dspbr_ggx_D_visible(b.ggx, v, h) * eo * eo * abs(lh) / (denom * denom);
}
DSPBR_FN float dspbr_volumetric_weight(DSPBR_IN(DspbrBsdf) b, vec3 v, float eta_i, float eta_o) {
  if (!(v.z > 0.0f)) return 0.0f;
  // A smooth lobe under total internal reflection transmits nothing.
  float eta = eta_i / eta_o;
  bool macro_tir = eta * sqrt(max(0.0f, 1.0f - v.z * v.z)) >= 1.0f && abs(eta - 1.0f) >= dspbr_index_matched;
  if (dspbr_is_delta_lobe(b, DSPBR_LOBE_TRANSMISSION) && macro_tir) return 0.0f;
  if (macro_tir) {
    // Beyond the critical angle: the share of facets tilted towards v by more than
    // theta_v - theta_c, times the factor at normal incidence (bsdf/volumetric_transmission.cpp).
    // tan(theta_v - theta_c) = num / den from sines and cosines (no inverse trigonometry).
    float alpha = max(b.ggx.au, b.ggx.av);
    float cos_v = clamp(v.z, 0.0f, 1.0f), sin_v = sqrt(1.0f - cos_v * cos_v);
    float sin_c = 1.0f / eta, cos_c = sqrt(max(0.0f, 1.0f - sin_c * sin_c));
    float num = max(0.0f, sin_v * cos_c - cos_v * sin_c), den = cos_v * cos_c + sin_v * sin_c;
    float a2 = alpha * alpha * den * den;
    return max(0.0f, 0.5f * a2 / (a2 + num * num) * dspbr_mean(dspbr_core_transmission_factor(b, 1.0f, eta_i, eta_o)));
  }
  return max(0.0f, dspbr_mean(dspbr_core_transmission_factor(b, v.z, eta_i, eta_o)));
}

// ---- Multiple scattering M_r,ms F_ms (spec eq. multiscatter; Kulla & Conty 2017) ----
DSPBR_FN vec3 dspbr_multiscatter_eval(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l, DspbrAlbedos av, DspbrAlbedos al) {
  if (!(v.z > 0.0f) || !(l.z > 0.0f) || b.ms_inv_norm == 0.0f) return dspbr_splat(0.0f);
  return b.f_ms * (av.missing_m * al.missing_m * b.ms_inv_norm);
}
DSPBR_FN float dspbr_multiscatter_weight(DSPBR_IN(DspbrBsdf) b, vec3 v, DspbrAlbedos av) {
  if (!(v.z > 0.0f) || b.ms_inv_norm == 0.0f) return 0.0f;
  return max(0.0f, dspbr_mean(b.f_ms)) * av.missing_m;
}

// ---- Diffuse base rho_d [B_u (1 - s) + s B_c] with translucency (spec eqs. diffuse, b_c) ----
DSPBR_FN vec3 dspbr_diffuse_eval(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l, DspbrAlbedos av, DspbrAlbedos al) {
  if (!(v.z > 0.0f) || l.z == 0.0f) return dspbr_splat(0.0f);
  float t = l.z > 0.0f ? 1.0f - b.translucency : b.translucency;  // T(v, l; l)
  if (t == 0.0f) return dspbr_splat(0.0f);
  float b_u = t * dspbr_inv_pi;
  float b_c = av.missing_base * al.missing_base * b.diffuse_inv_norm * t;
  vec3 base = dspbr_splat((1.0f - b.film_weight) * (b_u * (1.0f - b.specular) + b.specular * b_c));
  if (DSPBR_HAS_THIN_FILM != 0 && b.film_weight > 0.0f) {
    // ThinFilmOver*: + i B_u (1 - max(R(v.n), R(l.n))).
    vec3 r = dspbr_max3v(dspbr_film(b, v.z, b.eta), dspbr_film(b, abs(l.z), b.eta));
    base += (dspbr_splat(1.0f) - r) * (b.film_weight * b_u);
  }
  return b.rho_d * base;
}
DSPBR_FN float dspbr_diffuse_pdf(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l) {
  if (!(v.z > 0.0f)) return 0.0f;
  return (1.0f - b.translucency) * dspbr_cosine_hemisphere_pdf(l) + b.translucency * dspbr_cosine_hemisphere_pdf(-l);
}
DSPBR_FN float dspbr_diffuse_weight(DSPBR_IN(DspbrBsdf) b, vec3 v, DspbrAlbedos av) {
  if (!(v.z > 0.0f)) return 0.0f;
  float s = b.specular;
  float w = (1.0f - b.film_weight) * ((1.0f - s) + s * av.missing_base * (b.diffuse_inv_norm > 0.0f ? 1.0f : 0.0f));
  if (DSPBR_HAS_THIN_FILM != 0 && b.film_weight > 0.0f) w += b.film_weight * (1.0f - dspbr_mean(dspbr_film(b, v.z, b.eta)));
  return max(0.0f, dspbr_mean(b.rho_d) * w);
}

// ---- Sheen M_b rho_b (spec "Sheen"), sampled uniformly over the hemisphere ----
DSPBR_FN vec3 dspbr_sheen_eval(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l) {
  if (!(v.z > 0.0f) || !(l.z > 0.0f)) return dspbr_splat(0.0f);
  float mb = b.sheen_model == DSPBR_SHEEN_ASH ? dspbr_sheen_brdf_ash(v, l, b.alpha_b)
                                              : dspbr_sheen_brdf(v, l, b.alpha_b, b.sheen_lambda);
  return b.sheen_color * mb;
}
DSPBR_FN float dspbr_sheen_weight(DSPBR_IN(DspbrBsdf) b, vec3 v, DspbrAlbedos av) {
  if (!(v.z > 0.0f)) return 0.0f;
  return max(0.0f, dspbr_mean(b.sheen_color)) * max(av.sheen, 1e-3f);
}
// ShinyCore's factor on the layers below: min(1 - rho_hat E_b(v.n), 1 - rho_hat E_b(l.n)).
DSPBR_FN float dspbr_sheen_layer(DSPBR_IN(DspbrBsdf) b, DspbrAlbedos av, DspbrAlbedos al) {
  float rho_hat = dspbr_max3(b.sheen_color);
  return clamp(min(1.0f - rho_hat * av.sheen, 1.0f - rho_hat * al.sheen), 0.0f, 1.0f);
}

// ---- The flake c_f B_f (spec "Flake BSDF", "Flip-Flop Effect"): a cone around reflect(v, n_f) ----
// B_f = 1 / Omega_cone inside the cone, 0 outside, for a flake facing v; 0 for a mirror flake.
DSPBR_FN float dspbr_flake_cone(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l) {
  if (dspbr_is_delta_lobe(b, DSPBR_LOBE_FLAKE) || !(dot(v, b.flake_normal) > 0.0f)) return 0.0f;
  vec3 r = dspbr_reflect(v, b.flake_normal);
  return dot(l, r) > 1.0f - b.flake_one_minus_cos ? 1.0f / (2.0f * dspbr_pi * b.flake_one_minus_cos) : 0.0f;
}
DSPBR_FN vec3 dspbr_flake_eval(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l) {
  if (!(v.z > 0.0f) || !(l.z > 0.0f)) return dspbr_splat(0.0f);
  float bf = dspbr_flake_cone(b, v, l);
  if (bf == 0.0f) return dspbr_splat(0.0f);
  return dspbr_flake_tint(v, l, b.flake_color, b.flip_flop, b.flip_flop_color) * bf;
}
DSPBR_FN float dspbr_flake_pdf(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l) {
  if (!(v.z > 0.0f) || !(l.z > 0.0f)) return 0.0f;
  return dspbr_flake_cone(b, v, l);
}
DSPBR_FN float dspbr_flake_weight(DSPBR_IN(DspbrBsdf) b, vec3 v) {
  if (!(v.z > 0.0f) || !(dot(v, b.flake_normal) > 0.0f)) return 0.0f;
  vec3 r = dspbr_reflect(v, b.flake_normal);
  return max(0.0f, dspbr_mean(dspbr_flake_tint(v, r, b.flake_color, b.flip_flop, b.flip_flop_color))) * max(r.z, 0.0f);
}
// A direction uniform in the cone (1 - cos = u1 (1 - cos theta_cone)), or the mirror direction of a
// mirror flake with its reflectance lw = c_f l.n (the cone's limit).
DSPBR_FN bool dspbr_flake_sample(DSPBR_IN(DspbrBsdf) b, vec3 v, float u1, float u2, DSPBR_OUT(vec3) l, DSPBR_OUT(vec3) lw) {
  l = vec3(0.0f, 0.0f, 1.0f);
  lw = dspbr_splat(0.0f);
  if (!(v.z > 0.0f) || !(dot(v, b.flake_normal) > 0.0f)) return false;
  vec3 r = normalize(dspbr_reflect(v, b.flake_normal));
  if (dspbr_is_delta_lobe(b, DSPBR_LOBE_FLAKE)) {
    l = r;
    lw = dspbr_flake_tint(v, l, b.flake_color, b.flip_flop, b.flip_flop_color) * l.z;
    return l.z > 0.0f;
  }
  float omc = u1 * b.flake_one_minus_cos;
  float sn = sqrt(max(0.0f, omc * (2.0f - omc))), phi = 2.0f * dspbr_pi * u2;
  l = dspbr_to_world(dspbr_frame_from_normal(r), vec3(sn * cos(phi), sn * sin(phi), 1.0f - omc));
  return dspbr_flake_pdf(b, v, l) > 0.0f;
}
