// One conformance vector (docs/conformance.md, "Schema"): a material in the params instance form,
// a pair of directions in the local frame of docs/bsdf.md, and what the reference computes there
// with the tolerance an implementation is held to. Shared by the generator (vector_set.h), the
// document reader and writers (vector_file.h) and the checker (checker.h).
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dspbr/vec3.h"

namespace dspbr::conformance {

inline constexpr const char* kFormat = "dspbr-conformance";
inline constexpr int kFormatVersion = 1;

// |result - expected| <= abs + rel |expected|, per channel.
struct Tolerance {
  double abs = 0, rel = 0;
  bool admits(double result, double expected) const;
  // |result - expected| / (abs + rel |expected|): <= 1 passes.
  double ratio(double result, double expected) const;
};

// The delta (perfectly smooth) lobes towards one direction: the sum of their reflectances /
// transmittances (docs/bsdf.md, "Conventions": sample weight times discrete probability).
struct DeltaExpectation {
  Vec3 l;
  Rgb value;
};

struct Vector {
  std::string id;
  std::string group;                    // the set it belongs to (per-group verdicts): a component name,
                                        // "plain_metal", "plain_plastic", "combined", "extremes", "scenes"
  std::vector<std::string> components;  // the material's active components (dspbr/component.h names)
  nlohmann::ordered_json material;      // {"material": TYPE, "values": {...}} (docs/params.md)
  nlohmann::ordered_json gltf_material; // the glTF material object when the vector comes from one, else null
  nlohmann::ordered_json options;       // BSDF options besides the defaults ({"sheen": "ash"},
                                        // {"position": [...], "object_normal": [...]}), else null
  Vec3 v, l;
  Rgb f_cos;  // f(v, l) |l.z|, delta lobes excluded
  Tolerance tolerance;
  double pdf = 0;  // the reference sampler's solid-angle density of l
  Tolerance pdf_tolerance;
  std::optional<Rgb> albedo;  // directional albedo at v (delta lobes included)
  Tolerance albedo_tolerance;
  std::optional<Rgb> emission;  // L_e(v) when the material emits
  Tolerance emission_tolerance;
  std::vector<DeltaExpectation> delta;  // the delta lobes at v (empty: none)
  Tolerance delta_tolerance;
};

}  // namespace dspbr::conformance
