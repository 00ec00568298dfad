// Host-side helpers of the shader-library tests (tests/shader_library/): the reference material
// as the shader library's DspbrMaterial (src/dspbr/shader/material_mapping.h), its
// packing into the float records the device kernels read (kernel_common.glsl, in pack_record's
// order), the verdict on a set of results, and the library behind the reference's Bsdf interface.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "dspbr.h"
#include "dspbr/bsdf/bsdf.h"
#include "dspbr/bsdf/lobe_assembly.h"
#include "dspbr/conformance/vector.h"
#include "dspbr/conformance/vector_set.h"
#include "dspbr/material.h"
#include "dspbr/shader/material_mapping.h"
#include "dspbr/shader/shader_bsdf.h"
#include "dspbr/validate/chi2.h"

namespace shader_test {

using dspbr::shader::to_shader_material;
using dspbr::shader::to_shader_options;
// Every field of a DspbrMaterial by name (vec3 fields as name.x, .y, .z), for comparisons.
std::vector<std::pair<std::string, double>> material_fields(const dspbr_shader::DspbrMaterial& m);

// One vector's record for the device kernels: the material (DSPBR_MATERIAL_PACK), the options,
// v and l (kRecordFloats floats). The kernels write kResultFloats floats per vector in mode 0
// (kernel_common.glsl).
constexpr int kRecordFloats = 80;  // kernel_common.glsl's DSPBR_TEST_RECORD_FLOATS
constexpr int kResultFloats = 10;
constexpr int kAlbedoNodes = 256;  // albedo.glsl's DSPBR_TEST_ALBEDO_NODES
void pack_record(const dspbr::conformance::Vector& v, float* out);

// An implementation's results for one vector (the checker's Result, in float).
struct Outcome {
  dspbr_shader::vec3 f_cos;
  float pdf;
  std::optional<dspbr_shader::vec3> albedo, emission;
  std::optional<std::vector<dspbr::conformance::DeltaExpectation>> delta;
};
// The C++ compile's results for a vector: f cos and pdf; the albedo, the emission and the Dirac
// lobes where the vector gives them.
Outcome evaluate(const dspbr::conformance::Vector& x);
// A device kernel's results for a vector: kResultFloats floats of mode 0, and where the vector
// gives an albedo its kAlbedoNodes node sums (mode 1, 3 floats each) and its kDeltaChoices
// samples (mode 2, 7 floats each; kernel_common.glsl).
constexpr int kDeltaChoices = 8192;
Outcome outcome_from_device(const dspbr::conformance::Vector& x, const float* r, const float* nodes, const float* samples);
// The results file `dspbr conformance check` reads (JSON, docs/conformance.md "Results").
void write_results(const std::string& path, const std::vector<dspbr::conformance::Vector>& vectors,
                   const std::vector<Outcome>& results);
// The verdict on f cos and the pdf against each vector's tolerances, for a subset of the vectors
// (the checker wants every vector): prints a line per group and the failures (at most `show`);
// returns the number of failing vectors.
int judge(const std::vector<dspbr::conformance::Vector>& vectors, const std::vector<Outcome>& results,
          const std::string& what, int show = 12);

// One vector per built-in conformance material (the kit's own materials: each component, the plain
// sets, the combinations, the extremes), one direction each.
const std::vector<dspbr::conformance::Vector>& builtin_materials();

// The chi-square cases of the shader library (ShaderLibrary.SamplingMatchesPdfByChiSquare in C++,
// shader_vk_chi2 on the device): every built-in conformance material (one vector each), viewed at
// cos 0.7 and 0.2 from above and, for a volume, at -0.5 from inside; a thin film (spectral
// quadratures in every pdf call) at cos 0.7 only, with 30 theta bins and every 20th sample's
// consistency. settings.num_tests and stream are set for the whole list.
struct Chi2Case {
  dspbr::conformance::Vector vector;
  dspbr::Vec3 v;
  dspbr::validate::Chi2Settings settings;
};
std::vector<Chi2Case> chi2_cases();
// A failed chi-square result in one line: p and alpha, the support, the pdf's integral, the
// consistency deviations, the non-finite samples.
std::string chi2_summary(const dspbr::validate::Chi2Result& r);

// The Dirac lobes from the samples at kDeltaChoices stratified lobe choices (u = ((k + 0.5) /
// kDeltaChoices, 0.5, 0.5)), each as 7 floats: 1 for a Dirac sample, l, weight x pdf. A lobe's
// choices are one run of equal directions; weight x probability of any of its samples is its
// reflectance or transmittance (docs/bsdf.md, "Conventions").
std::vector<dspbr::conformance::DeltaExpectation> delta_lobes(const float* samples);
// The same samples from the C++ compile.
std::vector<float> delta_samples(const dspbr_shader::DspbrBsdf& b, dspbr_shader::vec3 v);

}  // namespace shader_test

namespace shader_test {

// The shader library's C++ compile behind the reference's Bsdf interface (src/dspbr/shader/shader_bsdf.h).
using dspbr::shader::ShaderBsdf;

}  // namespace shader_test
