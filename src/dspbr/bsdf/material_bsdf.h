// The full DSPBR 2025x material as one Bsdf: the spec's layering, bottom to top,
//   ThinCore / VolumetricCore (with thin film: ThinFilmOverThinCore / ThinFilmOverVolumetricCore)
//   -> ShinyCore   (sheen, albedo scaling)
//   -> GlitteryCore (flakes: the flake at the shading point replaces the layers below when opaque)
//   -> Coated      (clearcoat, (1 - c max(F_c(v.n_c), F_c(l.n_c))))
//   -> cut-out     (eval scaled by alpha; a pass-through Dirac l = -v of weight 1 - alpha)
// plus the emission L_e(v). Conventions: bsdf.h and docs/bsdf.md.
//
// Two-sided evaluation: for a viewer on the back side, f(v, l) = f_front(-v, -l): the
// back face is the same surface seen from the other side (its shading normal is -n, its tangent
// -t; GGX is symmetric under that half turn). This keeps f(v, l) = f(l, v) for thin-walled
// transmission with normal maps. Only the volumetric IOR order depends on the side (outside:
// eta_i = 1, eta_o = ior; inside: eta_i = ior, eta_o = 1). The back side is v.n < 0 (shading
// normal n) for thin-walled materials and v.z < 0 (geometric: inside the object) for volume
// boundaries; without a normal map both are v.z < 0.
//
// Sampling: one lobe is chosen with probability proportional to an estimate of its albedo for v
// (Lobe::sampling_weight times the layer factors at v, each present lobe at least 1e-3 of the
// largest), then the lobe samples a direction. pdf(v, l) is the mixture density over the non-delta
// lobes, so weight == eval(v, l) |l.z| / pdf(v, l) for non-delta samples.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "dspbr/bsdf/lobe.h"
#include "dspbr/bsdf/sheen_lobe.h"
#include "dspbr/frame.h"
#include "dspbr/lut/albedo.h"
#include "dspbr/lut/lut_set.h"
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

class MaterialBsdf : public Bsdf {
 public:
  // mask: the components to include (dspbr/component.h); a cleared bit removes that component's
  // terms and its layering factor. Default: active_components(m).
  explicit MaterialBsdf(const Material& m, const LutSet& luts = LutSet::builtin(), const BsdfOptions& opt = {});
  MaterialBsdf(const Material& m, const LutSet& luts, const BsdfOptions& opt, uint32_t mask);
  ~MaterialBsdf() override;

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

  enum Layer { kCoreLayer, kSheenLayer, kFlakeLayer, kCoatLayer, kCutoutLayer };
  struct Entry {
    std::unique_ptr<Lobe> lobe;  // null for the cut-out pass-through
    Layer layer;
    const Frame* frame;
  };

 private:
  struct Local;  // v, l in the frames of the side
  void build(const Material& m, const LutSet& luts, const BsdfOptions& opt);
  std::vector<Entry> build_side(const Material& m, const LutSet& luts, bool inside) const;
  // The transmission-compensation lobes of the transparent part (weight w_transp) of one side.
  void add_transmission_compensation(std::vector<Entry>& out, const LutSet& luts, bool inside, double r_uv,
                                     double eta, double w_transp, const Rgb& rho_s, const Rgb& rho) const;
  double layer_factor(Layer layer, const Vec3& v, const Vec3& l) const;
  void selection(const std::vector<Entry>& side, const Vec3& v, std::vector<double>& probs) const;
  Rgb eval_side(const std::vector<Entry>& side, const Vec3& v, const Vec3& l) const;
  double pdf_side(const std::vector<Entry>& side, const Vec3& v, const Vec3& l, const std::vector<double>& probs) const;

  bool back_side(const Vec3& v) const;

  uint32_t mask_;
  bool thin_walled_ = true;
  Frame core_, coat_;
  double eta_ = 1.5;
  double alpha_cut_ = 1;  // cut-out opacity
  double clearcoat_ = 0;  // c (0 when masked out)
  bool flake_opaque_ = false;
  bool compensate_transmission_ = false;
  std::unique_ptr<SheenLobe> sheen_scaler_;  // ShinyCore factor (null without sheen)
  Rgb rho_e_{0, 0, 0};                       // emitted luminance (0 without emission)
  std::array<std::vector<Entry>, 2> sides_;  // [0] v outside (v.z >= 0), [1] inside
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
