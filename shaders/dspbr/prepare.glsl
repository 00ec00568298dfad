// dspbr_prepare: a material and the renderer's shading frame -> the prepared BSDF, a fixed set of
// lobes with everything that does not depend on the directions computed once (spec "Putting It
// All Together"; the reference's lobe assembly, src/dspbr/bsdf/lobe_assembly.cpp). No heap, no
// recursion: it runs per hit in a path tracer and in a GPU kernel.

// The lobes, in the order of the reference's lobe stack (its sampling order); slot
// DSPBR_SLOT_PASS is the cut-out's pass-through l = -v.
DSPBR_CONST int DSPBR_LOBE_CORE_REFLECTION = 0;  // M_r with the core's Fresnel
DSPBR_CONST int DSPBR_LOBE_MULTISCATTER = 1;     // M_r,ms F_ms
DSPBR_CONST int DSPBR_LOBE_TRANSMISSION = 2;     // M_t' (thin-walled) or M_t (volumetric)
DSPBR_CONST int DSPBR_LOBE_DIFFUSE = 3;          // rho_d [B_u (1 - s) + s B_c], translucency
DSPBR_CONST int DSPBR_LOBE_SHEEN = 4;            // M_b rho_b
DSPBR_CONST int DSPBR_LOBE_CLEARCOAT = 5;        // M_c c F_c
DSPBR_CONST int DSPBR_SLOT_PASS = 6;             // (not a lobe: the cut-out's pass-through)
DSPBR_CONST int DSPBR_LOBE_FLAKE = 7;            // c_f B_f: the opaque flake replaces the layers below
DSPBR_CONST int DSPBR_LOBE_COUNT = 8;            // lobe indices 0..7, 6 excepted
DSPBR_CONST int DSPBR_SLOT_COUNT = 8;

// Sample flags (the reference's LobeFlags).
DSPBR_CONST uint DSPBR_FLAG_REFLECTION = 1u;
DSPBR_CONST uint DSPBR_FLAG_TRANSMISSION = 2u;
DSPBR_CONST uint DSPBR_FLAG_DELTA = 4u;
DSPBR_CONST uint DSPBR_FLAG_GLOSSY = 8u;
DSPBR_CONST uint DSPBR_FLAG_DIFFUSE = 16u;

// Sheen models (the spec's Lambda fit, or the alternative visibility).
DSPBR_CONST int DSPBR_SHEEN_MAIN = 0;
DSPBR_CONST int DSPBR_SHEEN_ASH = 1;

// What the material does not say: the sheen model, the object's surface area for emissionMode
// LUMINOUS_POWER (m^2), the wavelength of a spectral renderer's path (nm; > 0 with abbeNumber > 0:
// the dispersive IOR), and for the flakes the shading point and the bumped normal in object
// space (metres; spec "Flake Texture").
struct DspbrOptions {
  int sheen_model;
  float object_area_m2;
  float wavelength_nm;
  vec3 position;
  vec3 object_normal;
};
DSPBR_FN DspbrOptions dspbr_default_options() {
  DspbrOptions o;
  o.sheen_model = DSPBR_SHEEN_MAIN;
  o.object_area_m2 = 1.0f;
  o.wavelength_nm = 0.0f;
  o.position = vec3(0.0f, 0.0f, 0.0f);
  o.object_normal = vec3(0.0f, 0.0f, 1.0f);
  return o;
}

// Each present lobe gets at least this fraction of the largest selection weight (the reference's
// kMinSelectionFraction), and below this 1 - E_avg the compensation lobes vanish (kMinMissingEnergy).
DSPBR_CONST float dspbr_min_selection = 1e-3f;
DSPBR_CONST float dspbr_min_missing_energy = 1e-9f;
// Relative IOR difference below which the interface does not bend light (kIndexMatched).
DSPBR_CONST float dspbr_index_matched = 1e-7f;

