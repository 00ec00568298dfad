#include "dspbr/gltf/gltf_material.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <set>
#include <stdexcept>

#include "dspbr/constants.h"
#include "dspbr/params/material_instance.h"
#include "dspbr/params/material_params.h"
#include "dspbr/params/param_defs.h"
#include "dspbr/io/json_fields.h"
#include "dspbr/limits.h"

namespace dspbr::gltf {

namespace {

using Json = nlohmann::json;

// Material extensions this mapping reads (docs/gltf_mapping.md).
const std::set<std::string>& known_extensions() {
  static const std::set<std::string> names{
      "KHR_materials_clearcoat",   "KHR_materials_sheen",         "KHR_materials_transmission",
      "KHR_materials_volume",      "KHR_materials_ior",           "KHR_materials_specular",
      "KHR_materials_iridescence", "KHR_materials_anisotropy",    "KHR_materials_emissive_strength",
      "KHR_materials_dispersion",  "KHR_materials_diffuse_transmission", "3DS_materials_anisotropy",
      "3DS_materials_translucency", "3DS_materials_sss",          "3DS_materials_volume",
      "3DS_materials_emission"};
  return names;
}

class Mapper {
 public:
  Mapper(const GltfFile& file, const Json& mat, GltfMaterial& out)
      : file_(file), mat_(mat), out_(out) {
    n_textures_ = file.json.contains("textures") && file.json["textures"].is_array() ? file.json["textures"].size() : 0;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(file_.path + ": materials[" + std::to_string(out_.index) + "] '" + out_.name + "': " + what);
  }

  // An extension object from "extensions", else from "extras" (as in the validation scenes).
  const Json* ext(const char* name) const {
    for (const char* where : {"extensions", "extras"}) {
      if (!mat_.contains(where) || !mat_[where].is_object() || !mat_[where].contains(name)) continue;
      const Json& e = mat_[where][name];
      if (!e.is_object()) fail(std::string(where) + "." + name + " must be an object");
      return &e;
    }
    return nullptr;
  }

  double number(const Json& obj, const char* key, double fallback, const std::string& prefix) const {
    if (!obj.contains(key)) return fallback;
    if (!obj[key].is_number()) fail(prefix + key + " must be a number, got " + json_fields::quoted(obj[key]));
    const double x = obj[key].get<double>();
    if (!std::isfinite(x)) fail(prefix + key + " must be finite");
    return x;
  }

  template <std::size_t N>
  std::array<double, N> numbers(const Json& obj, const char* key, std::array<double, N> fallback,
                                const std::string& prefix) const {
    if (!obj.contains(key)) return fallback;
    const Json& v = obj[key];
    if (!v.is_array() || v.size() != N)
      fail(prefix + key + " must be an array of " + std::to_string(N) + " numbers, got " + json_fields::quoted(v));
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
      if (!v[i].is_number()) fail(prefix + key + " must be an array of " + std::to_string(N) + " numbers, got " + json_fields::quoted(v));
      out[i] = v[i].get<double>();
      if (!std::isfinite(out[i])) fail(prefix + key + " must hold finite numbers");
    }
    return out;
  }

  // Records a textureInfo property (glTF "textureInfo": {"index": i, ...}) driving `params`.
  void texture(const Json& obj, const char* key, const std::string& prefix, std::initializer_list<const char*> params,
               bool multiplies = true) {
    if (!obj.contains(key)) return;
    const Json& t = obj[key];
    if (!t.is_object() || !t.contains("index") || !t["index"].is_number_integer())
      fail(prefix + key + " must be a textureInfo object with an integer \"index\"");
    // The index as written (nlohmann keeps 2^63 and above unsigned: get<long long> would wrap it).
    const Json& i = t["index"];
    const bool in_range = i.is_number_unsigned() ? i.get<std::uint64_t>() < n_textures_
                                                 : i.get<long long>() >= 0 && std::uint64_t(i.get<long long>()) < n_textures_;
    if (!in_range) fail(prefix + key + " refers to texture " + i.dump() + ", which does not exist");
    const long long index = i.get<long long>();
    for (const char* p : params) out_.textures.push_back({p, prefix + key, static_cast<int>(index), multiplies});
  }

  Rgb rgb(const std::array<double, 3>& a) const { return {a[0], a[1], a[2]}; }

