#include "dspbr/bsdf/lobe_assembly.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dspbr/bsdf/cosine_factor.h"
#include "dspbr/bsdf/diffuse.h"
#include "dspbr/bsdf/dispersion.h"
#include "dspbr/bsdf/emission.h"
#include "dspbr/bsdf/flake_lobe.h"
#include "dspbr/bsdf/flakes.h"
#include "dspbr/bsdf/microfacet_reflection.h"
#include "dspbr/bsdf/multiscatter.h"
#include "dspbr/bsdf/shading_frame.h"
#include "dspbr/bsdf/thin_film.h"
#include "dspbr/bsdf/thin_transmission.h"
#include "dspbr/bsdf/transmission_compensation.h"
#include "dspbr/bsdf/volumetric_transmission.h"
#include "dspbr/component.h"
#include "dspbr/fresnel.h"
#include "dspbr/ggx.h"

namespace dspbr {

namespace {

using Layer = LobeMixture::Layer;

// What the assembly of one side reads besides the material and the tables.
struct SideInputs {
  uint32_t mask;
  double eta;
  bool flake_opaque;
  bool compensate_transmission;
  Deviation deviation;
  const std::optional<SheenLobe>& sheen;
  const FilmLayer& film;  // with the tables of R when the film is on
  const AssembledLobes& a;
};

// The transmission-compensation lobes of the transparent part (weight w_transp) of one side.
void add_transmission_compensation(LobeMixture& out, const LutSet& luts, bool thin_walled, bool inside, double r_uv,
                                   double eta, double w_transp, const Rgb& rho_s, const Rgb& rho) {
  // docs/bsdf.md, "Transmission compensation". E: albedo of the white core (specular 1) on one
  // side, including its M_r,ms F_ms term, whose albedo is F_ms (1 - E_m) (closed form).
  const double F0 = f0_from_ior(1.0, eta);
  const double f_ms = fresnel_ms(F0, 1.0, std::clamp(luts.E_m_avg(r_uv), 0.0, 1.0));
  const double missing_m_avg = luts.missing_E_m_avg(r_uv);
  // Share of the missing energy that leaves through the other side: the average transmittance of
  // Schlick's Fresnel, 1 - F_avg (spec eq. fr_avg), on the side of the viewer outside.
  double x_out = 1.0 - fresnel_avg(F0, 1.0), x_in = x_out;
  // The lobes own what they read: slices cut here at (r_uv, eta), the averages as numbers.
  CoreAlbedo e_v{AlbedoSlice::E_m(luts, r_uv), std::nullopt, f_ms}, e_other = e_v;
  double avg_v, avg_other;
  if (thin_walled) {
    // Thin-walled: E = E_m + F_ms (1 - E_m) on both sides (reflection F, transmission 1 - F of
    // the same M_r), so 1 - E = (1 - E_m)(1 - F_ms): no table beyond GGX_E / GGX_E_avg.
    avg_v = avg_other = 1.0 - (1.0 - f_ms) * missing_m_avg;
  } else {
    // The glass tables of the set, or the built-in published ones when it has none (a renderer
    // file written without them).
    const LutSet& g = luts.has_glass() ? luts : LutSet::published();
    if (!g.has_glass()) throw std::runtime_error("transmission compensation: no Glass tables (dspbr lut)");
    const double avg_out = g.E_glass_avg(r_uv, eta, false) + f_ms * missing_m_avg;
    const double avg_in = g.E_glass_avg(r_uv, eta, true) + f_ms * missing_m_avg;
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
    e_v.glass = AlbedoSlice::E_glass(g, r_uv, eta, inside);
    e_other.glass = AlbedoSlice::E_glass(g, r_uv, eta, !inside);
    avg_v = inside ? avg_in : avg_out;
    avg_other = inside ? avg_out : avg_in;
  }
  const double x = inside && !thin_walled ? x_in : x_out;
  const Rgb refl = (1.0 - x) * w_transp * rho_s, trans = x * w_transp * rho;
  if (refl.max_component() > 0)
    out.add(std::make_unique<TransmissionCompensation>(false, refl, e_v, e_v, avg_v), Layer::Core);
  if (trans.max_component() > 0)
    out.add(std::make_unique<TransmissionCompensation>(true, trans, std::move(e_v), std::move(e_other), avg_other),
            Layer::Core);
}

// The lobes of one side (spec "Putting It All Together"), without the flake lobe.
LobeMixture assemble_side(const Material& m, const LutSet& luts, const SideInputs& in, bool inside) {
  const AssembledLobes& a = in.a;
  const uint32_t mask = in.mask;
  const Deviation dev = in.deviation;
  const double guard = dev == Deviation::LambdaZeroAtGrazing ? kGrazingGuardCos : 0.0;
  LobeMixture::Layering layering;
  layering.core = a.core;
  layering.coat = a.coat;
  layering.clearcoat = a.clearcoat;
  layering.sheen = in.sheen;
  LobeMixture out(std::move(layering));
  // ---- Core (spec "Putting It All Together", "Thin Film") -----------------------------------
  const double metal = m.metallic, t = m.transparency, s = m.specular;
  const bool volumetric = !m.thinWalled;
  const double w_metal = (mask & kMetallic) ? metal : 0.0;
  const double w_opaque = (mask & kOpaqueDielectric) ? (1 - metal) * (1 - t) : 0.0;
  const double w_transp = (mask & (volumetric ? kVolumetricTransparent : kThinTransparent)) ? (1 - metal) * t : 0.0;
  const double l = (mask & kTranslucency) ? m.translucency : 0.0;
  const double i = (mask & kThinFilm) ? m.thinFilm : 0.0;
  const Rgb rho = m.albedo, rho_s = m.specularTint, rho_l = m.translucencyColor;
  const double eta = in.eta;
  // eta_i: IOR on v's side, eta_o: the other side (volumetric transparent part only).
  const double eta_i = (volumetric && inside) ? eta : 1.0, eta_o = (volumetric && inside) ? 1.0 : eta;
  const double F0 = f0_from_ior(1.0, eta);
  const Roughness2 ruv = anisotropic_roughness(m.roughness, m.anisotropy);
  const double alpha_u = roughness_to_alpha(ruv.u), alpha_v = roughness_to_alpha(ruv.v);
  const double r_uv = std::sqrt(ruv.u * ruv.v);

  // ThinCore weights: rho_s,r,0 = (1-m) F_0 s rho_s + m rho; rho_s,r,90 = (1-m) s + m;
  // rho_t = rho (1-m) t; rho_d = (rho (1-l) + rho_l l) (1-m) (1-t).
  CoreFresnel core;
  core.volumetric = volumetric;
  core.w_metal = w_metal, core.w_opaque = w_opaque, core.w_transp = w_transp;
  core.specular = s, core.film_weight = i;
  core.rho = rho;
  core.rho_sr0 = (w_opaque + w_transp) * s * F0 * rho_s + w_metal * rho;
  core.rho_sr90 = Rgb((w_opaque + w_transp) * s + w_metal);
  core.rho_t = rho * w_transp;
  core.f0_diel = F0 * rho_s;
  core.eta = eta, core.eta_i = eta_i, core.eta_o = eta_o;
  // Thin-film reflectance R(cos theta, eta_base, d_i, eta_i) with air above the film; a metal base
  // enters through its equivalent IOR.
  core.film = in.film;
  core.eta_rho = thin_film_metal_eta(rho);
  const Rgb rho_d = (rho * (1 - l) + rho_l * l) * w_opaque;

  const bool has_core = !in.flake_opaque && (w_metal + w_opaque + w_transp) > 0;
  if (has_core) {
    // M_r with the core Fresnel (CoreFresnel::reflection). Present unless every Fresnel weight
    // vanishes (e.g. a dielectric with s = 0 and no film).
    if (w_metal > 0 || s * (w_opaque + w_transp) > 0 || i > 0) {
      auto lobe = std::make_unique<MicrofacetReflection>(alpha_u, alpha_v,
                                                         CosineFactor::core(CosineFactor::Kind::CoreReflection, core));
      lobe->set_grazing_guard(guard);
      out.add(std::move(lobe), Layer::Core);
    }
    // M_r,ms F_ms(rho_s,r,0, rho_s,r,90) (same for every film weight). A mirror (delta M_r) has
    // E_m = 1 exactly: no compensation (the tables' first roughness sample is not at r = 0).
    const double e_m_avg = std::clamp(luts.E_m_avg(r_uv), 0.0, 1.0);
    const Rgb f_ms = dev == Deviation::BlendedFms
                         ? w_metal * fresnel_ms(rho, Rgb(1.0), e_m_avg) +
                               (w_opaque + w_transp) * fresnel_ms(core.f0_diel * s, Rgb(s), e_m_avg)
                         : fresnel_ms(core.rho_sr0, core.rho_sr90, e_m_avg);
    const bool mirror = GgxDistribution(alpha_u, alpha_v).effectively_smooth();
    if (f_ms.max_component() > 0 && !mirror && dev != Deviation::NoMultipleScattering)
      out.add(std::make_unique<MultiScatterReflection>(r_uv, f_ms, luts), Layer::Core);
    // Transmission: rho_t M_t' (1 - s F) (thin) or rho_t M_t (1 - s F_d) (volumetric); with a film
    // (1-i) times that + i rho_t M_t (1 - R).
    if (w_transp > 0 && core.rho_t.max_component() > 0) {
      if (volumetric) {
        auto lobe = std::make_unique<VolumetricTransmission>(
            alpha_u, alpha_v, eta_i, eta_o, CosineFactor::core(CosineFactor::Kind::VolumetricTransmission, core));
        lobe->set_grazing_guard(guard);
        lobe->set_factor_at_macro_normal(dev == Deviation::FresnelAtMacroNormal);
        out.add(std::move(lobe), Layer::Core);
      } else {
        auto lobe = std::make_unique<ThinTransmission>(alpha_u, alpha_v,
                                                       CosineFactor::core(CosineFactor::Kind::ThinTransmission, core));
        lobe->set_grazing_guard(guard);
        out.add(std::move(lobe), Layer::Core);
      }
      // Not for index-matched volumetric media: the transmission is then a Dirac that loses nothing.
      const bool matched = volumetric && std::abs(eta - 1.0) < kIndexMatched;
      if (in.compensate_transmission && !mirror && !matched)
        add_transmission_compensation(out, luts, a.thin_walled, inside, r_uv, eta, w_transp, rho_s, rho);
    }
    // Diffuse base rho_d [B_u (1 - s) + s B_c(F_0 rho_s)] (+ film term).
    if (w_opaque > 0 && rho_d.max_component() > 0) {
      DiffuseParams dp;
      dp.rho_d = rho_d;
      dp.specular = s;
      dp.translucency = l;
      dp.f0_max = (dev == Deviation::BcMaxRhoSr0 ? core.rho_sr0 : core.f0_diel).max_component();
      dp.r_uv = r_uv;
      dp.film_weight = i;
      dp.film = core.film;
      dp.film_eta_base = eta;
      out.add(std::make_unique<DiffuseBase>(dp, luts), Layer::Core);
    }
  }
  // ---- Sheen (ShinyCore: + M_b rho_b) -------------------------------------------------------------
  if (in.sheen) out.add(std::make_unique<SheenLobe>(*in.sheen), Layer::Sheen);
  // ---- Clearcoat (Coated: + M_c c F_c(h.v), isotropic GGX alpha = r_c^2) --------------------------
  if (a.clearcoat > 0) {
    const double ac = roughness_to_alpha(m.clearcoatRoughness);
    auto lobe = std::make_unique<MicrofacetReflection>(ac, ac, CosineFactor::clearcoat(a.clearcoat));
    lobe->set_grazing_guard(guard);
    out.add(std::move(lobe), Layer::Coat);
  }
  return out;
}

}  // namespace

AssembledLobes assemble_lobes(const Material& m, const LutSet& luts, const BsdfOptions& opt, uint32_t mask) {
  AssembledLobes a;
  a.core = core_frame(m);
  a.thin_walled = m.thinWalled;
  a.coat = clearcoat_frame(m);
  a.alpha_cut = std::clamp(m.cutoutOpacity, 0.0, 1.0);
  a.clearcoat = (mask & kClearcoat) ? m.clearcoat : 0.0;
  a.emission_coat = opt.deviation == Deviation::EmissionUnattenuated ? 0.0 : a.clearcoat;
  a.eta = m.ior;
  // Dispersion (spec "Dispersion"): eta(lambda) replaces ior at the caller's wavelength.
  if ((mask & kDispersion) && opt.wavelength_nm > 0 && m.abbeNumber > 0) a.eta = dispersion_ior(m, opt.wavelength_nm);
  bool flake_opaque = false;
  Flake flake;
  if ((mask & kFlakes) && m.flakeCoverage > 0) {
    flake = flake_at(opt.position, opt.object_normal, m);
    flake_opaque = flake.opacity > 0;
  }
  std::optional<SheenLobe> sheen;  // ShinyCore factor and lobe (absent without sheen)
  if ((mask & kSheen) && m.sheenColor.max_component() > 0 && !flake_opaque) {
    sheen.emplace(m.sheenColor, m.sheenRoughness, opt.sheen_model, luts);
    if (opt.deviation == Deviation::OldSheenLambda) sheen->set_lambda_fit(sheen_lambda_fit_ck17());
    sheen->set_scales_layers(opt.deviation != Deviation::NoSheenLayering);
  }
  if ((mask & kEmission) && m.emissionValue > 0) a.rho_e = emission_rho_e(m, opt.object_area_m2);
  // The film's R tabulated once for both sides, over the bases the core reads: the base IOR
  // (dielectric parts) and the metal's equivalent IOR (bsdf/thin_film_table.h).
  FilmLayer film{m.thinFilmThickness, m.thinFilmIor, {}};
  if ((mask & kThinFilm) && m.thinFilm > 0) {
    if (m.metallic <= 0) film = FilmLayer::tabulated(m.thinFilmThickness, m.thinFilmIor, {a.eta});
    else if (m.metallic >= 1) film = FilmLayer::tabulated(m.thinFilmThickness, m.thinFilmIor, {thin_film_metal_eta(m.albedo)});
    else film = FilmLayer::tabulated(m.thinFilmThickness, m.thinFilmIor, {a.eta, thin_film_metal_eta(m.albedo)});
  }
  const SideInputs in{mask, a.eta, flake_opaque, opt.transmission_compensation, opt.deviation, sheen, film, a};
  for (int side = 0; side < 2; ++side) {
    a.sides[size_t(side)] = assemble_side(m, luts, in, side == 1);
    // The flake lobe needs the flake normal (same on both sides).
    if (flake_opaque) a.sides[size_t(side)].add(std::make_unique<FlakeLobe>(flake.normal, m), Layer::Flake);
  }
  return a;
}

}  // namespace dspbr
