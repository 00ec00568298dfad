// glTF 2.0 materials -> DspbrMaterial: the mapping of docs/gltf_mapping.md over the factors a glTF
// loader reads, so that a renderer fills DspbrGltf once per material (textures multiply the
// factors, as glTF says, before the call). Each field is named after its glTF property; the has_*
// flags say whether the extension that decides a value is present (its absence differs from its
// defaults). dspbr_default_gltf() holds glTF's defaults with no extension.

DSPBR_CONST int DSPBR_GLTF_ALPHA_OPAQUE = 0;
DSPBR_CONST int DSPBR_GLTF_ALPHA_MASK = 1;
DSPBR_CONST int DSPBR_GLTF_ALPHA_BLEND = 2;

struct DspbrGltf {
  // glTF 2.0 core: pbrMetallicRoughness, alphaMode / alphaCutoff, emissiveFactor.
  vec3 baseColorFactor;  // rgb of pbrMetallicRoughness.baseColorFactor
  float baseColorAlpha;  // its alpha
  float metallicFactor;
  float roughnessFactor;
  int alphaMode;  // DSPBR_GLTF_ALPHA_*
  float alphaCutoff;
  vec3 emissiveFactor;
  float emissiveStrength;  // KHR_materials_emissive_strength
  // 3DS_materials_emission (without it: emissionValue pi for a non-black emissive colour).
  bool has_3ds_emission;
  float emissionValue;
  int emissionMode;  // DSPBR_EMISSIONMODE_*
  bool emissionEnergyNormalization;
  float specularFactor;      // KHR_materials_specular
  vec3 specularColorFactor;  // KHR_materials_specular
  float ior;                 // KHR_materials_ior
  float transmissionFactor;  // KHR_materials_transmission
  // KHR_materials_volume (without it the surface is thin-walled).
  bool has_volume;
  float thicknessFactor;
  float attenuationDistance;
  vec3 attenuationColor;
  float dispersion;  // KHR_materials_dispersion (20 / Abbe number; 0: none)
  float diffuseTransmissionFactor;      // KHR_materials_diffuse_transmission
  vec3 diffuseTransmissionColorFactor;  // KHR_materials_diffuse_transmission
  bool has_3ds_translucency;  // 3DS_materials_translucency (replaces diffuseTransmissionFactor)
  float translucencyFactor;
  vec3 subsurfaceColor;       // 3DS_materials_sss
  float subsurfaceAsymmetry;  // 3DS_materials_sss
  float iridescenceFactor;            // KHR_materials_iridescence
  float iridescenceIor;               // KHR_materials_iridescence
  float iridescenceThicknessMaximum;  // KHR_materials_iridescence, nm
  // KHR_materials_sheen (without it DSPBR's default sheen roughness stays: the sheen is black).
  bool has_sheen;
  vec3 sheenColorFactor;
  float sheenRoughnessFactor;
  float clearcoatFactor;           // KHR_materials_clearcoat
  float clearcoatRoughnessFactor;  // KHR_materials_clearcoat
  float anisotropyStrength;  // KHR_materials_anisotropy
  float anisotropyRotation;  // KHR_materials_anisotropy: radians, counter-clockwise from the tangent
  // 3DS_materials_anisotropy (used instead of KHR_materials_anisotropy when present).
  bool has_3ds_anisotropy;
  float anisotropyFactor;
  float anisotropyRotationFactor;  // [0, 1] = [0, 360 deg), DSPBR's own convention
};