  void run() {
    Material& m = out_.material;
    // Core metallic-roughness (glTF 2.0 "material.pbrMetallicRoughness"); defaults per the glTF spec.
    const Json pbr = mat_.value("pbrMetallicRoughness", Json::object());
    if (!pbr.is_object()) fail("pbrMetallicRoughness must be an object");
    const std::string pp = "pbrMetallicRoughness.";
    const auto base = numbers<4>(pbr, "baseColorFactor", {1, 1, 1, 1}, pp);
    m.albedo = {base[0], base[1], base[2]};
    m.metallic = number(pbr, "metallicFactor", 1.0, pp);
    m.roughness = number(pbr, "roughnessFactor", 1.0, pp);
    texture(pbr, "baseColorTexture", pp, {"albedo"});
    texture(pbr, "metallicRoughnessTexture", pp, {"metallic", "roughness"});
    // Alpha: BLEND uses alpha as coverage, MASK thresholds it at alphaCutoff, OPAQUE ignores it.
    if (mat_.contains("alphaMode") && !mat_["alphaMode"].is_string())
      fail("alphaMode must be a string (OPAQUE, MASK or BLEND), got " + json_fields::quoted(mat_["alphaMode"]));
    const std::string alpha_mode = mat_.value("alphaMode", std::string("OPAQUE"));
    if (alpha_mode == "BLEND") {
      m.cutoutOpacity = base[3];
      texture(pbr, "baseColorTexture", pp, {"cutoutOpacity"});
    } else if (alpha_mode == "MASK") {
      m.cutoutOpacity = base[3] >= number(mat_, "alphaCutoff", 0.5, "") ? 1.0 : 0.0;
      texture(pbr, "baseColorTexture", pp, {"cutoutOpacity"}, false);
    } else if (alpha_mode != "OPAQUE") {
      fail("alphaMode must be OPAQUE, MASK or BLEND, got \"" + alpha_mode + "\"");
    }
    texture(mat_, "normalTexture", "", {"normal"}, false);
    texture(mat_, "occlusionTexture", "", {""});  // no DSPBR counterpart (ambient occlusion)

    // Emission: glTF emissive (times KHR_materials_emissive_strength) read as luminance in cd/m^2.
    double strength = 1.0;
    if (const Json* e = ext("KHR_materials_emissive_strength"))
      strength = number(*e, "emissiveStrength", 1.0, "KHR_materials_emissive_strength.");
    const auto emissive = numbers<3>(mat_, "emissiveFactor", {0, 0, 0}, "");
    texture(mat_, "emissiveTexture", "", {"emissionColor"});
    m.emissionColor = rgb(emissive) * strength;
    if (!(std::isfinite(m.emissionColor.r) && std::isfinite(m.emissionColor.g) && std::isfinite(m.emissionColor.b)))
      fail("emissiveFactor x KHR_materials_emissive_strength.emissiveStrength is beyond the largest number");
    if (const Json* e = ext("3DS_materials_emission")) {
      const std::string p = "3DS_materials_emission.";
      m.emissionValue = number(*e, "emissionValue", 0.0, p);
      if (e->contains("emissionMode")) {
        try {
          set_material_parameter(m, "emissionMode", (*e)["emissionMode"]);
        } catch (const std::exception& ex) {
          fail(p + ex.what());
        }
      }
      if (e->contains("emissionEnergyNormalization")) {
        if (!(*e)["emissionEnergyNormalization"].is_boolean()) fail(p + "emissionEnergyNormalization must be true or false");
        m.emissionEnergyNormalization = (*e)["emissionEnergyNormalization"].get<bool>();
      }
    } else {
      // DSPBR luminance rho_e = l_v l_c / pi (spec "Emission", luminous emittance): l_v = pi gives
      // rho_e = emissive * strength.
      m.emissionValue = m.emissionColor.max_component() > 0 ? kPi : 0.0;
    }

    if (const Json* e = ext("KHR_materials_specular")) {
      const std::string p = "KHR_materials_specular.";
      m.specular = number(*e, "specularFactor", 1.0, p);
      m.specularTint = rgb(numbers<3>(*e, "specularColorFactor", {1, 1, 1}, p));
      texture(*e, "specularTexture", p, {"specular"});
      texture(*e, "specularColorTexture", p, {"specularTint"});
    }
    if (const Json* e = ext("KHR_materials_ior")) m.ior = number(*e, "ior", 1.5, "KHR_materials_ior.");
    if (const Json* e = ext("KHR_materials_transmission")) {
      const std::string p = "KHR_materials_transmission.";
      m.transparency = number(*e, "transmissionFactor", 0.0, p);
      texture(*e, "transmissionTexture", p, {"transparency"});
    }
    // Without KHR_materials_volume (or with thickness 0) a glTF surface is thin-walled.
    m.thinWalled = true;
    if (const Json* e = ext("KHR_materials_volume")) {
      const std::string p = "KHR_materials_volume.";
      m.thinWalled = !(number(*e, "thicknessFactor", 0.0, p) > 0);
      texture(*e, "thicknessTexture", p, {""}, false);  // thickness: geometry in DSPBR, no parameter
      if (e->contains("attenuationDistance")) {
        m.attenuationDistance = number(*e, "attenuationDistance", 0.0, p);
        if (!(m.attenuationDistance > 0))  // the extension's schema: exclusiveMinimum 0
          out_.notes.push_back("outside the glTF range, kept: KHR_materials_volume.attenuationDistance " +
                               json_fields::excerpt(Json(m.attenuationDistance)) + " must be above 0");
      }
      m.attenuationColor = rgb(numbers<3>(*e, "attenuationColor", {1, 1, 1}, p));
    }
    if (const Json* e = ext("KHR_materials_dispersion")) {
      // KHR_materials_dispersion: dispersion = 20 / V_d; DSPBR abbeNumber 0 means no dispersion.
      const double d = number(*e, "dispersion", 0.0, "KHR_materials_dispersion.");
      m.abbeNumber = d > 0 ? 20.0 / d : 0.0;
      if (d < 0)  // the extension's schema: minimum 0
        out_.notes.push_back("outside the glTF range: KHR_materials_dispersion.dispersion " + json_fields::excerpt(Json(d)) +
                             " must be at least 0; mapped to no dispersion");
    }
    if (const Json* e = ext("KHR_materials_diffuse_transmission")) {
      const std::string p = "KHR_materials_diffuse_transmission.";
      m.translucency = number(*e, "diffuseTransmissionFactor", 0.0, p);
      m.translucencyColor = rgb(numbers<3>(*e, "diffuseTransmissionColorFactor", {1, 1, 1}, p));
      texture(*e, "diffuseTransmissionTexture", p, {"translucency"});
      texture(*e, "diffuseTransmissionColorTexture", p, {"translucencyColor"});
    }
    if (const Json* e = ext("3DS_materials_translucency")) {
      const std::string p = "3DS_materials_translucency.";
      m.translucency = number(*e, "translucencyFactor", 0.0, p);
      texture(*e, "translucencyTexture", p, {"translucency"});
    }
    for (const char* name : {"3DS_materials_sss", "3DS_materials_volume"}) {
      if (const Json* e = ext(name)) {
        const std::string p = std::string(name) + ".";
        m.subsurfaceColor = rgb(numbers<3>(*e, "subsurfaceColor", {0, 0, 0}, p));
        m.subsurfaceAnisotropy = number(*e, "subsurfaceAsymmetry", 0.0, p);
      }
    }
    if (const Json* e = ext("KHR_materials_iridescence")) {
      const std::string p = "KHR_materials_iridescence.";
      m.thinFilm = number(*e, "iridescenceFactor", 0.0, p);
      m.thinFilmIor = number(*e, "iridescenceIor", 1.3, p);
      // Without a thickness texture the film is iridescenceThicknessMaximum thick (nm -> microns).
      m.thinFilmThickness = number(*e, "iridescenceThicknessMaximum", 400.0, p) / 1000.0;
      number(*e, "iridescenceThicknessMinimum", 100.0, p);  // type check only
      texture(*e, "iridescenceTexture", p, {"thinFilm"});
      texture(*e, "iridescenceThicknessTexture", p, {"thinFilmThickness"}, false);
    }
    if (const Json* e = ext("KHR_materials_sheen")) {
      const std::string p = "KHR_materials_sheen.";
      m.sheenColor = rgb(numbers<3>(*e, "sheenColorFactor", {0, 0, 0}, p));
      m.sheenRoughness = number(*e, "sheenRoughnessFactor", 0.0, p);
      texture(*e, "sheenColorTexture", p, {"sheenColor"});
      texture(*e, "sheenRoughnessTexture", p, {"sheenRoughness"});
    }
    if (const Json* e = ext("KHR_materials_clearcoat")) {
      const std::string p = "KHR_materials_clearcoat.";
      m.clearcoat = number(*e, "clearcoatFactor", 0.0, p);
      m.clearcoatRoughness = number(*e, "clearcoatRoughnessFactor", 0.0, p);
      texture(*e, "clearcoatTexture", p, {"clearcoat"});
      texture(*e, "clearcoatRoughnessTexture", p, {"clearcoatRoughness"});
      texture(*e, "clearcoatNormalTexture", p, {"clearcoatNormal"}, false);
    }
    const Json* khr_aniso = ext("KHR_materials_anisotropy");
    const Json* ds_aniso = ext("3DS_materials_anisotropy");
    if (khr_aniso && ds_aniso)
      out_.notes.push_back("both KHR_materials_anisotropy and 3DS_materials_anisotropy given: 3DS_materials_anisotropy used");
    if (khr_aniso && !ds_aniso) {
      const std::string p = "KHR_materials_anisotropy.";
      m.anisotropy = number(*khr_aniso, "anisotropyStrength", 0.0, p);
      if (m.anisotropy > 0)
        out_.notes.push_back("approximate mapping: KHR_materials_anisotropy's strength is copied to DSPBR's anisotropy "
                             "(the highlight's shape differs, docs/gltf_mapping.md)");
      // Radians, counter-clockwise from the tangent (towards the bitangent); DSPBR turns the tangent
      // clockwise (t' cos b - (n x t') sin b, spec "Tangent Space"): -theta / 2 pi, in [0, 1).
      const double turns = -number(*khr_aniso, "anisotropyRotation", 0.0, p) / (2 * kPi);
      m.anisotropyRotation = turns - std::floor(turns);
      texture(*khr_aniso, "anisotropyTexture", p, {"anisotropy"});
      texture(*khr_aniso, "anisotropyTexture", p, {"anisotropyRotation"}, false);
    }
    if (ds_aniso) {
      const std::string p = "3DS_materials_anisotropy.";
      // The published schema spells the strength "ansiotropyFactor"; the scenes use "anisotropyFactor".
      m.anisotropy = number(*ds_aniso, ds_aniso->contains("anisotropyFactor") ? "anisotropyFactor" : "ansiotropyFactor", 0.0, p);
      m.anisotropyRotation = number(*ds_aniso, "anisotropyRotationFactor", 0.0, p);
      texture(*ds_aniso, "anisotropyTexture", p, {"anisotropy", "anisotropyRotation"});
    }
    // Extensions we do not read.
    if (mat_.contains("extensions") && mat_["extensions"].is_object())
      for (const auto& [name, _] : mat_["extensions"].items())
        if (!known_extensions().count(name)) out_.notes.push_back("extension " + name + " is not mapped (ignored)");
  }

