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
