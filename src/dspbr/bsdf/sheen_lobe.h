// Sheen lobe M_b(v, l, h_r; r_b) rho_b (spec "Sheen"; Conty Estevez & Kulla 2017): Charlie D_b with
// the spec's Lambda fit (SheenModel::Main) or the alternative visibility of [NP13]
// (SheenModel::Ash). alpha_b = r_b^2, clamped up to kMinAlphaB (sheen.h) because D_b is
// undefined at alpha_b = 0 (the same clamp as the Sheen_E tables).
// Also the albedo-scaling factor of ShinyCore, min(1 - rho_hat E_b(v.n), 1 - rho_hat E_b(l.n)).
// Sampling: uniform hemisphere (robust at every alpha_b; D_b concentrates near grazing normals).
#pragma once
#include "dspbr/bsdf/lobe.h"
#include "dspbr/sheen.h"
#include "dspbr/tables/albedo_slice.h"

namespace dspbr {

class SheenLobe : public Lobe {
 public:
  SheenLobe(const Rgb& color, double sheen_roughness, SheenModel model, const LutSet& luts);
  Rgb eval(const Vec3& v, const Vec3& l) const override;
  double pdf(const Vec3& v, const Vec3& l) const override;
  BsdfSample sample(const Vec3& v, const Vec3& u) const override;
  uint32_t flags() const override { return kLobeReflection | kLobeGlossy; }
  double sampling_weight(const Vec3& v) const override;

  // E_b(|cos|; alpha_b) from the table of the chosen model, clamped to [0, 1].
  double albedo(double cos_theta) const;
  // ShinyCore's factor on the layers below: min(1 - rho_hat E_b(v.n), 1 - rho_hat E_b(l.n)),
  // rho_hat = max(rho_b); |cos| for a transmitted l.
  double layer_scale(double cos_v, double cos_l) const;
  double alpha_b() const { return alpha_b_; }
  // The conformance diagnosis's mistakes (lobe_assembly.h, Deviation): another Lambda fit (the
  // fit must outlive the lobe), and no scaling of the layers below (layer_scale = 1).
  void set_lambda_fit(const SheenLambdaFit& fit) { fit_ = &fit; }
  void set_scales_layers(bool scales) { scales_layers_ = scales; }

 private:
  Rgb color_;
  double alpha_b_;
  SheenModel model_;
  AlbedoSlice e_b_;  // E_b(mu; alpha_b) of the model
  const SheenLambdaFit* fit_ = &sheen_lambda_fit_spec();
  bool scales_layers_ = true;
};

}  // namespace dspbr
