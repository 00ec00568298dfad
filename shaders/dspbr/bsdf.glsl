// The prepared BSDF's public calls: dspbr_eval (f without the cosine), dspbr_pdf, dspbr_sample and
// dspbr_emission, with the conventions of docs/bsdf.md: v (towards the viewer) and l (towards the
// light) point away from the surface, in the space of the frame given to dspbr_prepare.
// Structure, as the reference's (src/dspbr/bsdf/material_bsdf.h):
//   two-sided  - a viewer on the back sees f(v, l) = f_back(-v, -l); the side is that of the core
//                normal (thin-walled) or of the geometric z (volume boundary: v.z < 0 is inside)
//   cut-out    - every lobe scaled by the opacity alpha, plus a pass-through Dirac l = -v of 1 - alpha
//   layering   - core lobes x (1 - c max(F_c(v.n_c), F_c(l.n_c))) x sheen scaling, sheen x the
//                coat's factor, clearcoat x 1 (spec "Putting It All Together")
//   sampling   - a lobe chosen with probability proportional to its selection weight times its
//                layer factor at (v, v), each present one at least 1e-3 of the largest; pdf is the
//                mixture density of the non-delta lobes, so weight = f |l.n| / pdf.

struct DspbrSample {
  vec3 l;        // the sampled direction (frame space)
  vec3 weight;   // f |l.n| / pdf (non-delta); reflectance / probability (delta)
  float pdf;     // solid-angle density (non-delta) or discrete probability (delta)
  uint flags;    // DSPBR_FLAG_*
  bool valid;    // false: the sample failed (absorbed, below the horizon, total internal reflection)
};

DSPBR_FN DspbrSample dspbr_failed_sample() {
  DspbrSample s;
  s.l = vec3(0.0f, 0.0f, 1.0f);
  s.weight = dspbr_splat(0.0f);
  s.pdf = 0.0f;
  s.flags = 0u;
  s.valid = false;
  return s;
}

// The side of v (in the frame's local coordinates): true for the back.
DSPBR_FN bool dspbr_back_side(DSPBR_IN(DspbrBsdf) b, vec3 v) { return b.thin_walled ? dot(v, b.core.n) < 0.0f : v.z < 0.0f; }
// The IOR on v's side (eta_i) and on the other side (eta_o): the volume's only on the inside.
DSPBR_FN float dspbr_eta_i(DSPBR_IN(DspbrBsdf) b, bool back) { return (!b.thin_walled && back) ? b.eta : 1.0f; }
DSPBR_FN float dspbr_eta_o(DSPBR_IN(DspbrBsdf) b, bool back) { return (!b.thin_walled && back) ? 1.0f : b.eta; }

// The layer factors of (v, l) times the cut-out opacity s: core, sheen, clearcoat.
struct DspbrLayers {
  float core;
  float sheen;
  float coat;
};
DSPBR_FN DspbrLayers dspbr_layers(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l, DspbrAlbedos av, DspbrAlbedos al) {
  DspbrLayers f;
  float s = b.alpha_cut;
  f.coat = s;
  float below = s;
  if (DSPBR_HAS_CLEARCOAT != 0 && b.clearcoat > 0.0f)
    below *= 1.0f - b.clearcoat * max(dspbr_clearcoat_fresnel(dot(v, b.coat.n)), dspbr_clearcoat_fresnel(dot(l, b.coat.n)));
  f.sheen = below;
  f.core = DSPBR_HAS_SHEEN != 0 && dspbr_has_lobe(b, DSPBR_LOBE_SHEEN) ? below * dspbr_sheen_layer(b, av, al) : below;
  return f;
}
DSPBR_FN float dspbr_layer_of(DspbrLayers f, int k) {
  if (k == DSPBR_LOBE_CLEARCOAT) return f.coat;
  if (k == DSPBR_LOBE_SHEEN || k == DSPBR_LOBE_FLAKE) return f.sheen;
  return f.core;
}
DSPBR_FN vec3 dspbr_flip_z(vec3 w) { return vec3(w.x, w.y, -w.z); }

