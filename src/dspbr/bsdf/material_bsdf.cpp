#include "dspbr/bsdf/material_bsdf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dspbr/bsdf/diffuse.h"
#include "dspbr/bsdf/dispersion.h"
#include "dspbr/bsdf/emission.h"
#include "dspbr/bsdf/flake_lobe.h"
#include "dspbr/bsdf/flakes.h"
#include "dspbr/bsdf/microfacet_reflection.h"
#include "dspbr/bsdf/multiscatter.h"
#include "dspbr/bsdf/sampling.h"
#include "dspbr/bsdf/shading_frame.h"
#include "dspbr/bsdf/thin_film.h"
#include "dspbr/bsdf/thin_transmission.h"
#include "dspbr/bsdf/transmission_compensation.h"
#include "dspbr/bsdf/volumetric_transmission.h"
#include "dspbr/fresnel.h"
#include "dspbr/ggx.h"
#include "dspbr/component.h"

namespace dspbr {

namespace {

// Clearcoat Fresnel F_c = 0.04 + 0.96 (1 - cos)^5 (spec "Clearcoat", eta = 1.5).
double fresnel_clearcoat(double cos_theta) { return fresnel_schlick(cos_theta, 0.04, 1.0); }

// Each present lobe gets at least this fraction of the largest selection weight, so that no lobe
// with a non-zero value is left unsampled when its albedo estimate is poor.
constexpr double kMinSelectionFraction = 1e-3;


}  // namespace

void MaterialBsdf::add_transmission_compensation(std::vector<Entry>& out, const LutSet& luts, bool inside,
                                                 double r_uv, double eta, double w_transp, const Rgb& rho_s,
                                                 const Rgb& rho) const {
  // docs/bsdf.md, "Transmission compensation". E: albedo of the white core (specular 1) on one
  // side, including its M_r,ms F_ms term, whose albedo is F_ms (1 - E_m) (closed form).
  const double F0 = f0_from_ior(1.0, eta);
  const double f_ms = fresnel_ms(F0, 1.0, std::clamp(luts.E_m_avg(r_uv), 0.0, 1.0));
  const double missing_m_avg = luts.missing_E_m_avg(r_uv);
  // Share of the missing energy that leaves through the other side: the average transmittance of
  // Schlick's Fresnel, 1 - F_avg (spec eq. fr_avg), on the side of the viewer outside.
  double x_out = 1.0 - fresnel_avg(F0, 1.0), x_in = x_out;
  TransmissionCompensation::AlbedoFn e_v, e_other;
  double avg_v, avg_other;
  if (thin_walled_) {
    // Thin-walled: E = E_m + F_ms (1 - E_m) on both sides (reflection F, transmission 1 - F of
    // the same M_r), so 1 - E = (1 - E_m)(1 - F_ms): no table beyond GGX_E / GGX_E_avg.
    const LutSet* lp = &luts;  // the caller's set outlives the BSDF (as for the other lobes)
    e_v = e_other = [lp, r_uv, f_ms](double c) { return 1.0 - (1.0 - f_ms) * (1.0 - lp->E_m(c, r_uv)); };
    avg_v = avg_other = 1.0 - (1.0 - f_ms) * missing_m_avg;
  } else {
    // The glass tables of the set, or the built-in published ones when it has none (a renderer
    // file written without them).
    const LutSet* gp = luts.has_glass() ? &luts : &LutSet::published();
    if (!gp->has_glass()) throw std::runtime_error("transmission compensation: no Glass tables (dspbr lut)");
    const LutSet* lp = &luts;
    auto side_fn = [gp, lp, r_uv, eta, f_ms](bool in) -> TransmissionCompensation::AlbedoFn {
      return [gp, lp, r_uv, eta, f_ms, in](double c) {
        return gp->E_glass(c, r_uv, eta, in) + f_ms * (1.0 - lp->E_m(c, r_uv));
      };
    };
    const double avg_out = gp->E_glass_avg(r_uv, eta, false) + f_ms * missing_m_avg;
    const double avg_in = gp->E_glass_avg(r_uv, eta, true) + f_ms * missing_m_avg;
    // Reciprocity of the transmission parts, f(v, l) / eta_o^2 = f(l, v) / eta_i^2 (docs/bsdf.md):
    // x_in (1 - E_in,avg) eta^2 = x_out (1 - E_out,avg); x_in <= 1 bounds x_out.
    const double m_out = std::max(1.0 - avg_out, 0.0), m_in = std::max(1.0 - avg_in, 0.0);
    if (m_in > kMinMissingEnergy) {
      x_in = x_out * m_out / (eta * eta * m_in);
      if (x_in > 1.0) {
        x_in = 1.0;
        x_out = eta * eta * m_in / std::max(m_out, kMinMissingEnergy);
      }
    } else {
      x_out = x_in = 0.0;
    }
    e_v = side_fn(inside);
    e_other = side_fn(!inside);
    avg_v = inside ? avg_in : avg_out;
    avg_other = inside ? avg_out : avg_in;
  }
  const double x = inside && !thin_walled_ ? x_in : x_out;
  const Rgb refl = (1.0 - x) * w_transp * rho_s, trans = x * w_transp * rho;
  if (refl.max_component() > 0)
    out.push_back({std::make_unique<TransmissionCompensation>(false, refl, e_v, e_v, avg_v), kCoreLayer, &core_});
  if (trans.max_component() > 0)
    out.push_back({std::make_unique<TransmissionCompensation>(true, trans, e_v, e_other, avg_other), kCoreLayer,
                   &core_});
}

MaterialBsdf::MaterialBsdf(const Material& m, const LutSet& luts, const BsdfOptions& opt)
    : MaterialBsdf(m, luts, opt, active_components(m)) {}

MaterialBsdf::MaterialBsdf(const Material& m, const LutSet& luts, const BsdfOptions& opt, uint32_t mask)
    : mask_(mask) {
  build(m, luts, opt);
}

MaterialBsdf::~MaterialBsdf() = default;

bool MaterialBsdf::back_side(const Vec3& v) const {
  // Thin-walled: the side of the shading normal (keeps reciprocity with normal maps);
  // volume boundary: the geometric side (v.z < 0 is inside the object).
  return thin_walled_ ? dot(v, core_.n) < 0 : v.z < 0;
}

void MaterialBsdf::build(const Material& m, const LutSet& luts, const BsdfOptions& opt) {
  core_ = core_frame(m);
  thin_walled_ = m.thinWalled;
  compensate_transmission_ = opt.transmission_compensation;
  coat_ = clearcoat_frame(m);
  alpha_cut_ = std::clamp(m.cutoutOpacity, 0.0, 1.0);
  clearcoat_ = (mask_ & kClearcoat) ? m.clearcoat : 0.0;
  eta_ = m.ior;
  // Dispersion (spec "Dispersion"): eta(lambda) replaces ior at the caller's wavelength.
  if ((mask_ & kDispersion) && opt.wavelength_nm > 0 && m.abbeNumber > 0)
    eta_ = dispersion_ior(m, opt.wavelength_nm);
  if ((mask_ & kFlakes) && m.flakeCoverage > 0) {
    const Flake flake = flake_at(opt.position, opt.object_normal, m);
    flake_opaque_ = flake.opacity > 0;
  }
  if ((mask_ & kSheen) && m.sheenColor.max_component() > 0 && !flake_opaque_)
    sheen_scaler_ = std::make_unique<SheenLobe>(m.sheenColor, m.sheenRoughness, opt.sheen_model, luts);
  if ((mask_ & kEmission) && m.emissionValue > 0) rho_e_ = emission_rho_e(m, opt.object_area_m2);
  sides_[0] = build_side(m, luts, false);
  sides_[1] = build_side(m, luts, true);
  // The flake lobe needs the flake normal: added here (same on both sides).
  if (flake_opaque_) {
    const Flake flake = flake_at(opt.position, opt.object_normal, m);
    for (auto& side : sides_)
      side.push_back({std::make_unique<FlakeLobe>(flake.normal, m), kFlakeLayer, &core_});
  }
}

std::vector<MaterialBsdf::Entry> MaterialBsdf::build_side(const Material& m, const LutSet& luts,
                                                          bool inside) const {
  std::vector<Entry> out;
  // ---- Core (spec "Putting It All Together", "Thin Film") -----------------------------------
  const double metal = m.metallic, t = m.transparency, s = m.specular;
  const bool volumetric = !m.thinWalled;
  const double w_metal = (mask_ & kMetallic) ? metal : 0.0;
  const double w_opaque = (mask_ & kOpaqueDielectric) ? (1 - metal) * (1 - t) : 0.0;
  const double w_transp = (mask_ & (volumetric ? kVolumetricTransparent : kThinTransparent)) ? (1 - metal) * t : 0.0;
  const double l = (mask_ & kTranslucency) ? m.translucency : 0.0;
  const double i = (mask_ & kThinFilm) ? m.thinFilm : 0.0;
  const Rgb rho = m.albedo, rho_s = m.specularTint, rho_l = m.translucencyColor;
  const double eta = eta_;
  // eta_i: IOR on v's side, eta_o: the other side (volumetric transparent part only).
  const double eta_i = (volumetric && inside) ? eta : 1.0, eta_o = (volumetric && inside) ? 1.0 : eta;
  const double F0 = f0_from_ior(1.0, eta);
  const Roughness2 ruv = anisotropic_roughness(m.roughness, m.anisotropy);
  const double alpha_u = roughness_to_alpha(ruv.u), alpha_v = roughness_to_alpha(ruv.v);
  const double r_uv = std::sqrt(ruv.u * ruv.v);

  // ThinCore weights: rho_s,r,0 = (1-m) F_0 s rho_s + m rho; rho_s,r,90 = (1-m) s + m;
  // rho_t = rho (1-m) t; rho_d = (rho (1-l) + rho_l l) (1-m) (1-t).
  const Rgb rho_sr0 = (w_opaque + w_transp) * s * F0 * rho_s + w_metal * rho;
  const Rgb rho_sr90 = Rgb((w_opaque + w_transp) * s + w_metal);
  const Rgb rho_t = rho * w_transp;
  const Rgb rho_d = (rho * (1 - l) + rho_l * l) * w_opaque;
  const Rgb f0_diel = F0 * rho_s;

  // Thin-film reflectance R(cos theta, eta_base, d_i, eta_i) with air above the film.
  const double d_film = m.thinFilmThickness, eta_film = m.thinFilmIor;
  const double eta_rho = thin_film_metal_eta(rho);
  auto R = [d_film, eta_film](double c, double eta_base) {
    return thin_film_reflectance(c, eta_base, d_film, eta_film);
  };
  // R for a cosine measured on v's side of a volumetric boundary: from inside, the film is seen
  // through the base; a lossless stack reflects equally from both sides at corresponding angles,
  // and total internal reflection gives 1.
  auto R_side = [R, eta_i, eta_o, eta](double c) {
    if (eta_i <= eta_o) return R(c, eta);
    const double s2 = sin2_transmitted(c, eta_i, eta_o);
    if (s2 >= 1.0) return Rgb(1.0);
    return R(std::sqrt(1.0 - s2), eta);
  };

  const bool has_core = !flake_opaque_ && (w_metal + w_opaque + w_transp) > 0;
  if (has_core) {
    // M_r with the core Fresnel. ThinCore: F(rho_s,r,0, rho_s,r,90); VolumetricCore:
    // m F(rho, 1) + (1-m)(1-t) s F(F_0 rho_s, 1) + (1-m) t s F_d(F_0 rho_s, 1). With a thin film of
    // weight i: (1-i) times that + i [m R(eta_rho) + (1-m)(1-t) R(eta) + (1-m) t R(eta)], the
    // ThinFilmOverCore definition (see docs/bsdf.md for the two misprints this corrects).
    CosineFn fresnel = [=](double c) {
      Rgb f = volumetric ? w_metal * fresnel_schlick(c, rho, Rgb(1.0)) +
                               w_opaque * s * fresnel_schlick(c, f0_diel, Rgb(1.0)) +
                               w_transp * s * fresnel_schlick_d(c, f0_diel, Rgb(1.0), eta_i, eta_o)
                         : fresnel_schlick(c, rho_sr0, rho_sr90);
      if (i > 0) {
        Rgb fr = w_opaque * R(c, eta) + w_transp * (volumetric ? R_side(c) : R(c, eta));
        if (w_metal > 0) fr += w_metal * R(c, eta_rho);
        f = (1 - i) * f + i * fr;
      }
      return f;
    };
    // Present unless every Fresnel weight vanishes (e.g. a dielectric with s = 0 and no film).
    if (w_metal > 0 || s * (w_opaque + w_transp) > 0 || i > 0)
      out.push_back({std::make_unique<MicrofacetReflection>(alpha_u, alpha_v, fresnel), kCoreLayer, &core_});
    // M_r,ms F_ms(rho_s,r,0, rho_s,r,90) (same for every film weight). A mirror (delta M_r) has
    // E_m = 1 exactly: no compensation (the tables' first roughness sample is not at r = 0).
    const Rgb f_ms = fresnel_ms(rho_sr0, rho_sr90, std::clamp(luts.E_m_avg(r_uv), 0.0, 1.0));
    const bool mirror = std::max(alpha_u, alpha_v) < kDeltaAlpha;
    if (f_ms.max_component() > 0 && !mirror)
      out.push_back({std::make_unique<MultiScatterReflection>(r_uv, f_ms, luts), kCoreLayer, &core_});
    // Transmission: rho_t M_t' (1 - s F) (thin) or rho_t M_t (1 - s F_d) (volumetric); with a film
    // (1-i) times that + i rho_t M_t (1 - R).
    if (w_transp > 0 && rho_t.max_component() > 0) {
      if (volumetric) {
        CosineFn factor = [=](double c) {
          Rgb f = rho_t * (1.0 - s * fresnel_schlick_d(c, f0_diel, Rgb(1.0), eta_i, eta_o));
          if (i > 0) f = (1 - i) * f + i * rho_t * (1.0 - R_side(c));
          return f;
        };
        out.push_back({std::make_unique<VolumetricTransmission>(alpha_u, alpha_v, eta_i, eta_o, factor), kCoreLayer,
                       &core_});
      } else {
        CosineFn factor = [=](double c) {
          Rgb f = rho_t * (1.0 - s * fresnel_schlick(c, f0_diel, Rgb(1.0)));
          if (i > 0) f = (1 - i) * f + i * rho_t * (1.0 - R(c, eta));
          return f;
        };
        out.push_back({std::make_unique<ThinTransmission>(alpha_u, alpha_v, factor), kCoreLayer, &core_});
      }
      // Not for index-matched volumetric media: the transmission is then a Dirac that loses nothing.
      const bool matched = volumetric && std::abs(eta - 1.0) < kIndexMatched;
      if (compensate_transmission_ && !mirror && !matched) add_transmission_compensation(out, luts, inside, r_uv, eta, w_transp, rho_s, rho);
    }
    // Diffuse base rho_d [B_u (1 - s) + s B_c(F_0 rho_s)] (+ film term).
    if (w_opaque > 0 && rho_d.max_component() > 0) {
      DiffuseParams dp;
      dp.rho_d = rho_d;
      dp.specular = s;
      dp.translucency = l;
      dp.f0_max = f0_diel.max_component();
      dp.r_uv = r_uv;
      dp.film_weight = i;
      dp.film_reflectance = [R, eta](double c) { return R(c, eta); };
      out.push_back({std::make_unique<DiffuseBase>(dp, luts), kCoreLayer, &core_});
    }
  }
  // ---- Sheen (ShinyCore: + M_b rho_b) -------------------------------------------------------------
  if (sheen_scaler_) {
    out.push_back({std::make_unique<SheenLobe>(*sheen_scaler_), kSheenLayer, &core_});
  }
  // ---- Clearcoat (Coated: + M_c c F_c(h.v), isotropic GGX alpha = r_c^2) --------------------------
  if (clearcoat_ > 0) {
    const double a = roughness_to_alpha(m.clearcoatRoughness), c = clearcoat_;
    CosineFn fc = [c](double cos_theta) { return Rgb(c * fresnel_clearcoat(cos_theta)); };
    out.push_back({std::make_unique<MicrofacetReflection>(a, a, fc), kCoatLayer, &coat_});
  }
  // ---- Cut-out pass-through -------------------------------------------------------------------------
  if (alpha_cut_ < 1) out.push_back({nullptr, kCutoutLayer, nullptr});
  return out;
}

double MaterialBsdf::layer_factor(Layer layer, const Vec3& v, const Vec3& l) const {
  if (layer == kCutoutLayer) return 1.0 - alpha_cut_;
  double f = alpha_cut_;
  if (layer == kCoatLayer) return f;
  if (clearcoat_ > 0) {
    // Coated: GlitteryCore (1 - c max(F_c(v.n_c), F_c(l.n_c))); |cos| for a transmitted l.
    f *= 1.0 - clearcoat_ * std::max(fresnel_clearcoat(dot(v, coat_.n)), fresnel_clearcoat(dot(l, coat_.n)));
  }
  if (layer == kCoreLayer && sheen_scaler_) f *= sheen_scaler_->layer_scale(dot(v, core_.n), dot(l, core_.n));
  return f;
}

void MaterialBsdf::selection(const std::vector<Entry>& side, const Vec3& v, std::vector<double>& probs) const {
  probs.assign(side.size(), 0.0);
  double max_w = 0;
  for (size_t k = 0; k < side.size(); ++k) {
    const Entry& e = side[k];
    double w;
    if (!e.lobe) w = 1.0 - alpha_cut_;
    else w = e.lobe->sampling_weight(e.frame->to_local(v)) * layer_factor(e.layer, v, v);
    probs[k] = std::isfinite(w) ? std::max(w, 0.0) : 0.0;
    max_w = std::max(max_w, probs[k]);
  }
  double sum = 0;
  for (size_t k = 0; k < side.size(); ++k) {
    // A lobe scaled by a zero layer factor (alpha = 0 ...) stays at 0; the cut-out pass-through
    // only when alpha = 1 (then it is absent anyway).
    const bool present = side[k].lobe ? alpha_cut_ > 0 : alpha_cut_ < 1;
    if (present) probs[k] = max_w > 0 ? std::max(probs[k], kMinSelectionFraction * max_w) : 1.0;
    sum += probs[k];
  }
  if (sum > 0)
    for (double& p : probs) p /= sum;
}

Rgb MaterialBsdf::eval_side(const std::vector<Entry>& side, const Vec3& v, const Vec3& l) const {
  Rgb f(0);
  for (const Entry& e : side) {
    if (!e.lobe || e.lobe->is_delta()) continue;
    // The coat reflects: nothing towards the other side of the surface (its own normal n_c may
    // differ from n; without this check f(v, l) != f(l, v) where the two planes disagree).
    if (e.layer == kCoatLayer && !(dot(l, core_.n) > 0)) continue;
    const Rgb fk = e.lobe->eval(e.frame->to_local(v), e.frame->to_local(l));
    if (fk.max_component() > 0) f += fk * layer_factor(e.layer, v, l);
  }
  return f;
}

double MaterialBsdf::pdf_side(const std::vector<Entry>& side, const Vec3& v, const Vec3& l,
                              const std::vector<double>& probs) const {
  double p = 0;
  for (size_t k = 0; k < side.size(); ++k) {
    const Entry& e = side[k];
    if (!e.lobe || e.lobe->is_delta() || probs[k] == 0) continue;
    p += probs[k] * e.lobe->pdf(e.frame->to_local(v), e.frame->to_local(l));
  }
  return p;
}

Rgb MaterialBsdf::eval(const Vec3& v_in, const Vec3& l_in) const {
  const bool inside = back_side(v_in);
  const Vec3 v = inside ? -v_in : v_in, l = inside ? -l_in : l_in;
  return eval_side(sides_[inside], v, l);
}

double MaterialBsdf::pdf(const Vec3& v_in, const Vec3& l_in) const {
  const bool inside = back_side(v_in);
  const Vec3 v = inside ? -v_in : v_in, l = inside ? -l_in : l_in;
  std::vector<double> probs;
  selection(sides_[inside], v, probs);
  return pdf_side(sides_[inside], v, l, probs);
}

double MaterialBsdf::delta_probability(const Vec3& v_in) const {
  const bool inside = back_side(v_in);
  const Vec3 v = inside ? -v_in : v_in;
  const auto& side = sides_[inside];
  std::vector<double> probs;
  selection(side, v, probs);
  double p = 0;
  for (size_t k = 0; k < side.size(); ++k)
    if (!side[k].lobe || side[k].lobe->is_delta()) p += probs[k];
  return p;
}

BsdfSample MaterialBsdf::sample(const Vec3& v_in, const Vec3& u) const {
  BsdfSample out;
  const bool inside = back_side(v_in);
  const Vec3 v = inside ? -v_in : v_in;
  const auto& side = sides_[inside];
  std::vector<double> probs;
  selection(side, v, probs);
  // Choose a lobe with u.x and rescale u.x to [0, 1) inside the chosen interval.
  // (Rounding of the cumulative sum: u.x beyond it picks the last lobe with a non-zero probability.)
  size_t k = side.size(), last = side.size();
  double cum = 0, cum_last = 0;
  for (size_t j = 0; j < side.size(); ++j) {
    if (!(probs[j] > 0)) continue;
    if (u.x < cum + probs[j]) {
      k = j;
      break;
    }
    last = j;
    cum_last = cum;
    cum += probs[j];
  }
  if (k == side.size()) {
    if (last == side.size()) return out;  // nothing to sample
    k = last;
    cum = cum_last;
  }
  const double ux = std::clamp((u.x - cum) / probs[k], 0.0, std::nextafter(1.0, 0.0));
  const Entry& e = side[k];
  Vec3 l;
  if (!e.lobe) {  // cut-out pass-through: l = -v, weight (1 - alpha) / P
    out.l = -v_in;
    out.weight = Rgb((1.0 - alpha_cut_) / probs[k]);
    out.pdf = probs[k];
    out.flags = kLobeTransmission | kLobeDelta;
    out.valid = true;
    return out;
  }
  const Vec3 vk = e.frame->to_local(v);
  const BsdfSample s = e.lobe->sample(vk, {ux, u.y, u.z});
  if (!s.valid) return out;
  l = normalize(e.frame->to_world(s.l));
  if (s.flags & kLobeDelta) {
    if (e.layer == kCoatLayer && !(dot(l, core_.n) > 0)) return out;  // as in eval_side
    out.weight = s.weight * (layer_factor(e.layer, v, l) / probs[k]);
    out.pdf = probs[k] * s.pdf;
    out.flags = kLobeDelta | (l.z * v.z >= 0 ? kLobeReflection : kLobeTransmission);
  } else {
    out.pdf = pdf_side(side, v, l, probs);
    if (!(out.pdf > 0)) return out;
    out.weight = eval_side(side, v, l) * (std::abs(l.z) / out.pdf);
    out.flags = (s.flags & (kLobeGlossy | kLobeDiffuse)) | (l.z * v.z >= 0 ? kLobeReflection : kLobeTransmission);
  }
  out.l = inside ? -l : l;
  out.valid = true;
  return out;
}

uint32_t MaterialBsdf::flags() const {
  uint32_t f = 0;
  for (const auto& side : sides_)
    for (const Entry& e : side) f |= e.lobe ? e.lobe->flags() : (kLobeTransmission | kLobeDelta);
  return f;
}

Rgb MaterialBsdf::emission(const Vec3& v) const {
  // Spec "Emission": L_e(v) = rho_e (1 - c F_c(v.n_c)) if v.n > 0 (in the core frame: n = +z),
  // scaled by the cut-out opacity (a cut-out hole emits nothing).
  if (rho_e_.max_component() <= 0) return Rgb(0);
  return emission_radiance(rho_e_, core_.to_local(v), core_.to_local(coat_.n), clearcoat_) * alpha_cut_;
}

std::unique_ptr<MaterialBsdf> make_component_bsdf(const std::string& name, const Material& m, const LutSet& luts,
                                                  const BsdfOptions& opt) {
  const uint32_t active = active_components(m);
  const uint32_t core = kMetallic | kOpaqueDielectric | kThinTransparent | kVolumetricTransparent;
  uint32_t mask = 0;
  for (Component c : all_components())
    if (name == component_name(c)) mask = c;
  if (!mask) throw std::invalid_argument("unknown BSDF component '" + name + "'");
  if (mask == kTranslucency) mask |= kOpaqueDielectric;
  if (mask == kThinFilm) mask |= active & core;
  if (mask == kDispersion) mask |= kVolumetricTransparent;
  return std::make_unique<MaterialBsdf>(m, luts, opt, mask);
}

}  // namespace dspbr