 private:
  const GltfFile& file_;
  const Json& mat_;
  GltfMaterial& out_;
  std::size_t n_textures_ = 0;
};

// Mapped values outside the DSPBR generic material's ranges (reported, kept as they are).
void range_notes(GltfMaterial& g) {
  static const ParamDefs* defs = [] () -> const ParamDefs* {
    try {
      static const ParamDefs d = default_param_defs();
      return &d;
    } catch (const std::exception&) {
      return nullptr;
    }
  }();
  if (!defs || !defs->has_material("generic")) return;
  Json values = Json::object();
  for (const auto& id : material_parameter_ids())
    if (defs->material("generic").find(id)) values[id] = get_material_parameter(g.material, id);
  for (const auto& problem : check_material_instance(*defs, {{"material", "generic"}, {"values", values}}))
    g.notes.push_back("outside the DSPBR range, kept: " + problem);
}

}  // namespace

std::vector<std::string> GltfMaterial::textured_parameters() const {
  std::vector<std::string> ids;
  for (const auto& t : textures)
    if (!t.parameter.empty() && std::find(ids.begin(), ids.end(), t.parameter) == ids.end()) ids.push_back(t.parameter);
  return ids;
}

std::vector<GltfMaterial> map_materials(const GltfFile& file) {
  std::vector<GltfMaterial> out;
  if (!file.json.contains("materials")) return out;
  const Json& mats = file.json["materials"];
  if (!mats.is_array()) throw std::runtime_error(file.path + ": \"materials\" must be an array");
  if (mats.size() > limits::kSceneMaterials)
    throw std::runtime_error(file.path + ": " + std::to_string(mats.size()) + " materials, more than the limit of " +
                             std::to_string(limits::kSceneMaterials) + " (docs/limits.md)");
  std::set<std::string> required;
  if (file.json.contains("extensionsRequired") && file.json["extensionsRequired"].is_array())
    for (const auto& r : file.json["extensionsRequired"])
      if (r.is_string()) required.insert(r.get<std::string>());
  for (std::size_t i = 0; i < mats.size(); ++i) {
    GltfMaterial g;
    g.index = static_cast<int>(i);
    const Json& mat = mats[i];
    if (mat.is_object() && mat.contains("name") && mat["name"].is_string()) g.name = mat["name"].get<std::string>();
    if (g.name.empty()) g.name = "material " + std::to_string(i);
    if (!mat.is_object())
      throw std::runtime_error(file.path + ": materials[" + std::to_string(i) + "] must be an object");
    Mapper(file, mat, g).run();
    for (const auto& r : required)
      if (r.rfind("KHR_materials_", 0) == 0 && !known_extensions().count(r) && mat.contains("extensions") &&
          mat["extensions"].is_object() && mat["extensions"].contains(r))
        g.notes.push_back("required extension " + r + " is not mapped: the result is approximate");
    range_notes(g);
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace dspbr::gltf