struct DspbrBsdf {
  DspbrFrame frame;  // the renderer's shading frame (directions in and out are in its space)
  DspbrFrame core;   // the core frame in frame's local coordinates: material normal, rotated tangent
  bool core_is_frame; // core is the identity (no normal map, no rotation): dspbr_to_core skips it
  DspbrFrame coat;   // the clearcoat frame (clearcoatNormal)
  uint lobes;        // bit k: lobe k is present
  uint delta;        // bit k: lobe k is a Dirac (perfectly smooth)
  bool thin_walled;
  float alpha_cut;  // cut-out opacity
  float clearcoat;  // c
  float eta;        // ior
  DspbrGgx ggx;     // the core's anisotropic GGX
  DspbrGgx coat_ggx;
  // ThinCore / VolumetricCore weights: m, (1-m)(1-t), (1-m) t; s; l.
  float w_metal;
  float w_opaque;
  float w_transp;
  float specular;
  float translucency;
  vec3 rho;       // albedo
  vec3 rho_sr0;   // (1-m) F_0 s rho_s + m rho (over the dielectric parts' weight)
  vec3 rho_sr90;  // (1-m) s + m
  vec3 rho_t;     // rho (1-m) t
  vec3 f0_diel;   // F_0 rho_s
  vec3 rho_d;     // (rho (1-l) + rho_l l) (1-m)(1-t)
  float r_uv;     // sqrt(r_u r_v): the tables' roughness
  float f0_max;   // max(F_0 rho_s): the coordinate of E(mu; r, f0)
  vec3 f_ms;      // F_ms(rho_s,r,0, rho_s,r,90)
  float fms_base; // F_ms(f0_max, 1; E_m,avg): E(mu; r, f0_max)'s multiple-scattering term
  float ms_inv_norm;       // 1 / (pi (1 - E_m,avg)), 0 in the mirror limit
  float diffuse_inv_norm;  // 1 / (pi (1 - E_avg(r, f0_max))), 0 when nothing is left
  vec3 sheen_color;
  float alpha_b;
  int sheen_model;
  DspbrSheenLambda sheen_lambda;
  vec3 rho_e;  // emitted luminance factor (spec "Emission")
  // Thin film over the core (spec "Thin Film"): weight i, thickness (um), film IOR, and the
  // equivalent IOR of the metal base (-1: a mirror).
  float film_weight;
  float film_thickness;
  float film_ior;
  float film_eta_rho;
  // The flake at the shading point (when opaque): its normal in the core frame, 1 - cos theta_cone,
  // its colour and the flip-flop effect.
  vec3 flake_normal;
  float flake_one_minus_cos;
  vec3 flake_color;
  float flip_flop;
  vec3 flip_flop_color;
};

// w (in the frame's local coordinates) in the core frame; w itself where the two coincide (the
// transform would multiply by ones and add zeros: the same value for finite w, six dot products less).
DSPBR_FN vec3 dspbr_to_core(DSPBR_IN(DspbrBsdf) b, vec3 w) { return b.core_is_frame ? w : dspbr_to_local(b.core, w); }

DSPBR_FN bool dspbr_has_lobe(DSPBR_IN(DspbrBsdf) b, int k) { return ((b.lobes >> uint(k)) & 1u) != 0u; }
DSPBR_FN bool dspbr_is_delta_lobe(DSPBR_IN(DspbrBsdf) b, int k) { return ((b.delta >> uint(k)) & 1u) != 0u; }

// t = t' cos(beta) - (n x t') sin(beta), beta = 2 pi anisotropyRotation (spec "Tangent Space").
DSPBR_FN DspbrFrame dspbr_core_frame(DSPBR_IN(DspbrMaterial) m) {
  DspbrFrame base = dspbr_normal_frame(m.normal);
  vec3 n = base.n;
  float beta = 2.0f * dspbr_pi * m.anisotropyRotation;
  // beta = 0 (no rotation, the default) is base itself: no sine and cosine to compute.
  if (beta == 0.0f) return base;
  DspbrFrame f;
  f.n = n;
  f.t = normalize(base.t * cos(beta) - cross(n, base.t) * sin(beta));
  f.b = cross(n, f.t);
  return f;
}

