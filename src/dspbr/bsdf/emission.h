// Emission: the luminance rho_e from the photometric emission parameters, and the emitted radiance
// L_e(v) below the clearcoat. Spec "Emission" (and "Clearcoat" for F_c).
#pragma once
#include "dspbr/material.h"
#include "dspbr/vec3.h"

namespace dspbr {

// rho_e in cd/m^2 (= lm / (m^2 sr)), spec "Emission":
//   l_vc = l_v l_c, or l_v l_c / (l_c . (0.2126729, 0.7151522, 0.0721750)) when normalizing;
//   rho_e = l_vc / pi (mode lx: luminous emittance) or l_vc / (pi area) (mode lm: luminous power).
// area_m2: the area of the object's entire surface in m^2, used only in lm mode.
// Normalizing a zero-luminance colour (black: all channels 0) gives 0: a black emission colour
// emits nothing (a texture may be black in places; an error there would break rendering).
// Throws std::invalid_argument for a negative or non-finite value or colour channel, and in lm mode
// for an area that is not a positive finite number.
Rgb emission_rho_e(const Rgb& color, double value, EmissionMode mode, bool normalize, double area_m2);
inline Rgb emission_rho_e(const Material& m, double area_m2) {
  return emission_rho_e(m.emissionColor, m.emissionValue, m.emissionMode, m.emissionEnergyNormalization, area_m2);
}

// L_e(v) = rho_e (1 - c F_c(v.n_c)) if v.n > 0, else 0 (spec "Emission"), with the clearcoat
// Fresnel F_c(cos) = 0.04 + 0.96 (1 - |cos|)^5 (spec "Clearcoat"). v in the local shading frame
// (n = +z); n_c the clearcoat normal in that frame; c the clearcoat weight.
Rgb emission_radiance(const Rgb& rho_e, const Vec3& v, const Vec3& n_c, double clearcoat);

}  // namespace dspbr
