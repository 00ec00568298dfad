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

struct BsdfOptions {
  SheenModel sheen_model = SheenModel::Main;  // spec Lambda fit (Main) or alternative visibility (Ash)
  Vec3 position{0, 0, 0};                     // object-space shading point p in metres (flakes)
  Vec3 object_normal{0, 0, 1};                // bumped normal in object space (flakes' triplanar choice)
  double wavelength_nm = 0;                   // > 0: dispersive IOR eta(lambda) (dispersion component)
  double object_area_m2 = 1;                  // object surface area for emission in lm
  // Energy compensation of the transparent core's rough transmission (beyond DSPBR 2025x; off:
  // the spec's BSDF). Adds the TransmissionCompensation lobes (docs/bsdf.md).
  bool transmission_compensation = false;
};

struct AssembledLobes {
  std::array<LobeMixture, 2> sides;  // [0] v outside (v.z >= 0), [1] inside
  bool thin_walled = true;           // the side is that of the shading normal (else geometric)
  Frame core, coat;                  // shading frames of the core and the clearcoat
  double eta = 1.5;                  // ior, or eta(lambda) with dispersion
  double alpha_cut = 1;              // cut-out opacity
  double clearcoat = 0;              // c (0 when masked out)
  Rgb rho_e{0, 0, 0};                // emitted luminance (0 without emission)
};

// mask: the components to include (dspbr/component.h); a cleared bit removes that component's
// terms and its layering factor.
AssembledLobes assemble_lobes(const Material& m, const LutSet& luts, const BsdfOptions& opt, uint32_t mask);

}  // namespace dspbr
