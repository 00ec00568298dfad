// The DSPBR generic material: one field per parameter of params-2025x.json's "generic"
// material, named by its JSON id, with the JSON defaults. Ranges and their handling are
// documented per field in validate_material() (material.cpp).
#pragma once
#include <limits>
#include <string>

#include "dspbr/vec3.h"

namespace dspbr {

enum class EmissionMode { LuminousEmittance, LuminousPower };  // lx (lm/m^2) or lm

struct Material {
  // Base
  Rgb albedo{1, 1, 1};
  double metallic = 0;
  double roughness = 0;
  double anisotropy = 0;
  double anisotropyRotation = 0;  // [0,1] -> [0, 360 deg]
  Vec3 normal{0, 0, 1};           // in the local (unperturbed) shading frame
  Vec3 displacement{0, 0, 0};     // in the tangent frame (t, b, n)
  double translucency = 0;
  Rgb translucencyColor{1, 1, 1};
  double transparency = 0;
  double cutoutOpacity = 1;
  double specular = 1;
  Rgb specularTint{1, 1, 1};
  // Iridescence (thin film)
  double thinFilm = 0;
  double thinFilmThickness = 0.4;  // microns
  double thinFilmIor = 1.3;
  // Sheen
  Rgb sheenColor{0, 0, 0};
  double sheenRoughness = 0.5;
  // Flakes
  double flakeCoverage = 0;
  Rgb flakeColor{1, 1, 1};
  double flakeSize = 0;  // mm
  double flakeRoughness = 0;
  double flipFlop = 0;
  Rgb flipFlopColor{1, 1, 1};
  // Coating
  double clearcoat = 0;
  double clearcoatRoughness = 0;
  Vec3 clearcoatNormal{0, 0, 1};
  // Emission
  Rgb emissionColor{1, 1, 1};
  double emissionValue = 0;
  EmissionMode emissionMode = EmissionMode::LuminousEmittance;
  bool emissionEnergyNormalization = false;
  // Volume
  bool thinWalled = true;
  double ior = 1.5;
  double abbeNumber = 0;
  Rgb attenuationColor{1, 1, 1};
  double attenuationDistance = std::numeric_limits<double>::infinity();
  Rgb subsurfaceColor{0, 0, 0};
  double subsurfaceAnisotropy = 0;
};

// Checks every field against the ranges of params-2025x.json's generic material and throws
// std::invalid_argument with a one-line message naming the first bad field, its value and the
// range ("parameter 'roughness' = 1.5 is outside [0, 1]"). Per field (material.cpp):
// - float in [min, max] (max absent: [min, +inf)); NaN and infinities rejected, except
//   attenuationDistance, which may be +inf (no attenuation);
// - colour channels in [0, max] (emissionColor: [0, +inf));
// - normal / clearcoatNormal: finite and non-zero; the BSDF normalizes them (spec: |n| = 1);
// - displacement: finite.
// Nothing is clamped silently: the spec gives ranges, not clamping rules.
void validate_material(const Material& m);

}  // namespace dspbr