DSPBR_FN DspbrGltf dspbr_default_gltf() {
  DspbrGltf g;
  g.baseColorFactor = vec3(1.0f, 1.0f, 1.0f);
  g.baseColorAlpha = 1.0f;
  g.metallicFactor = 1.0f;
  g.roughnessFactor = 1.0f;
  g.alphaMode = DSPBR_GLTF_ALPHA_OPAQUE;
  g.alphaCutoff = 0.5f;
  g.emissiveFactor = vec3(0.0f, 0.0f, 0.0f);
  g.emissiveStrength = 1.0f;
  g.has_3ds_emission = false;
  g.emissionValue = 0.0f;
  g.emissionMode = DSPBR_EMISSIONMODE_LUMINOUS_EMITTANCE;
  g.emissionEnergyNormalization = false;
  g.specularFactor = 1.0f;
  g.specularColorFactor = vec3(1.0f, 1.0f, 1.0f);
  g.ior = 1.5f;
  g.transmissionFactor = 0.0f;
  g.has_volume = false;
  g.thicknessFactor = 0.0f;
  g.attenuationDistance = 3.402823466e38f;  // glTF: +inf
  g.attenuationColor = vec3(1.0f, 1.0f, 1.0f);
  g.dispersion = 0.0f;
  g.diffuseTransmissionFactor = 0.0f;
  g.diffuseTransmissionColorFactor = vec3(1.0f, 1.0f, 1.0f);
  g.has_3ds_translucency = false;
  g.translucencyFactor = 0.0f;
  g.subsurfaceColor = vec3(0.0f, 0.0f, 0.0f);
  g.subsurfaceAsymmetry = 0.0f;
  g.iridescenceFactor = 0.0f;
  g.iridescenceIor = 1.3f;
  g.iridescenceThicknessMaximum = 400.0f;
  g.has_sheen = false;
  g.sheenColorFactor = vec3(0.0f, 0.0f, 0.0f);
  g.sheenRoughnessFactor = 0.0f;
  g.clearcoatFactor = 0.0f;
  g.clearcoatRoughnessFactor = 0.0f;
  g.anisotropyStrength = 0.0f;
  g.anisotropyRotation = 0.0f;
  g.has_3ds_anisotropy = false;
  g.anisotropyFactor = 0.0f;
  g.anisotropyRotationFactor = 0.0f;
  return g;
}

// The factors as DSPBR_GLTF_FLOATS consecutive floats in the struct's order (an int as its value,
// a boolean as 0 or 1), as DSPBR_MATERIAL_PACK / UNPACK do for the material (material.glsl): a
// renderer uploads glTF factors per material with DSPBR_GLTF_PACK(g, rec, k) and reads them back
// with DSPBR_GLTF_UNPACK(g, rec, k).
DSPBR_CONST uint DSPBR_GLTF_FLOATS = 54u;
#define DSPBR_GLTF_UNPACK(g, rec, k) \
  (g).baseColorFactor = vec3((rec)[(k) + 0u], (rec)[(k) + 1u], (rec)[(k) + 2u]); \
  (g).baseColorAlpha = (rec)[(k) + 3u]; \
  (g).metallicFactor = (rec)[(k) + 4u]; \
  (g).roughnessFactor = (rec)[(k) + 5u]; \
  (g).alphaMode = int((rec)[(k) + 6u]); \
  (g).alphaCutoff = (rec)[(k) + 7u]; \
  (g).emissiveFactor = vec3((rec)[(k) + 8u], (rec)[(k) + 9u], (rec)[(k) + 10u]); \
  (g).emissiveStrength = (rec)[(k) + 11u]; \
  (g).has_3ds_emission = (rec)[(k) + 12u] > 0.5f; \
  (g).emissionValue = (rec)[(k) + 13u]; \
  (g).emissionMode = int((rec)[(k) + 14u]); \
  (g).emissionEnergyNormalization = (rec)[(k) + 15u] > 0.5f; \
  (g).specularFactor = (rec)[(k) + 16u]; \
  (g).specularColorFactor = vec3((rec)[(k) + 17u], (rec)[(k) + 18u], (rec)[(k) + 19u]); \
  (g).ior = (rec)[(k) + 20u]; \
  (g).transmissionFactor = (rec)[(k) + 21u]; \
  (g).has_volume = (rec)[(k) + 22u] > 0.5f; \
  (g).thicknessFactor = (rec)[(k) + 23u]; \
  (g).attenuationDistance = (rec)[(k) + 24u]; \
  (g).attenuationColor = vec3((rec)[(k) + 25u], (rec)[(k) + 26u], (rec)[(k) + 27u]); \
  (g).dispersion = (rec)[(k) + 28u]; \
  (g).diffuseTransmissionFactor = (rec)[(k) + 29u]; \
  (g).diffuseTransmissionColorFactor = vec3((rec)[(k) + 30u], (rec)[(k) + 31u], (rec)[(k) + 32u]); \
  (g).has_3ds_translucency = (rec)[(k) + 33u] > 0.5f; \
  (g).translucencyFactor = (rec)[(k) + 34u]; \
  (g).subsurfaceColor = vec3((rec)[(k) + 35u], (rec)[(k) + 36u], (rec)[(k) + 37u]); \
  (g).subsurfaceAsymmetry = (rec)[(k) + 38u]; \
  (g).iridescenceFactor = (rec)[(k) + 39u]; \
  (g).iridescenceIor = (rec)[(k) + 40u]; \
  (g).iridescenceThicknessMaximum = (rec)[(k) + 41u]; \
  (g).has_sheen = (rec)[(k) + 42u] > 0.5f; \
  (g).sheenColorFactor = vec3((rec)[(k) + 43u], (rec)[(k) + 44u], (rec)[(k) + 45u]); \
  (g).sheenRoughnessFactor = (rec)[(k) + 46u]; \
  (g).clearcoatFactor = (rec)[(k) + 47u]; \
  (g).clearcoatRoughnessFactor = (rec)[(k) + 48u]; \
  (g).anisotropyStrength = (rec)[(k) + 49u]; \
  (g).anisotropyRotation = (rec)[(k) + 50u]; \
  (g).has_3ds_anisotropy = (rec)[(k) + 51u] > 0.5f; \
  (g).anisotropyFactor = (rec)[(k) + 52u]; \
  (g).anisotropyRotationFactor = (rec)[(k) + 53u];
