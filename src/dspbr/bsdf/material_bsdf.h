// The full DSPBR 2025x material as one Bsdf: the spec's layering, bottom to top,
//   ThinCore / VolumetricCore (with thin film: ThinFilmOverThinCore / ThinFilmOverVolumetricCore)
//   -> ShinyCore   (sheen, albedo scaling)
//   -> GlitteryCore (flakes: the flake at the shading point replaces the layers below when opaque)
//   -> Coated      (clearcoat, (1 - c max(F_c(v.n_c), F_c(l.n_c))))
//   -> cut-out     (eval scaled by alpha; a pass-through Dirac l = -v of weight 1 - alpha)
// plus the emission L_e(v). Conventions: bsdf.h and docs/bsdf.md.
//
// Structure: the spec's lobe assembly (bsdf/lobe_assembly.h) builds the lobe stack of each side,
// a generic lobe mixture (bsdf/lobe_mixture.h) evaluates, selects and samples it, and two thin
// wrappers add the cut-out (bsdf/cut_out.h) and the two-sided evaluation (bsdf/two_sided.h: for a
// viewer on the back side f(v, l) = f_back(-v, -l); only the volumetric IOR order depends on the
// side: outside eta_i = 1, eta_o = ior; inside eta_i = ior, eta_o = 1).
//
// Sampling: one lobe is chosen with probability proportional to an estimate of its albedo for v
// (Lobe::sampling_weight times the layer factors at v, each present lobe at least 1e-3 of the
// largest), then the lobe samples a direction. pdf(v, l) is the mixture density over the non-delta
// lobes, so weight == eval(v, l) |l.z| / pdf(v, l) for non-delta samples.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "dspbr/bsdf/bsdf.h"
#include "dspbr/bsdf/cut_out.h"
#include "dspbr/bsdf/lobe_assembly.h"
#include "dspbr/bsdf/two_sided.h"
#include "dspbr/frame.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/material.h"

namespace dspbr {

class MaterialBsdf : public Bsdf {
 public:
  // mask: the components to include (dspbr/component.h); a cleared bit removes that component's
  // terms and its layering factor. Default: active_components(m).
  explicit MaterialBsdf(const Material& m, const LutSet& luts = LutSet::builtin(), const BsdfOptions& opt = {});
  MaterialBsdf(const Material& m, const LutSet& luts, const BsdfOptions& opt, uint32_t mask);

  Rgb eval(const Vec3& v, const Vec3& l) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override;

  // Emitted radiance L_e(v) (cd/m^2 = lm m^-2 sr^-1): rho_e (1 - c F_c(v.n_c)) for v.n > 0, times
  // the cut-out opacity alpha.
  Rgb emission(const Vec3& v) const;
  // Total probability of the delta lobes for v (the pdf integrates to 1 - this - P(fail)).
  double delta_probability(const Vec3& v) const;
  uint32_t mask() const { return mask_; }
  // The IOR the BSDF uses (ior, or eta(lambda) with dispersion).
  double ior() const { return eta_; }

  // The lobe stack of a side (false: v outside / in front of the shading normal).
  const LobeMixture& lobes(bool back) const { return bsdf_.side(back).inner(); }

 private:
  uint32_t mask_;
  Frame core_, coat_;
  double eta_ = 1.5;
  double alpha_cut_ = 1;  // cut-out opacity
  double clearcoat_ = 0;  // c attenuating the emission (AssembledLobes::emission_coat)
  Rgb rho_e_{0, 0, 0};    // emitted luminance (0 without emission)
  TwoSided<CutOut> bsdf_;
};

// The material restricted to one component by its component_name() ("metallic",
// "opaque_dielectric", "thin_transparent", "volumetric_transparent", "translucency",
// "thin_film", "sheen", "flakes", "clearcoat", "emission"). "translucency" includes the opaque
// dielectric it belongs to; "thin_film" includes the active core components under the film.
// Throws std::invalid_argument for an unknown name.
std::unique_ptr<MaterialBsdf> make_component_bsdf(const std::string& name, const Material& m,
                                                  const LutSet& luts = LutSet::builtin(),
                                                  const BsdfOptions& opt = {});

}  // namespace dspbr