// rho_e of spec "Emission": L_vc / pi (emittance, lx) or L_vc / (pi A) (power, lm), L_vc the colour
// times the value, or normalised by the colour's luminance (linear sRGB, D65).
DSPBR_FN vec3 dspbr_emission_rho_e(DSPBR_IN(DspbrMaterial) m, DspbrOptions o) {
  if (!(m.emissionValue > 0.0f)) return dspbr_splat(0.0f);
  // In float the products overflow (a dim colour normalised: value / luminance; a large value
  // times a colour) and 0 x inf is NaN: the colour is scaled to a largest channel of 1 first, so
  // that each channel's product stays finite until its last factor, and each channel saturates at
  // the largest float (the library's +inf, shaders/README.md) on its own (the seventh and eighth
  // fresh testers' passes: inf and NaN for value 100 and colour (1e-37, 0, 0); a channel in range
  // pulled down with one beyond it).
  float c_max = dspbr_max3(m.emissionColor);
  if (!(c_max > 0.0f)) return dspbr_splat(0.0f);
  vec3 c = m.emissionColor / c_max;
  bool power = m.emissionMode == DSPBR_EMISSIONMODE_LUMINOUS_POWER;
  float area = o.object_area_m2 > 0.0f ? o.object_area_m2 : 1.0f;
  // c <= 1: c value is finite; each later factor finite, so a channel becomes +inf at worst, never NaN.
  vec3 l = (c * m.emissionValue) * min(power ? dspbr_inv_pi / area : dspbr_inv_pi, dspbr_float_max);
  l = m.emissionEnergyNormalization ? l / (0.2126729f * c.x + 0.7151522f * c.y + 0.0721750f * c.z)  // lum >= 0.0722
                                    : l * c_max;
  return vec3(min(l.x, dspbr_float_max), min(l.y, dspbr_float_max), min(l.z, dspbr_float_max));
}