// A direction closer to the horizon of a lobe's frame than |cos| 1e-9 is on it: no value, no
// density, no sample, as the reference's kHorizonCos (src/dspbr/bsdf/lobe_mixture.h). Below it the
// lobes' 1/cos factors overflow a float (the ninth fresh tester's pass: f = +inf at a cosine of
// 1.4e-45, which the sampler itself produced), and f cos there is below 1e-9 f anyway. NaN included.
DSPBR_CONST float dspbr_horizon_cos = 1e-9f;
DSPBR_FN bool dspbr_on_horizon(vec3 w) { return !(abs(w.z) >= dspbr_horizon_cos); }

// f of lobe k (no layer factor) for v, l in the side's coordinates (vc, lc: the same in the core
// frame); av, al: the tables at v and l.
DSPBR_FN vec3 dspbr_lobe_eval(DSPBR_IN(DspbrBsdf) b, int k, vec3 v, vec3 l, vec3 vc, vec3 lc, float eta_i, float eta_o,
                              DspbrAlbedos av, DspbrAlbedos al) {
  if (DSPBR_HAS_CLEARCOAT != 0 && k == DSPBR_LOBE_CLEARCOAT) {
    // The coat reflects: nothing towards the other side of the core's surface.
    if (!(dot(l, b.core.n) > 0.0f)) return dspbr_splat(0.0f);
    vec3 vk = dspbr_to_local(b.coat, v), lk = dspbr_to_local(b.coat, l);
    if (dspbr_on_horizon(vk) || dspbr_on_horizon(lk)) return dspbr_splat(0.0f);
    return dspbr_reflection_eval(b, k, vk, lk, eta_i, eta_o);
  }
  if (k == DSPBR_LOBE_CORE_REFLECTION) return dspbr_reflection_eval(b, k, vc, lc, eta_i, eta_o);
  if (k == DSPBR_LOBE_MULTISCATTER) return dspbr_multiscatter_eval(b, vc, lc, av, al);
  if (DSPBR_HAS_VOLUMETRIC_TRANSPARENT != 0 && k == DSPBR_LOBE_TRANSMISSION && !b.thin_walled)
    return dspbr_volumetric_eval(b, vc, lc, eta_i, eta_o);
  if (DSPBR_HAS_THIN_TRANSPARENT != 0 && k == DSPBR_LOBE_TRANSMISSION && b.thin_walled) {
    if (!(lc.z < 0.0f)) return dspbr_splat(0.0f);
    return dspbr_reflection_eval(b, k, vc, dspbr_flip_z(lc), eta_i, eta_o);  // M_t' = M_r(v, l mirrored)
  }
  if (DSPBR_HAS_OPAQUE_DIELECTRIC != 0 && k == DSPBR_LOBE_DIFFUSE) return dspbr_diffuse_eval(b, vc, lc, av, al);
  if (DSPBR_HAS_FLAKES != 0 && k == DSPBR_LOBE_FLAKE) return dspbr_flake_eval(b, vc, lc);
  if (DSPBR_HAS_SHEEN != 0 && k == DSPBR_LOBE_SHEEN) return dspbr_sheen_eval(b, vc, lc);
  return dspbr_splat(0.0f);
}

// The density with which lobe k samples l (vc, lc: v and l in the core frame).
DSPBR_FN float dspbr_lobe_pdf(DSPBR_IN(DspbrBsdf) b, int k, vec3 v, vec3 l, vec3 vc, vec3 lc, float eta_i, float eta_o) {
  if (DSPBR_HAS_CLEARCOAT != 0 && k == DSPBR_LOBE_CLEARCOAT) {
    vec3 vk = dspbr_to_local(b.coat, v), lk = dspbr_to_local(b.coat, l);
    return dspbr_on_horizon(vk) || dspbr_on_horizon(lk) ? 0.0f : dspbr_ggx_reflection_pdf(b.coat_ggx, vk, lk);
  }
  if (k == DSPBR_LOBE_CORE_REFLECTION) return dspbr_ggx_reflection_pdf(b.ggx, vc, lc);
  if (DSPBR_HAS_VOLUMETRIC_TRANSPARENT != 0 && k == DSPBR_LOBE_TRANSMISSION && !b.thin_walled)
    return dspbr_volumetric_pdf(b, vc, lc, eta_i, eta_o);
  if (DSPBR_HAS_THIN_TRANSPARENT != 0 && k == DSPBR_LOBE_TRANSMISSION && b.thin_walled)
    return dspbr_ggx_reflection_pdf(b.ggx, vc, dspbr_flip_z(lc));
  if (DSPBR_HAS_OPAQUE_DIELECTRIC != 0 && k == DSPBR_LOBE_DIFFUSE) return dspbr_diffuse_pdf(b, vc, lc);
  if (DSPBR_HAS_FLAKES != 0 && k == DSPBR_LOBE_FLAKE) return dspbr_flake_pdf(b, vc, lc);
  if (!(vc.z > 0.0f)) return 0.0f;
  if (k == DSPBR_LOBE_MULTISCATTER) return dspbr_cosine_hemisphere_pdf(lc);
  return DSPBR_HAS_SHEEN != 0 && k == DSPBR_LOBE_SHEEN ? dspbr_uniform_hemisphere_pdf(lc) : 0.0f;
}

