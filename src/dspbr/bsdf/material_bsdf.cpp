#include "dspbr/bsdf/material_bsdf.h"

#include <stdexcept>

#include "dspbr/bsdf/emission.h"
#include "dspbr/component.h"

namespace dspbr {

MaterialBsdf::MaterialBsdf(const Material& m, const LutSet& luts, const BsdfOptions& opt)
    : MaterialBsdf(m, luts, opt, active_components(m)) {}

MaterialBsdf::MaterialBsdf(const Material& m, const LutSet& luts, const BsdfOptions& opt, uint32_t mask)
    : mask_(mask) {
  AssembledLobes a = assemble_lobes(m, luts, opt, mask);
  core_ = a.core;
  coat_ = a.coat;
  eta_ = a.eta;
  alpha_cut_ = a.alpha_cut;
  clearcoat_ = a.emission_coat;
  rho_e_ = a.rho_e;
  // Thin-walled: the side of the shading normal (keeps reciprocity with normal maps); volume
  // boundary: the geometric side (v.z < 0 is inside the object).
  bsdf_ = TwoSided<CutOut>({CutOut(std::move(a.sides[0]), a.alpha_cut), CutOut(std::move(a.sides[1]), a.alpha_cut)},
                           a.thin_walled, a.core.n);
}

Rgb MaterialBsdf::eval(const Vec3& v, const Vec3& l) const { return bsdf_.eval(v, l); }
double MaterialBsdf::pdf(const Vec3& v, const Vec3& l) const { return bsdf_.pdf(v, l); }
BsdfSample MaterialBsdf::sample(const Vec3& v, const Vec3& u) const { return bsdf_.sample(v, u); }
double MaterialBsdf::delta_probability(const Vec3& v) const { return bsdf_.delta_probability(v); }
uint32_t MaterialBsdf::flags() const { return bsdf_.flags(); }

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
