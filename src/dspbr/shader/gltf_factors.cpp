#include "dspbr/shader/gltf_factors.h"

#include <string>

namespace dspbr::shader {

dspbr_shader::DspbrGltf gltf_factors(const nlohmann::json& mat) {
  using dspbr_shader::vec3;
  dspbr_shader::DspbrGltf g = dspbr_shader::dspbr_default_gltf();
  auto num = [](const nlohmann::json& o, const char* k, float& x) {
    if (o.contains(k)) x = o[k].get<float>();
  };
  auto rgb = [](const nlohmann::json& o, const char* k, vec3& x) {
    if (o.contains(k)) x = vec3(o[k][0].get<float>(), o[k][1].get<float>(), o[k][2].get<float>());
  };
  auto ext = [&](const char* name) -> const nlohmann::json* {
    for (const char* where : {"extensions", "extras"})
      if (mat.contains(where) && mat[where].contains(name)) return &mat[where][name];
    return nullptr;
  };
  const nlohmann::json pbr = mat.value("pbrMetallicRoughness", nlohmann::json::object());
  if (pbr.contains("baseColorFactor")) {
    const auto& c = pbr["baseColorFactor"];
    g.baseColorFactor = vec3(c[0].get<float>(), c[1].get<float>(), c[2].get<float>());
    g.baseColorAlpha = c[3].get<float>();
  }
  num(pbr, "metallicFactor", g.metallicFactor);
  num(pbr, "roughnessFactor", g.roughnessFactor);
  const std::string mode = mat.value("alphaMode", std::string("OPAQUE"));
  g.alphaMode = mode == "BLEND" ? dspbr_shader::DSPBR_GLTF_ALPHA_BLEND
                : mode == "MASK" ? dspbr_shader::DSPBR_GLTF_ALPHA_MASK
                                 : dspbr_shader::DSPBR_GLTF_ALPHA_OPAQUE;
  num(mat, "alphaCutoff", g.alphaCutoff);
  rgb(mat, "emissiveFactor", g.emissiveFactor);
  if (const auto* e = ext("KHR_materials_emissive_strength")) num(*e, "emissiveStrength", g.emissiveStrength);
  if (const auto* e = ext("3DS_materials_emission")) {
    g.has_3ds_emission = true;
    num(*e, "emissionValue", g.emissionValue);
    if (e->value("emissionMode", std::string()) == "LUMINOUS_POWER")
      g.emissionMode = dspbr_shader::DSPBR_EMISSIONMODE_LUMINOUS_POWER;
    g.emissionEnergyNormalization = e->value("emissionEnergyNormalization", false);
  }
  if (const auto* e = ext("KHR_materials_specular")) {
    num(*e, "specularFactor", g.specularFactor);
    rgb(*e, "specularColorFactor", g.specularColorFactor);
  }
  if (const auto* e = ext("KHR_materials_ior")) num(*e, "ior", g.ior);
  if (const auto* e = ext("KHR_materials_transmission")) num(*e, "transmissionFactor", g.transmissionFactor);
  if (const auto* e = ext("KHR_materials_volume")) {
    g.has_volume = true;
    num(*e, "thicknessFactor", g.thicknessFactor);
    num(*e, "attenuationDistance", g.attenuationDistance);
    rgb(*e, "attenuationColor", g.attenuationColor);
  }
  if (const auto* e = ext("KHR_materials_dispersion")) num(*e, "dispersion", g.dispersion);
  if (const auto* e = ext("KHR_materials_diffuse_transmission")) {
    num(*e, "diffuseTransmissionFactor", g.diffuseTransmissionFactor);
    rgb(*e, "diffuseTransmissionColorFactor", g.diffuseTransmissionColorFactor);
  }
  if (const auto* e = ext("3DS_materials_translucency")) {
    g.has_3ds_translucency = true;
    num(*e, "translucencyFactor", g.translucencyFactor);
  }
  for (const char* name : {"3DS_materials_sss", "3DS_materials_volume"})
    if (const auto* e = ext(name)) {
      rgb(*e, "subsurfaceColor", g.subsurfaceColor);
      num(*e, "subsurfaceAsymmetry", g.subsurfaceAsymmetry);
    }
  if (const auto* e = ext("KHR_materials_iridescence")) {
    num(*e, "iridescenceFactor", g.iridescenceFactor);
    num(*e, "iridescenceIor", g.iridescenceIor);
    num(*e, "iridescenceThicknessMaximum", g.iridescenceThicknessMaximum);
  }
  if (const auto* e = ext("KHR_materials_sheen")) {
    g.has_sheen = true;
    rgb(*e, "sheenColorFactor", g.sheenColorFactor);
    num(*e, "sheenRoughnessFactor", g.sheenRoughnessFactor);
  }
  if (const auto* e = ext("KHR_materials_clearcoat")) {
    num(*e, "clearcoatFactor", g.clearcoatFactor);
    num(*e, "clearcoatRoughnessFactor", g.clearcoatRoughnessFactor);
  }
  if (const auto* e = ext("KHR_materials_anisotropy")) {
    num(*e, "anisotropyStrength", g.anisotropyStrength);
    num(*e, "anisotropyRotation", g.anisotropyRotation);
  }
  if (const auto* e = ext("3DS_materials_anisotropy")) {
    g.has_3ds_anisotropy = true;
    num(*e, e->contains("anisotropyFactor") ? "anisotropyFactor" : "ansiotropyFactor", g.anisotropyFactor);
    num(*e, "anisotropyRotationFactor", g.anisotropyRotationFactor);
  }
  return g;
}

}  // namespace dspbr::shader