DSPBR_FN DspbrBsdf dspbr_prepare(DSPBR_IN(DspbrMaterial) m, DspbrFrame frame, DSPBR_IN(DspbrOptions) o) {
  DspbrBsdf b;
  b.frame = frame;
  b.core = dspbr_core_frame(m);
  b.core_is_frame = dspbr_is_identity_frame(b.core);
  b.thin_walled = m.thinWalled;
  b.alpha_cut = dspbr_clamp_nan(m.cutoutOpacity, 0.0f, 1.0f);
  // A component compiled out (features.glsl) has weight 0, as in the reference's component masks.
  b.clearcoat = DSPBR_HAS_CLEARCOAT != 0 ? m.clearcoat : 0.0f;
  // The coat's frame is read only where the clearcoat weighs (its lobe, its layer factor, and the
  // emission's attenuation, times c): without a clearcoat the frame is not built.
  b.coat = b.clearcoat > 0.0f ? dspbr_normal_frame(m.clearcoatNormal) : dspbr_identity_frame();
  // Dispersion belongs to the volumetric transparent part (src/dspbr/component.cpp): eta(lambda) only
  // behind a volume boundary that transmits, as the reference (it bent thin walls and opaque
  // dielectrics too; the eighth fresh tester's pass).
  bool dispersive = DSPBR_HAS_DISPERSION != 0 && DSPBR_HAS_VOLUMETRIC_TRANSPARENT != 0 && !m.thinWalled && m.metallic < 1.0f &&
                    m.transparency > 0.0f;
  b.eta = dispersive ? dspbr_dispersion_ior(m.ior, m.abbeNumber, o.wavelength_nm) : m.ior;
  // Anisotropic roughness (r_u, r_v) = r (1, 1 - o), alpha = r^2 (spec "Microfacet BSDF").
  float r_u = m.roughness, r_v = m.roughness * (1.0f - m.anisotropy);
  b.ggx = dspbr_ggx(r_u * r_u, r_v * r_v);
  b.coat_ggx = dspbr_ggx(m.clearcoatRoughness * m.clearcoatRoughness, m.clearcoatRoughness * m.clearcoatRoughness);
  b.r_uv = sqrt(r_u * r_v);
  float metal = m.metallic, t = m.transparency, s = m.specular;
  bool volumetric = !m.thinWalled;
  bool transp_on = volumetric ? DSPBR_HAS_VOLUMETRIC_TRANSPARENT != 0 : DSPBR_HAS_THIN_TRANSPARENT != 0;
  b.w_metal = DSPBR_HAS_METALLIC != 0 ? metal : 0.0f;
  b.w_opaque = DSPBR_HAS_OPAQUE_DIELECTRIC != 0 ? (1.0f - metal) * (1.0f - t) : 0.0f;
  b.w_transp = transp_on ? (1.0f - metal) * t : 0.0f;
  b.specular = s;
  b.translucency = DSPBR_HAS_TRANSLUCENCY != 0 ? m.translucency : 0.0f;
  b.rho = m.albedo;
  float F0 = dspbr_f0_from_ior(1.0f, b.eta);
  b.f0_diel = m.specularTint * F0;
  b.rho_sr0 = b.f0_diel * ((b.w_opaque + b.w_transp) * s) + m.albedo * b.w_metal;
  b.rho_sr90 = dspbr_splat((b.w_opaque + b.w_transp) * s + b.w_metal);
  b.rho_t = m.albedo * b.w_transp;
  b.rho_d = (m.albedo * (1.0f - b.translucency) + m.translucencyColor * b.translucency) * b.w_opaque;
  b.f0_max = dspbr_max3(b.f0_diel);
  b.film_weight = DSPBR_HAS_THIN_FILM != 0 ? m.thinFilm : 0.0f;
  b.film_thickness = m.thinFilmThickness;
  b.film_ior = m.thinFilmIor;
  b.film_eta_rho = b.film_weight > 0.0f ? dspbr_thin_film_metal_eta(m.albedo) : 0.0f;
  b.lobes = 0u;
  b.delta = 0u;
  // GlitteryCore: an opaque flake at the shading point replaces the core and the sheen.
  DspbrFlake flake;
  flake.opacity = 0.0f;
  flake.normal = vec3(0.0f, 0.0f, 1.0f);
  if (DSPBR_HAS_FLAKES != 0 && m.flakeCoverage > 0.0f) flake = dspbr_flake_at(o.position, o.object_normal, m.flakeCoverage, m.flakeSize, m.flakeRoughness);
  bool flake_opaque = flake.opacity > 0.0f;
  b.flake_normal = flake.normal;
  b.flake_one_minus_cos = dspbr_flake_one_minus_cos_cone(m.flakeRoughness);
  b.flake_color = m.flakeColor;
  b.flip_flop = m.flipFlop;
  b.flip_flop_color = m.flipFlopColor;
  if (flake_opaque) {
    b.lobes |= 1u << uint(DSPBR_LOBE_FLAKE);
    if (b.flake_one_minus_cos < dspbr_flake_delta_cone) b.delta |= 1u << uint(DSPBR_LOBE_FLAKE);
  }
  bool mirror = b.ggx.mirror;
  if (!flake_opaque && b.w_metal + b.w_opaque + b.w_transp > 0.0f) {
    if (b.w_metal > 0.0f || s * (b.w_opaque + b.w_transp) > 0.0f || b.film_weight > 0.0f) {
      b.lobes |= 1u << uint(DSPBR_LOBE_CORE_REFLECTION);
      if (mirror) b.delta |= 1u << uint(DSPBR_LOBE_CORE_REFLECTION);
    }
    // M_r,ms F_ms (spec eq. multiscatter); none for a mirror (E_m = 1). 1 - E_m,avg is read for this
    // lobe and for B_c's normalisation below: a smooth metal or glass reads no table here (its 0 is
    // read by nothing).
    bool bc_needed = DSPBR_HAS_OPAQUE_DIELECTRIC != 0 && b.w_opaque > 0.0f;
    float missing_m = !mirror || bc_needed ? dspbr_ggx_E_avg_missing(b.r_uv) : 0.0f;
    float e_avg = 1.0f - missing_m;  // dspbr_ggx_E_avg
    b.f_ms = dspbr_fresnel_ms3(b.rho_sr0, b.rho_sr90, dspbr_clamp_nan(e_avg, 0.0f, 1.0f));
    b.ms_inv_norm = missing_m > dspbr_min_missing_energy ? 1.0f / (dspbr_pi * missing_m) : 0.0f;
    if (dspbr_max3(b.f_ms) > 0.0f && !mirror) b.lobes |= 1u << uint(DSPBR_LOBE_MULTISCATTER);
    // Present as in the reference (w_transp > 0 and rho_t > 0 in double): from the factors, not from
    // their float product, which underflows for a transmission near the smallest float (the pdf was
    // then 0 where the lobe's minimum selection share gives 1e-5..1e-4; the eighth fresh tester's pass).
    if (transp_on && metal < 1.0f && t > 0.0f && dspbr_max3(m.albedo) > 0.0f) {
      b.lobes |= 1u << uint(DSPBR_LOBE_TRANSMISSION);
      bool matched = volumetric && abs(b.eta - 1.0f) < dspbr_index_matched;
      if (mirror || matched) b.delta |= 1u << uint(DSPBR_LOBE_TRANSMISSION);
    }
    // B_c's normalisation (reads GGX_B_avg: only for an opaque dielectric part, compiled in), from the
    // 1 - E_m,avg read above.
    float missing_b = bc_needed ? 1.0f - dspbr_base_E_avg_given(b.r_uv, b.f0_max, missing_m) : 0.0f;
    b.fms_base = dspbr_fresnel_ms(b.f0_max, 1.0f, e_avg);
    b.diffuse_inv_norm = missing_b > dspbr_min_missing_energy ? 1.0f / (dspbr_pi * missing_b) : 0.0f;
    if (b.w_opaque > 0.0f && dspbr_max3(b.rho_d) > 0.0f) b.lobes |= 1u << uint(DSPBR_LOBE_DIFFUSE);
  } else {
    b.f_ms = dspbr_splat(0.0f);
    b.fms_base = 0.0f;
    b.ms_inv_norm = 0.0f;
    b.diffuse_inv_norm = 0.0f;
  }
  // Sheen (ShinyCore): alpha_b = r_b^2, at least dspbr_min_alpha_b.
  b.sheen_color = m.sheenColor;
  b.alpha_b = max(m.sheenRoughness * m.sheenRoughness, dspbr_min_alpha_b);
  b.sheen_model = o.sheen_model;
  // The Lambda fit (five powers) only for a sheen lobe: the main model's eval is its one reader.
  b.sheen_lambda = dspbr_sheen_lambda_unused();
  if (DSPBR_HAS_SHEEN != 0 && dspbr_max3(m.sheenColor) > 0.0f && !flake_opaque) {
    b.lobes |= 1u << uint(DSPBR_LOBE_SHEEN);
    b.sheen_lambda = dspbr_sheen_lambda_fit(b.alpha_b);
  }
  if (b.clearcoat > 0.0f) {
    b.lobes |= 1u << uint(DSPBR_LOBE_CLEARCOAT);
    if (b.coat_ggx.mirror) b.delta |= 1u << uint(DSPBR_LOBE_CLEARCOAT);
  }
  b.rho_e = DSPBR_HAS_EMISSION != 0 ? dspbr_emission_rho_e(m, o) : dspbr_splat(0.0f);
  return b;
}