// The selection weight of lobe k at v, without its layer factor.
DSPBR_FN float dspbr_lobe_weight(DSPBR_IN(DspbrBsdf) b, int k, vec3 v, float eta_i, float eta_o, DspbrAlbedos av) {
  if (DSPBR_HAS_CLEARCOAT != 0 && k == DSPBR_LOBE_CLEARCOAT) return dspbr_reflection_weight(b, k, dspbr_to_local(b.coat, v), eta_i, eta_o);
  vec3 vc = dspbr_to_core(b, v);
  if (k == DSPBR_LOBE_CORE_REFLECTION) return dspbr_reflection_weight(b, k, vc, eta_i, eta_o);
  if (k == DSPBR_LOBE_MULTISCATTER) return dspbr_multiscatter_weight(b, vc, av);
  if (DSPBR_HAS_VOLUMETRIC_TRANSPARENT != 0 && k == DSPBR_LOBE_TRANSMISSION && !b.thin_walled)
    return dspbr_volumetric_weight(b, vc, eta_i, eta_o);
  if (DSPBR_HAS_THIN_TRANSPARENT != 0 && k == DSPBR_LOBE_TRANSMISSION && b.thin_walled)
    return dspbr_reflection_weight(b, k, vc, eta_i, eta_o);
  if (DSPBR_HAS_OPAQUE_DIELECTRIC != 0 && k == DSPBR_LOBE_DIFFUSE) return dspbr_diffuse_weight(b, vc, av);
  if (DSPBR_HAS_FLAKES != 0 && k == DSPBR_LOBE_FLAKE) return dspbr_flake_weight(b, vc);
  if (DSPBR_HAS_SHEEN != 0 && k == DSPBR_LOBE_SHEEN) return dspbr_sheen_weight(b, vc, av);
  return 0.0f;
}

// The selection probabilities of the slots at v (side coordinates): the lobes, then the cut-out's
// pass-through (1 - alpha).
struct DspbrSelection {
  float p[8];
};
DSPBR_FN DspbrSelection dspbr_select(DSPBR_IN(DspbrBsdf) b, vec3 v, float eta_i, float eta_o, DspbrAlbedos av) {
  DspbrSelection sel;
  DspbrLayers f = dspbr_layers(b, v, v, av, av);
  float max_w = 0.0f;
  for (int k = 0; k < DSPBR_LOBE_COUNT; ++k) {
    float w = 0.0f;
    if (dspbr_has_lobe(b, k)) {
      w = dspbr_lobe_weight(b, k, v, eta_i, eta_o, av) * dspbr_layer_of(f, k);
      w = (isnan(w) || isinf(w)) ? 0.0f : max(w, 0.0f);
    }
    sel.p[k] = w;
    max_w = max(max_w, w);
  }
  sel.p[DSPBR_SLOT_PASS] = b.alpha_cut < 1.0f ? 1.0f - b.alpha_cut : 0.0f;
  max_w = max(max_w, sel.p[DSPBR_SLOT_PASS]);
  float sum = 0.0f;
  for (int j = 0; j < DSPBR_SLOT_COUNT; ++j) {
    bool present = j == DSPBR_SLOT_PASS ? b.alpha_cut < 1.0f : (dspbr_has_lobe(b, j) && b.alpha_cut > 0.0f);
    if (present) sel.p[j] = max_w > 0.0f ? max(sel.p[j], dspbr_min_selection * max_w) : 1.0f;
    sum += sel.p[j];
  }
  for (int j = 0; j < DSPBR_SLOT_COUNT; ++j) sel.p[j] = sum > 0.0f ? sel.p[j] / sum : 0.0f;
  return sel;
}

