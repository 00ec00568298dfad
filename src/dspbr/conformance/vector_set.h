// The conformance vector set (docs/conformance.md): materials covering every component of DSPBR
// 2025x alone and combined, a plain metal and a plain plastic set, the extremes, and optionally
// the materials of the validation scenes (through the glTF mapping), each at seeded pairs of
// directions, evaluated with the reference BSDF (built-in renderer tables, default options but
// those a vector names). The same seed gives the same vectors whatever the thread count.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dspbr/conformance/vector.h"

namespace dspbr::conformance {

struct GenerateSettings {
  std::uint64_t seed = 1;
  int directions = 20;      // pairs of directions per material (the extremes add their own)
  std::string scenes_dir;   // folder of .gltf files whose materials join the set ("": none)
  bool albedo = true;       // the directional albedo at the first vector of each material (where the quadrature converges)
};

// The stated maximum error of the reference's table lookups at the point of use (the renderer
// layout; README "Tables in a renderer": every DSPBR table within 1.1e-3). The tolerances derive
// from it (docs/conformance.md, "Tolerances").
inline constexpr double kTableError = 1.1e-3;
// Relative error allowed for float evaluation of the closed forms.
inline constexpr double kFloatRelative = 1e-5;
// Absolute floor (f cos units) for values that cancel to about zero in float.
inline constexpr double kFloatAbsolute = 1e-6;
// The thin-film reflectance R of the reference is a spline of its spectral integral within 1e-4
// (docs/bsdf.md, "Cost and threads"); relative to the smallest R of a film (about 0.04), 2.5e-3.
inline constexpr double kThinFilmRelative = 2.5e-3;

// The albedo of a vector is given when two quadrature resolutions agree within this (per channel).
inline constexpr double kAlbedoAgreement = 2e-3;

// Throws std::runtime_error naming the file for an unreadable scene file.
std::vector<Vector> generate_vectors(const GenerateSettings& s);

}  // namespace dspbr::conformance

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/conformance/results.h"

namespace dspbr::conformance {

// The material of a vector (its instance against the built-in definitions) and its BSDF options.
// Throws std::runtime_error for an invalid instance or options.
Material vector_material(const Vector& v);
BsdfOptions vector_options(const Vector& v);

// What an implementation reading `luts` computes for a vector: f cos and pdf (the reference BSDF
// with those tables). `evaluate(v, LutSet::builtin())` reproduces the expected values.
struct Evaluation {
  Rgb f_cos;
  double pdf = 0;
};
Evaluation evaluate(const Vector& v, const LutSet& luts);

// What an implementation behind the Bsdf interface gives for vector x, as `conformance check`
// judges it: f cos and pdf, the delta lobes (the sweep of generate, where b.flags() has a Dirac
// lobe) and, where x has one, the albedo (generate's finer quadrature plus the delta lobes). The
// emission is not part of Bsdf: left out. `dspbr validate` judges the shader library's C++ compile
// with it (apps/dspbr/validate_shader_library.h).
Result implementation_result(const Vector& x, const Bsdf& b);

// How an implementation represents DSPBR where it differs from the reference by design
// (`conformance check --tables`, `--min-roughness`).
struct Representation {
  const LutSet* tables = nullptr;  // the energy tables it reads (nullptr: the renderer tables)
  double min_roughness = 0;        // it clamps roughness and clearcoatRoughness to at least this
};

// The vectors' expectations as the reference computes them for that representation: f cos, pdf,
// the delta lobes and, where a vector has one, the albedo (the finer of generate's two
// quadratures) with the tables; with min_roughness > 0, f cos, pdf and the delta lobes of the
// material with its roughnesses clamped (a mirror becomes a narrow lobe: its delta lobes go, its
// peak is judged against the clamped lobe's), the albedo kept (the mirror's reflectance, which the
// narrow lobe carries). The tolerances stay: their table part (kTableError) then allows the
// implementation's lookups that far from the tables' own. Throws std::runtime_error for an
// invalid instance or options.
void expect_with(std::vector<Vector>& vectors, const Representation& r);

// The reference BSDF of vector `v` (material `m`, its vector_material) as an implementation with
// that representation reads it: its tables, its roughness clamp, and the conformance diagnosis's
// `deviation` (diagnosis.h) in the options. expect_with's and the diagnosis's one construction.
MaterialBsdf represented_bsdf(const Vector& v, Material m, const Representation& r,
                              Deviation deviation = Deviation::None);

}  // namespace dspbr::conformance
