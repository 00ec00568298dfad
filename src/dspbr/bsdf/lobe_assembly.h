// The spec's lobe assembly (spec "Putting It All Together", "Thin Film", "Sheen", "Flakes",
// "Clearcoat"): a pure function from a Material, the options and the tables to the fixed-capacity
// lobe stacks of the two sides, the layering factors between them and the values the wrappers
// need (cut-out opacity, side rule, emission). Read side by side with the spec's equations:
//   ThinCore / VolumetricCore (with thin film: ThinFilmOverThinCore / ThinFilmOverVolumetricCore)
//   -> ShinyCore   (sheen, albedo scaling)
//   -> GlitteryCore (flakes: the flake at the shading point replaces the layers below when opaque)
//   -> Coated      (clearcoat, (1 - c max(F_c(v.n_c), F_c(l.n_c))))
//   -> cut-out     (bsdf/cut_out.h)
// Side 0 is v outside (front), side 1 v inside (back, evaluated with -v, -l; bsdf/two_sided.h).
#pragma once
#include <array>
#include <cstdint>

#include "dspbr/bsdf/lobe_mixture.h"
#include "dspbr/sheen.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/material.h"

namespace dspbr {

// Classic implementation mistakes, reproduced on purpose: the conformance kit's diagnosis
// (docs/conformance.md, "Diagnosis") evaluates the reference with each one and asks which of them
// explains an implementation's failing vectors. None is the spec's BSDF; the others are never the
// default anywhere else.
enum class Deviation {
  None,
  NoMultipleScattering,  // no M_r,ms F_ms lobe (no Kulla-Conty compensation of the specular lobes)
  BlendedFms,            // F_ms = m F_ms(rho, 1) + (1 - m) F_ms(s F_0 rho_s, s), not of the mixed Fresnel
  BcMaxRhoSr0,           // the diffuse base's B_c read at max(rho_s,r,0), not max(F_0 rho_s)
  NoSheenLayering,       // the sheen does not scale the core (ShinyCore's min(1 - rho_hat E_b) left out)
  OldSheenLambda,        // the sheen's Lambda from Conty & Kulla 2017's fit, not the spec's
  FresnelAtMacroNormal,  // volumetric rough transmission's Fresnel at v.n instead of v.h
  LambdaZeroAtGrazing,   // GGX Lambda = 0 where |cos theta| < kGrazingGuardCos (a "guard" that makes f ~ 1/cos)
  EmissionUnattenuated,  // emission not scaled by the clearcoat's (1 - c F_c)
};
// The cosine below which Deviation::LambdaZeroAtGrazing sets Lambda to 0.
inline constexpr double kGrazingGuardCos = 1e-3;

struct BsdfOptions {
  SheenModel sheen_model = SheenModel::Main;  // spec Lambda fit (Main) or alternative visibility (Ash)
  Vec3 position{0, 0, 0};                     // object-space shading point p in metres (flakes)
  Vec3 object_normal{0, 0, 1};                // bumped normal in object space (flakes' triplanar choice)
  double wavelength_nm = 0;                   // > 0: dispersive IOR eta(lambda) (dispersion component)
  double object_area_m2 = 1;                  // object surface area for emission in lm
  // Energy compensation of the transparent core's rough transmission (beyond DSPBR 2025x; off:
  // the spec's BSDF). Adds the TransmissionCompensation lobes (docs/bsdf.md).
  bool transmission_compensation = false;
  Deviation deviation = Deviation::None;  // the conformance diagnosis's mistakes (above)
};

struct AssembledLobes {
  std::array<LobeMixture, 2> sides;  // [0] v outside (v.z >= 0), [1] inside
  bool thin_walled = true;           // the side is that of the shading normal (else geometric)
  Frame core, coat;                  // shading frames of the core and the clearcoat
  double eta = 1.5;                  // ior, or eta(lambda) with dispersion
  double alpha_cut = 1;              // cut-out opacity
  double clearcoat = 0;              // c (0 when masked out)
  double emission_coat = 0;          // the c that attenuates emission (clearcoat, 0 for EmissionUnattenuated)
  Rgb rho_e{0, 0, 0};                // emitted luminance (0 without emission)
};

// mask: the components to include (dspbr/component.h); a cleared bit removes that component's
// terms and its layering factor.
AssembledLobes assemble_lobes(const Material& m, const LutSet& luts, const BsdfOptions& opt, uint32_t mask);

}  // namespace dspbr