// Values of f below this are returned as 0: in float they are denormal, with fewer significant
// bits than any check's tolerance (f * |cos| / pdf of such a value is not reproducible).
DSPBR_CONST float dspbr_tiny = 1e-30f;
DSPBR_FN float dspbr_flush_tiny(float x) { return x >= dspbr_tiny ? x : 0.0f; }

// The tables at w's cosine in the core frame.
DSPBR_FN DspbrAlbedos dspbr_albedos_at(DSPBR_IN(DspbrBsdf) b, vec3 w) { return dspbr_albedos(b, dot(w, b.core.n)); }

// f(v, l) and the mixture pdf on one side (v in front, side coordinates; av: the tables at v).
DSPBR_FN vec3 dspbr_eval_side(DSPBR_IN(DspbrBsdf) b, vec3 v, vec3 l, float eta_i, float eta_o, DspbrAlbedos av) {
  // v and l in the core frame, once for every lobe.
  vec3 vc = dspbr_to_core(b, v), lc = dspbr_to_core(b, l);
  if (dspbr_on_horizon(vc) || dspbr_on_horizon(lc)) return dspbr_splat(0.0f);
  DspbrAlbedos al = dspbr_albedos(b, lc.z);
  DspbrLayers f = dspbr_layers(b, v, l, av, al);
  vec3 sum = dspbr_splat(0.0f);
  for (int k = 0; k < DSPBR_LOBE_COUNT; ++k)
    if (dspbr_has_lobe(b, k) && !dspbr_is_delta_lobe(b, k))
      sum += dspbr_lobe_eval(b, k, v, l, vc, lc, eta_i, eta_o, av, al) * dspbr_layer_of(f, k);
  return vec3(dspbr_flush_tiny(sum.x), dspbr_flush_tiny(sum.y), dspbr_flush_tiny(sum.z));
}
DSPBR_FN float dspbr_pdf_side(DSPBR_IN(DspbrBsdf) b, DspbrSelection sel, vec3 v, vec3 l, float eta_i, float eta_o) {
  float p = 0.0f;
  vec3 vc = dspbr_to_core(b, v), lc = dspbr_to_core(b, l);
  if (dspbr_on_horizon(vc) || dspbr_on_horizon(lc)) return p;
  for (int k = 0; k < DSPBR_LOBE_COUNT; ++k)
    if (dspbr_has_lobe(b, k) && !dspbr_is_delta_lobe(b, k) && sel.p[k] > 0.0f)
      p += sel.p[k] * dspbr_lobe_pdf(b, k, v, l, vc, lc, eta_i, eta_o);
  return p;
}

// v and l in the side's coordinates (the frame's local ones, both negated for a viewer on the
// back) and the side's IORs.
struct DspbrSide {
  vec3 v;
  vec3 l;
  float eta_i;
  float eta_o;
};
DSPBR_FN DspbrSide dspbr_side(DSPBR_IN(DspbrBsdf) b, vec3 v_in, vec3 l_in) {
  DspbrSide s;
  s.v = dspbr_to_local(b.frame, dspbr_unit_direction(v_in));
  s.l = dspbr_to_local(b.frame, dspbr_unit_direction(l_in));
  bool back = dspbr_back_side(b, s.v);
  if (back) {
    s.v = -s.v;
    s.l = -s.l;
  }
  s.eta_i = dspbr_eta_i(b, back);
  s.eta_o = dspbr_eta_o(b, back);
  return s;
}

// f(v, l) without the cosine (delta lobes excluded).
DSPBR_FN vec3 dspbr_eval(DSPBR_IN(DspbrBsdf) b, vec3 v_in, vec3 l_in) {
  DspbrSide s = dspbr_side(b, v_in, l_in);
  return dspbr_eval_side(b, s.v, s.l, s.eta_i, s.eta_o, dspbr_albedos_at(b, s.v));
}