#define DSPBR_GLTF_PACK(g, rec, k) \
  (rec)[(k) + 0u] = (g).baseColorFactor.x; (rec)[(k) + 1u] = (g).baseColorFactor.y; (rec)[(k) + 2u] = (g).baseColorFactor.z; \
  (rec)[(k) + 3u] = (g).baseColorAlpha; \
  (rec)[(k) + 4u] = (g).metallicFactor; \
  (rec)[(k) + 5u] = (g).roughnessFactor; \
  (rec)[(k) + 6u] = float((g).alphaMode); \
  (rec)[(k) + 7u] = (g).alphaCutoff; \
  (rec)[(k) + 8u] = (g).emissiveFactor.x; (rec)[(k) + 9u] = (g).emissiveFactor.y; (rec)[(k) + 10u] = (g).emissiveFactor.z; \
  (rec)[(k) + 11u] = (g).emissiveStrength; \
  (rec)[(k) + 12u] = ((g).has_3ds_emission ? 1.0f : 0.0f); \
  (rec)[(k) + 13u] = (g).emissionValue; \
  (rec)[(k) + 14u] = float((g).emissionMode); \
  (rec)[(k) + 15u] = ((g).emissionEnergyNormalization ? 1.0f : 0.0f); \
  (rec)[(k) + 16u] = (g).specularFactor; \
  (rec)[(k) + 17u] = (g).specularColorFactor.x; (rec)[(k) + 18u] = (g).specularColorFactor.y; (rec)[(k) + 19u] = (g).specularColorFactor.z; \
  (rec)[(k) + 20u] = (g).ior; \
  (rec)[(k) + 21u] = (g).transmissionFactor; \
  (rec)[(k) + 22u] = ((g).has_volume ? 1.0f : 0.0f); \
  (rec)[(k) + 23u] = (g).thicknessFactor; \
  (rec)[(k) + 24u] = (g).attenuationDistance; \
  (rec)[(k) + 25u] = (g).attenuationColor.x; (rec)[(k) + 26u] = (g).attenuationColor.y; (rec)[(k) + 27u] = (g).attenuationColor.z; \
  (rec)[(k) + 28u] = (g).dispersion; \
  (rec)[(k) + 29u] = (g).diffuseTransmissionFactor; \
  (rec)[(k) + 30u] = (g).diffuseTransmissionColorFactor.x; (rec)[(k) + 31u] = (g).diffuseTransmissionColorFactor.y; (rec)[(k) + 32u] = (g).diffuseTransmissionColorFactor.z; \
  (rec)[(k) + 33u] = ((g).has_3ds_translucency ? 1.0f : 0.0f); \
  (rec)[(k) + 34u] = (g).translucencyFactor; \
  (rec)[(k) + 35u] = (g).subsurfaceColor.x; (rec)[(k) + 36u] = (g).subsurfaceColor.y; (rec)[(k) + 37u] = (g).subsurfaceColor.z; \
  (rec)[(k) + 38u] = (g).subsurfaceAsymmetry; \
  (rec)[(k) + 39u] = (g).iridescenceFactor; \
  (rec)[(k) + 40u] = (g).iridescenceIor; \
  (rec)[(k) + 41u] = (g).iridescenceThicknessMaximum; \
  (rec)[(k) + 42u] = ((g).has_sheen ? 1.0f : 0.0f); \
  (rec)[(k) + 43u] = (g).sheenColorFactor.x; (rec)[(k) + 44u] = (g).sheenColorFactor.y; (rec)[(k) + 45u] = (g).sheenColorFactor.z; \
  (rec)[(k) + 46u] = (g).sheenRoughnessFactor; \
  (rec)[(k) + 47u] = (g).clearcoatFactor; \
  (rec)[(k) + 48u] = (g).clearcoatRoughnessFactor; \
  (rec)[(k) + 49u] = (g).anisotropyStrength; \
  (rec)[(k) + 50u] = (g).anisotropyRotation; \
  (rec)[(k) + 51u] = ((g).has_3ds_anisotropy ? 1.0f : 0.0f); \
  (rec)[(k) + 52u] = (g).anisotropyFactor; \
  (rec)[(k) + 53u] = (g).anisotropyRotationFactor;

