#include "dspbr/gltf/gltf_export.h"

#include <algorithm>
#include <cmath>

#include "dspbr/gltf/gltf_file.h"
#include "dspbr/gltf/gltf_material.h"
#include "dspbr/params/material_params.h"

namespace dspbr::gltf {

namespace {

using Json = nlohmann::json;

Json rgb(const Rgb& c) { return Json::array({c.r, c.g, c.b}); }

// Two parameter values (numbers, booleans, strings, arrays of numbers) equal within relative 1e-12.
bool same(const Json& a, const Json& b) {
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    return x == y || std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
  }
  if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!same(a[i], b[i])) return false;
    return true;
  }
  return a == b;
}

}  // namespace

Json gltf_material_for(const Material& m, const std::string& name) {
  Json mat{{"name", name},
           {"pbrMetallicRoughness",
            {{"baseColorFactor", {m.albedo.r, m.albedo.g, m.albedo.b, m.cutoutOpacity}},
             {"metallicFactor", m.metallic},
             {"roughnessFactor", m.roughness}}}};
  if (m.cutoutOpacity < 1) mat["alphaMode"] = "BLEND";  // alpha as coverage
  Json ext = Json::object();
  // Emission: glTF's factor is [0, 1]; a brighter colour goes through the strength.
  const double peak = m.emissionColor.max_component();
  mat["emissiveFactor"] = rgb(peak > 1 ? m.emissionColor * (1 / peak) : m.emissionColor);
  if (peak > 1) ext["KHR_materials_emissive_strength"] = {{"emissiveStrength", peak}};
  ext["3DS_materials_emission"] = {{"emissionValue", m.emissionValue},
                                   {"emissionMode", get_material_parameter(m, "emissionMode")},
                                   {"emissionEnergyNormalization", m.emissionEnergyNormalization}};
  ext["KHR_materials_specular"] = {{"specularFactor", m.specular}, {"specularColorFactor", rgb(m.specularTint)}};
  ext["KHR_materials_ior"] = {{"ior", m.ior}};
  ext["KHR_materials_transmission"] = {{"transmissionFactor", m.transparency}};
  Json volume{{"thicknessFactor", m.thinWalled ? 0.0 : 1.0}, {"attenuationColor", rgb(m.attenuationColor)}};
  if (std::isfinite(m.attenuationDistance)) volume["attenuationDistance"] = m.attenuationDistance;
  ext["KHR_materials_volume"] = volume;
  if (m.abbeNumber > 0) ext["KHR_materials_dispersion"] = {{"dispersion", 20 / m.abbeNumber}};
  ext["KHR_materials_diffuse_transmission"] = {{"diffuseTransmissionFactor", m.translucency},
                                               {"diffuseTransmissionColorFactor", rgb(m.translucencyColor)}};
  ext["3DS_materials_sss"] = {{"subsurfaceColor", rgb(m.subsurfaceColor)}, {"subsurfaceAsymmetry", m.subsurfaceAnisotropy}};
  ext["KHR_materials_iridescence"] = {{"iridescenceFactor", m.thinFilm},
                                      {"iridescenceIor", m.thinFilmIor},
                                      {"iridescenceThicknessMaximum", m.thinFilmThickness * 1000}};
  ext["KHR_materials_sheen"] = {{"sheenColorFactor", rgb(m.sheenColor)}, {"sheenRoughnessFactor", m.sheenRoughness}};
  ext["KHR_materials_clearcoat"] = {{"clearcoatFactor", m.clearcoat}, {"clearcoatRoughnessFactor", m.clearcoatRoughness}};
  // DSPBR's own anisotropy (KHR_materials_anisotropy's strength is an approximate mapping).
  ext["3DS_materials_anisotropy"] = {{"anisotropyFactor", m.anisotropy}, {"anisotropyRotationFactor", m.anisotropyRotation}};
  mat["extensions"] = ext;

  // Mapped back: the same material, or glTF cannot say it.
  GltfFile file;
  file.path = "(" + name + " as glTF)";
  file.json = Json{{"asset", {{"version", "2.0"}}}, {"materials", Json::array({mat})}};
  const std::vector<GltfMaterial> back = map_materials(file);
  if (back.size() != 1) return nullptr;
  for (const std::string& id : material_parameter_ids())
    if (!same(get_material_parameter(back[0].material, id), get_material_parameter(m, id))) return nullptr;
  return mat;
}

}  // namespace dspbr::gltf