// The solid-angle density with which dspbr_sample produces l through its non-delta lobes.
DSPBR_FN float dspbr_pdf(DSPBR_IN(DspbrBsdf) b, vec3 v_in, vec3 l_in) {
  DspbrSide s = dspbr_side(b, v_in, l_in);
  return dspbr_pdf_side(b, dspbr_select(b, s.v, s.eta_i, s.eta_o, dspbr_albedos_at(b, s.v)), s.v, s.l, s.eta_i, s.eta_o);
}

// A direction from lobe k in the lobe's own frame (v_k: v in that frame); lw: a delta lobe's
// reflectance or transmittance. False when the sample fails.
DSPBR_FN bool dspbr_lobe_sample(DSPBR_IN(DspbrBsdf) b, int k, vec3 vk, vec3 u, float eta_i, float eta_o, DSPBR_OUT(vec3) l,
                                DSPBR_OUT(vec3) lw) {
  l = vec3(0.0f, 0.0f, 1.0f);
  lw = dspbr_splat(0.0f);
  if (!(vk.z > 0.0f)) return false;
  bool delta = dspbr_is_delta_lobe(b, k);
  if (k == DSPBR_LOBE_CORE_REFLECTION || k == DSPBR_LOBE_CLEARCOAT ||
      (k == DSPBR_LOBE_TRANSMISSION && b.thin_walled)) {
    DspbrGgx g = dspbr_lobe_ggx(b, k);
    if (delta) {
      l = vec3(-vk.x, -vk.y, vk.z);
      lw = dspbr_lobe_factor(b, k, vk.z, eta_i, eta_o);
    } else {
      vec3 h = dspbr_ggx_sample_wm(g, vk, u.y, u.z);
      if (!(dot(vk, h) > 0.0f)) return false;
      l = normalize(dspbr_reflect(vk, h));
      if (!(dspbr_ggx_reflection_pdf(g, vk, l) > 0.0f)) return false;
    }
    if (k == DSPBR_LOBE_TRANSMISSION) l = dspbr_flip_z(l);
    return true;
  }
  if (k == DSPBR_LOBE_TRANSMISSION) {
    float eta = eta_i / eta_o;
    if (delta) {
      if (!dspbr_refract(vk, vec3(0.0f, 0.0f, 1.0f), abs(eta - 1.0f) < dspbr_index_matched ? 1.0f : eta, l)) return false;
      lw = dspbr_core_transmission_factor(b, vk.z, eta_i, eta_o);
      return true;
    }
    vec3 h = dspbr_ggx_sample_wm(b.ggx, vk, u.y, u.z);
    if (!(dot(vk, h) > 0.0f) || !dspbr_refract(vk, h, eta, l)) return false;
    return dspbr_volumetric_pdf(b, vk, l, eta_i, eta_o) > 0.0f;
  }
  if (DSPBR_HAS_FLAKES != 0 && k == DSPBR_LOBE_FLAKE) return dspbr_flake_sample(b, vk, u.y, u.z, l, lw);
  if (DSPBR_HAS_SHEEN != 0 && k == DSPBR_LOBE_SHEEN) {
    l = dspbr_sample_uniform_hemisphere(u.y, u.z);
    return l.z > 0.0f;
  }
  l = dspbr_sample_cosine_hemisphere(u.y, u.z);
  if (k == DSPBR_LOBE_DIFFUSE && u.x < b.translucency) l = -l;
  return k == DSPBR_LOBE_DIFFUSE ? dspbr_diffuse_pdf(b, vk, l) > 0.0f : l.z > 0.0f;
}

