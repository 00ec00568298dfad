// The colour factor of one cosine that a microfacet lobe multiplies M_r or M_t with (its "Fresnel"),
// as a small value type: the core's merged Fresnel and transmission factors of the spec's "Putting
// It All Together" and "Thin Film" equations, the clearcoat's c F_c, or any function (Custom, for
// tests and experiments). Evaluating one is a switch, not a call through std::function, and each
// thin-film reflectance R it needs is computed once per cosine.
#pragma once
#include <array>
#include <functional>
#include <initializer_list>
#include <memory>
#include <type_traits>
#include <utility>

#include "dspbr/bsdf/thin_film_table.h"
#include "dspbr/vec3.h"

namespace dspbr {

// A colour-valued function of one cosine.
using CosineFn = std::function<Rgb(double cos_theta)>;

// The thin film over the core (spec "Thin Film"): air | film (eta_film, thickness) | base.
struct FilmLayer {
  double thickness_um = 0, eta_film = 1;
  // R over cos theta for the bases the lobes read (the base IOR and the metal's eta_rho), built
  // once by the lobe assembly and shared by the lobes (bsdf/thin_film_table.h).
  std::array<std::shared_ptr<const ThinFilmTable>, 2> tables;

  // The film with tables for the given bases (an infinite or repeated base gets none).
  static FilmLayer tabulated(double thickness_um, double eta_film, std::initializer_list<double> eta_bases);
  // R(cos theta, eta_base, d_i, eta_i): the table of that base, else the Fourier evaluation
  // (bsdf/thin_film.h).
  Rgb reflectance(double cos_theta, double eta_base) const;
};

// Everything the core's Fresnel and transmission factors read (spec "Putting It All Together":
// ThinCore / VolumetricCore, and ThinFilmOver* with film weight i).
struct CoreFresnel {
  bool volumetric = false;
  double w_metal = 0, w_opaque = 0, w_transp = 0;  // m, (1-m)(1-t), (1-m) t (0 when masked out)
  double specular = 1, film_weight = 0;            // s, i
  Rgb rho{1, 1, 1}, rho_sr0{0, 0, 0}, rho_sr90{1, 1, 1}, rho_t{0, 0, 0}, f0_diel{0.04, 0.04, 0.04};
  double eta = 1.5, eta_i = 1, eta_o = 1.5;  // base IOR; IOR on v's side and on the other side
  double eta_rho = 1;                         // equivalent IOR of the metal base under the film
  FilmLayer film;

  // M_r's factor. ThinCore: F(rho_s,r,0, rho_s,r,90); VolumetricCore: m F(rho, 1) + (1-m)(1-t) s
  // F(F_0 rho_s, 1) + (1-m) t s F_d(F_0 rho_s, 1); with a film (1-i) times that + i [m R(eta_rho) +
  // (1-m)(1-t) R(eta) + (1-m) t R(eta)] (docs/bsdf.md for the two misprints this corrects).
  Rgb reflection(double cos_theta) const;
  // M_t' factor of ThinCore: rho_t (1 - s F(F_0 rho_s, 1)); film: (1-i) that + i rho_t (1 - R).
  Rgb thin_transmission(double cos_theta) const;
  // M_t factor of VolumetricCore: rho_t (1 - s F_d(F_0 rho_s, 1)); film: (1-i) that + i rho_t (1 - R).
  Rgb volumetric_transmission(double cos_theta) const;
  // R for a cosine measured on v's side of a volumetric boundary: from inside, the film is seen
  // through the base; a lossless stack reflects equally from both sides at corresponding angles,
  // and total internal reflection gives 1.
  Rgb film_side(double cos_theta) const;
};

class CosineFactor {
 public:
  enum class Kind { Custom, CoreReflection, ThinTransmission, VolumetricTransmission, Clearcoat };

  // Any callable Rgb(double): the Custom kind.
  CosineFactor(CosineFn f) : kind_(Kind::Custom), custom_(std::move(f)) {}
  template <class F, class = std::enable_if_t<!std::is_same_v<std::decay_t<F>, CosineFactor> &&
                                              !std::is_same_v<std::decay_t<F>, CosineFn> &&
                                              std::is_invocable_r_v<Rgb, F, double>>>
  CosineFactor(F f) : CosineFactor(CosineFn(std::move(f))) {}

  static CosineFactor core(Kind kind, const CoreFresnel& core) {
    CosineFactor f;
    f.kind_ = kind;
    f.core_ = core;
    return f;
  }
  // c F_c(cos), F_c = 0.04 + 0.96 (1 - cos)^5 (spec "Clearcoat", eta = 1.5).
  static CosineFactor clearcoat(double c) {
    CosineFactor f;
    f.kind_ = Kind::Clearcoat;
    f.clearcoat_ = c;
    return f;
  }

  Rgb operator()(double cos_theta) const;
  Kind kind() const { return kind_; }

 private:
  CosineFactor() = default;
  Kind kind_ = Kind::Clearcoat;
  double clearcoat_ = 0;
  CoreFresnel core_;
  CosineFn custom_;
};

// F_c(cos) = 0.04 + 0.96 (1 - |cos|)^5, the clearcoat's Schlick Fresnel (spec "Clearcoat").
double fresnel_clearcoat(double cos_theta);

inline Rgb CosineFactor::operator()(double c) const {
  switch (kind_) {
    case Kind::CoreReflection: return core_.reflection(c);
    case Kind::ThinTransmission: return core_.thin_transmission(c);
    case Kind::VolumetricTransmission: return core_.volumetric_transmission(c);
    case Kind::Clearcoat: return Rgb(clearcoat_ * fresnel_clearcoat(c));
    case Kind::Custom: return custom_(c);
  }
  return Rgb(0);
}

}  // namespace dspbr
