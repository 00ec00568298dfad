#include "dspbr/shader/material_mapping.h"

#include <cmath>

namespace dspbr::shader {

using dspbr_shader::vec3;

namespace {
vec3 v3(const Rgb& c) { return vec3(float(c.r), float(c.g), float(c.b)); }
vec3 v3(const Vec3& c) { return vec3(float(c.x), float(c.y), float(c.z)); }
}  // namespace

dspbr_shader::DspbrMaterial to_shader_material(const Material& m) {
  dspbr_shader::DspbrMaterial s = dspbr_shader::dspbr_default_material();
  s.albedo = v3(m.albedo);
  s.metallic = float(m.metallic);
  s.roughness = float(m.roughness);
  s.anisotropy = float(m.anisotropy);
  s.anisotropyRotation = float(m.anisotropyRotation);
  s.normal = v3(m.normal);
  s.displacement = v3(m.displacement);
  s.translucency = float(m.translucency);
  s.translucencyColor = v3(m.translucencyColor);
  s.transparency = float(m.transparency);
  s.cutoutOpacity = float(m.cutoutOpacity);
  s.specular = float(m.specular);
  s.specularTint = v3(m.specularTint);
  s.thinFilm = float(m.thinFilm);
  s.thinFilmThickness = float(m.thinFilmThickness);
  s.thinFilmIor = float(m.thinFilmIor);
  s.sheenColor = v3(m.sheenColor);
  s.sheenRoughness = float(m.sheenRoughness);
  s.flakeCoverage = float(m.flakeCoverage);
  s.flakeColor = v3(m.flakeColor);
  s.flakeSize = float(m.flakeSize);
  s.flakeRoughness = float(m.flakeRoughness);
  s.flipFlop = float(m.flipFlop);
  s.flipFlopColor = v3(m.flipFlopColor);
  s.clearcoat = float(m.clearcoat);
  s.clearcoatRoughness = float(m.clearcoatRoughness);
  s.clearcoatNormal = v3(m.clearcoatNormal);
  s.emissionColor = v3(m.emissionColor);
  s.emissionValue = float(m.emissionValue);
  s.emissionMode = m.emissionMode == EmissionMode::LuminousPower ? dspbr_shader::DSPBR_EMISSIONMODE_LUMINOUS_POWER
                                                                         : dspbr_shader::DSPBR_EMISSIONMODE_LUMINOUS_EMITTANCE;
  s.emissionEnergyNormalization = m.emissionEnergyNormalization;
  s.thinWalled = m.thinWalled;
  s.ior = float(m.ior);
  s.abbeNumber = float(m.abbeNumber);
  s.attenuationColor = v3(m.attenuationColor);
  s.attenuationDistance = std::isinf(m.attenuationDistance) ? 3.402823466e38f : float(m.attenuationDistance);
  s.subsurfaceColor = v3(m.subsurfaceColor);
  s.subsurfaceAnisotropy = float(m.subsurfaceAnisotropy);
  return s;
}

dspbr_shader::DspbrOptions to_shader_options(const BsdfOptions& o) {
  dspbr_shader::DspbrOptions s = dspbr_shader::dspbr_default_options();
  s.sheen_model = o.sheen_model == SheenModel::Ash ? dspbr_shader::DSPBR_SHEEN_ASH : dspbr_shader::DSPBR_SHEEN_MAIN;
  s.object_area_m2 = float(o.object_area_m2);
  s.wavelength_nm = float(o.wavelength_nm);
  s.position = vec3(float(o.position.x), float(o.position.y), float(o.position.z));
  s.object_normal = vec3(float(o.object_normal.x), float(o.object_normal.y), float(o.object_normal.z));
  return s;
}

void pack_shader_inputs(const Material& m, const BsdfOptions& o, const Vec3& v, const Vec3& l, float* out) {
  const dspbr_shader::DspbrMaterial sm = to_shader_material(m);
  const dspbr_shader::DspbrOptions so = to_shader_options(o);
  DSPBR_MATERIAL_PACK(sm, out, 0u);
  std::size_t i = dspbr_shader::DSPBR_MATERIAL_FLOATS;
  const auto put3 = [&](vec3 c) { out[i] = c.x, out[i + 1] = c.y, out[i + 2] = c.z, i += 3; };
  out[i++] = float(so.sheen_model);
  out[i++] = so.object_area_m2;
  put3(so.position), put3(so.object_normal), put3(v3(v)), put3(v3(l));
}

}  // namespace dspbr::shader