// Samples l for v with three uniform numbers u in [0, 1): u.x chooses the lobe (and is reused,
// rescaled, by the diffuse lobe's choice of side), u.y and u.z the direction.
DSPBR_FN DspbrSample dspbr_sample(DSPBR_IN(DspbrBsdf) b, vec3 v_in, vec3 u) {
  DspbrSample out_s = dspbr_failed_sample();
  vec3 v = dspbr_to_local(b.frame, dspbr_unit_direction(v_in));
  bool back = dspbr_back_side(b, v);
  if (back) v = -v;
  float eta_i = dspbr_eta_i(b, back), eta_o = dspbr_eta_o(b, back);
  DspbrAlbedos av = dspbr_albedos_at(b, v);
  DspbrSelection sel = dspbr_select(b, v, eta_i, eta_o, av);
  // The slot whose interval of the cumulative probabilities holds u.x (rounding: the last slot
  // with a non-zero probability).
  int chosen = -1, last = -1;
  float cum = 0.0f, cum_last = 0.0f;
  for (int j = 0; j < DSPBR_SLOT_COUNT; ++j) {
    if (chosen >= 0 || !(sel.p[j] > 0.0f)) continue;
    if (u.x < cum + sel.p[j]) {
      chosen = j;
    } else {
      last = j;
      cum_last = cum;
      cum += sel.p[j];
    }
  }
  if (chosen < 0) {
    if (last < 0) return out_s;
    chosen = last;
    cum = cum_last;
  }
  float p = sel.p[chosen];
  vec3 l;
  if (chosen == DSPBR_SLOT_PASS) {
    l = -v;
    out_s.weight = dspbr_splat((1.0f - b.alpha_cut) / p);
    out_s.pdf = p;
    out_s.flags = DSPBR_FLAG_TRANSMISSION | DSPBR_FLAG_DELTA;
  } else {
    float ux = clamp((u.x - cum) / p, 0.0f, 0.99999994f);
    DspbrFrame lf = chosen == DSPBR_LOBE_CLEARCOAT ? b.coat : b.core;
    vec3 vk = dspbr_to_local(lf, v);
    if (dspbr_on_horizon(vk) || dspbr_on_horizon(dspbr_to_core(b, v))) return out_s;
    vec3 lk, lw;
    if (!dspbr_lobe_sample(b, chosen, vk, vec3(ux, u.y, u.z), eta_i, eta_o, lk, lw)) return out_s;
    l = normalize(dspbr_to_world(lf, lk));
    uint side = l.z * v.z >= 0.0f ? DSPBR_FLAG_REFLECTION : DSPBR_FLAG_TRANSMISSION;
    if (dspbr_is_delta_lobe(b, chosen)) {
      if (chosen == DSPBR_LOBE_CLEARCOAT && !(dot(l, b.core.n) > 0.0f)) return out_s;  // as in eval
      out_s.weight = lw * (dspbr_layer_of(dspbr_layers(b, v, l, av, dspbr_albedos_at(b, l)), chosen) / p);
      out_s.pdf = p;
      out_s.flags = DSPBR_FLAG_DELTA | side;
    } else {
      out_s.pdf = dspbr_pdf_side(b, sel, v, l, eta_i, eta_o);
      if (!(out_s.pdf > 0.0f)) return out_s;
      out_s.weight = dspbr_eval_side(b, v, l, eta_i, eta_o, av) * (abs(l.z) / out_s.pdf);
      bool diffuse = chosen == DSPBR_LOBE_MULTISCATTER || chosen == DSPBR_LOBE_DIFFUSE;
      out_s.flags = (diffuse ? DSPBR_FLAG_DIFFUSE : DSPBR_FLAG_GLOSSY) | side;
    }
  }
  if (back) l = -l;
  out_s.l = dspbr_to_world(b.frame, l);
  // Never a valid sample without a direction: a zero v (a view of no length, NaN or Inf) passes
  // through a cut-out as l = 0, and a refraction into a volume of ior 1e8 at exactly normal
  // incidence from inside gave NaN (the eleventh fresh tester's pass).
  float ll = dot(out_s.l, out_s.l);
  if (!(ll > 0.0f) || isinf(ll)) return dspbr_failed_sample();
  out_s.valid = true;
  return out_s;
}

// Emitted radiance L_e(v) = rho_e (1 - c F_c(v.n_c)) for v above the core's surface, times the
// cut-out opacity (spec "Emission"; cd/m^2).
DSPBR_FN vec3 dspbr_emission(DSPBR_IN(DspbrBsdf) b, vec3 v_in) {
  if (DSPBR_HAS_EMISSION == 0 || !(dspbr_max3(b.rho_e) > 0.0f)) return dspbr_splat(0.0f);
  vec3 vc = dspbr_to_core(b, dspbr_to_local(b.frame, dspbr_unit_direction(v_in)));
  if (!(vc.z > 0.0f)) return dspbr_splat(0.0f);
  float fc = dspbr_clearcoat_fresnel(dot(vc, dspbr_to_core(b, b.coat.n)));
  return b.rho_e * ((1.0f - b.clearcoat * fc) * b.alpha_cut);
}