// KHR_materials_anisotropy turns the anisotropy direction counter-clockwise (tangent towards
// bitangent); DSPBR turns the tangent clockwise (t' cos beta - (n x t') sin beta, spec "Tangent
// Space"): rotation = -theta / 2 pi, wrapped into [0, 1).
DSPBR_FN float dspbr_gltf_rotation_from_khr(float theta) {
  float turns = -theta / (2.0f * dspbr_pi);
  return turns - floor(turns);
}

// The DSPBR material of glTF factors (docs/gltf_mapping.md, "Parameter by parameter").
DSPBR_FN DspbrMaterial dspbr_material_from_gltf(DSPBR_IN(DspbrGltf) g) {
  DspbrMaterial m = dspbr_default_material();
  m.albedo = g.baseColorFactor;
  m.metallic = g.metallicFactor;
  m.roughness = g.roughnessFactor;
  if (g.alphaMode == DSPBR_GLTF_ALPHA_BLEND) m.cutoutOpacity = g.baseColorAlpha;
  if (g.alphaMode == DSPBR_GLTF_ALPHA_MASK) m.cutoutOpacity = g.baseColorAlpha >= g.alphaCutoff ? 1.0f : 0.0f;
  // Emission: glTF's emissive x strength read as luminance in cd/m^2: l_c = that, l_v = pi
  // (rho_e = l_v l_c / pi, spec "Emission") unless 3DS_materials_emission gives them.
  m.emissionColor = g.emissiveFactor * g.emissiveStrength;
  if (g.has_3ds_emission) {
    m.emissionValue = g.emissionValue;
    m.emissionMode = g.emissionMode;
    m.emissionEnergyNormalization = g.emissionEnergyNormalization;
  } else {
    m.emissionValue = dspbr_max3(m.emissionColor) > 0.0f ? dspbr_pi : 0.0f;
  }
  m.specular = g.specularFactor;
  m.specularTint = g.specularColorFactor;
  m.ior = g.ior;
  m.transparency = g.transmissionFactor;
  // glTF: thickness 0 (or no volume) is a thin wall.
  m.thinWalled = !(g.has_volume && g.thicknessFactor > 0.0f);
  if (g.has_volume) {
    m.attenuationDistance = g.attenuationDistance;
    m.attenuationColor = g.attenuationColor;
  }
  m.abbeNumber = g.dispersion > 0.0f ? 20.0f / g.dispersion : 0.0f;
  m.translucency = g.has_3ds_translucency ? g.translucencyFactor : g.diffuseTransmissionFactor;
  m.translucencyColor = g.diffuseTransmissionColorFactor;
  m.subsurfaceColor = g.subsurfaceColor;
  m.subsurfaceAnisotropy = g.subsurfaceAsymmetry;
  m.thinFilm = g.iridescenceFactor;
  m.thinFilmIor = g.iridescenceIor;
  m.thinFilmThickness = g.iridescenceThicknessMaximum / 1000.0f;  // nm -> um
  if (g.has_sheen) {
    m.sheenColor = g.sheenColorFactor;
    m.sheenRoughness = g.sheenRoughnessFactor;
  }
  m.clearcoat = g.clearcoatFactor;
  m.clearcoatRoughness = g.clearcoatRoughnessFactor;
  if (g.has_3ds_anisotropy) {
    m.anisotropy = g.anisotropyFactor;
    m.anisotropyRotation = g.anisotropyRotationFactor;
  } else {
    m.anisotropy = g.anisotropyStrength;
    m.anisotropyRotation = dspbr_gltf_rotation_from_khr(g.anisotropyRotation);
  }
  return m;
}
