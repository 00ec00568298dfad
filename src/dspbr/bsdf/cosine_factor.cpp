#include "dspbr/bsdf/cosine_factor.h"

#include <cmath>

#include "dspbr/bsdf/thin_film.h"
#include "dspbr/fresnel.h"

namespace dspbr {

FilmLayer FilmLayer::tabulated(double thickness_um, double eta_film, std::initializer_list<double> eta_bases) {
  FilmLayer f{thickness_um, eta_film, {}};
  std::size_t k = 0;
  for (double eta : eta_bases) {
    if (k == f.tables.size() || std::isinf(eta) || (k > 0 && f.tables[0]->eta_base() == eta)) continue;
    f.tables[k++] = std::make_shared<const ThinFilmTable>(eta, thickness_um, eta_film);
  }
  return f;
}

Rgb FilmLayer::reflectance(double cos_theta, double eta_base) const {
  for (const auto& t : tables)
    if (t && t->eta_base() == eta_base) return (*t)(cos_theta);
  return thin_film_reflectance(cos_theta, eta_base, thickness_um, eta_film);
}

double fresnel_clearcoat(double cos_theta) { return fresnel_schlick(cos_theta, 0.04, 1.0); }

Rgb CoreFresnel::film_side(double c) const {
  if (eta_i <= eta_o) return film.reflectance(c, eta);
  const double s2 = sin2_transmitted(c, eta_i, eta_o);
  if (s2 >= 1.0) return Rgb(1.0);
  return film.reflectance(std::sqrt(1.0 - s2), eta);
}

Rgb CoreFresnel::reflection(double c) const {
  const double s = specular, i = film_weight;
  Rgb f = volumetric ? Rgb(0) : fresnel_schlick(c, rho_sr0, rho_sr90);
  if (volumetric) {
    // A term of weight 0 adds exactly +0 (the Schlick terms are finite): it is not evaluated.
    if (w_metal > 0) f = w_metal * fresnel_schlick(c, rho, Rgb(1.0));
    if (w_opaque > 0) f += w_opaque * s * fresnel_schlick(c, f0_diel, Rgb(1.0));
    if (w_transp > 0) f += w_transp * s * fresnel_schlick_d(c, f0_diel, Rgb(1.0), eta_i, eta_o);
  }
  if (i > 0) {
    // R(c, eta) once for the opaque and (seen from outside) the transparent part; a term of weight
    // 0 contributes exactly 0 and is not evaluated.
    const bool transp_sees_eta = !volumetric || eta_i <= eta_o;
    const Rgb r_eta = (w_opaque > 0 || (w_transp > 0 && transp_sees_eta)) ? film.reflectance(c, eta) : Rgb(0);
    const Rgb r_transp = w_transp > 0 ? (transp_sees_eta ? r_eta : film_side(c)) : Rgb(0);
    Rgb fr = w_opaque * r_eta + w_transp * r_transp;
    if (w_metal > 0) fr += w_metal * film.reflectance(c, eta_rho);
    f = (1 - i) * f + i * fr;
  }
  return f;
}

Rgb CoreFresnel::thin_transmission(double c) const {
  const double s = specular, i = film_weight;
  Rgb f = rho_t * (1.0 - s * fresnel_schlick(c, f0_diel, Rgb(1.0)));
  if (i > 0) f = (1 - i) * f + i * rho_t * (1.0 - film.reflectance(c, eta));
  return f;
}

Rgb CoreFresnel::volumetric_transmission(double c) const {
  const double s = specular, i = film_weight;
  Rgb f = rho_t * (1.0 - s * fresnel_schlick_d(c, f0_diel, Rgb(1.0), eta_i, eta_o));
  if (i > 0) f = (1 - i) * f + i * rho_t * (1.0 - film_side(c));
  return f;
}

}  // namespace dspbr
