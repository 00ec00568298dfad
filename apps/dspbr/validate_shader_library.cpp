#include "validate_shader_library.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "dspbr/conformance/checker.h"
#include "dspbr/conformance/vector_set.h"
#include "dspbr/shader/shader_bsdf.h"
#include "report_script.h"

namespace dspbr::cli {

namespace {

// The reference's component cases whose material is that component alone (a white metal, a white
// plastic, a glass): the whole material is the component, so its case and claim hold for the
// library, which has whole materials only.
bool whole_material(const validate::BsdfCase& c) {
  static const char* kWhole[] = {"material", "metallic", "opaque_dielectric", "thin_transparent", "volumetric_transparent"};
  return std::find(std::begin(kWhole), std::end(kWhole), c.component) != std::end(kWhole);
}

// The vectors of `g` on the C++ compile, judged per group.
std::vector<validate::ConformanceGroup> vectors_on_the_library(const conformance::GenerateSettings& g) {
  std::vector<conformance::Vector> vectors = conformance::generate_vectors(g);
  std::vector<conformance::Result> results(vectors.size());
  tbb::parallel_for(std::size_t(0), vectors.size(), [&](std::size_t i) {
    const conformance::Vector& x = vectors[i];
    const shader::ShaderBsdf b(conformance::vector_material(x), conformance::vector_options(x));
    results[i] = conformance::implementation_result(x, b);
    if (x.emission) results[i].emission = b.emission(x.v);
  });
  // Per group as `dspbr conformance check` tallies them (its report's "groups").
  const conformance::Check check = conformance::check_results(vectors, results);
  std::vector<validate::ConformanceGroup> out;
  const nlohmann::ordered_json report = conformance::check_report(vectors, results, check, nlohmann::ordered_json::object(), 0);
  for (const auto& g : report["groups"])
    out.push_back({g["name"].get<std::string>(), g["vectors"].get<std::size_t>(), g["failed"].get<std::size_t>(),
                   g["worst_ratio"].get<double>(), g["worst_id"].get<std::string>()});
  return out;
}

}  // namespace

validate::OtherImplementation shader_library_checks(const validate::Catalog& reference, bool quick) {
  validate::OtherImplementation o;
  o.name = "the shader library's C++ compile (shaders/dspbr.h, float, renderer-layout tables)";
  o.catalog.luts = reference.luts;
  for (const validate::BsdfCase& c : reference.cases) {
    if (!c.material) {
      o.left_out.push_back(c.name + ": not a material");
    } else if (c.options.transmission_compensation) {
      o.left_out.push_back(c.name + ": the transmission compensation (beyond DSPBR 2025x) is not in the library");
    } else if (!whole_material(c)) {
      o.left_out.push_back(c.name + ": one lobe of a material (the library evaluates whole materials)");
    } else if (quick && c.component != "material" && c.material->roughness != 0.5) {
      // The quick run (seconds): the core components at roughness 0.5 only.
      o.left_out.push_back(c.name + ": the quick run checks the core components at roughness 0.5 only");
    } else {
      validate::BsdfCase s = c;
      s.bsdf = std::make_shared<shader::ShaderBsdf>(*c.material, c.options);
      o.catalog.cases.push_back(std::move(s));
    }
  }
  for (validate::StabilityCase& s : validate::whole_material_stability(reference)) {
    s.bsdf = std::make_shared<shader::ShaderBsdf>(*s.material, s.options);
    o.catalog.stability.push_back(std::move(s));
  }
  // In float, pdf and weight agree with eval and pdf to rounding (ShaderLibrary.SamplingMatchesPdfByChiSquare).
  o.consistency_tol = 1e-4;
  // A quarter of the full run's million samples per chi-square test (its sampling is most of the
  // section's time: 7.2 s with a million); the shader tests draw 100,000.
  o.chi2_samples_max = 250000;
  // The full run: the default set of `dspbr conformance generate` (the validation scenes' materials
  // included); the quick run: the built-in materials with 2 direction pairs each instead of 20 and
  // no albedo (the albedo quadratures cost 0.6 s whatever the directions).
  conformance::GenerateSettings g;
  if (quick) g.directions = 2, g.albedo = false;
  o.vector_set = "the vectors of dspbr conformance generate --no-scenes --directions 2 --no-albedo (the quick run's subset)";
  if (!quick) {
    try {
      g.scenes_dir = shared_path("scenes/sphere", "");
      o.vector_set = "the default vectors of dspbr conformance generate (with the validation scenes' materials)";
    } catch (const std::exception& e) {
      o.vector_set = std::string("the vectors of dspbr conformance generate --no-scenes (") + e.what() + ")";
    }
  }
  o.conformance = [g] { return vectors_on_the_library(g); };
  return o;
}

}  // namespace dspbr::cli
