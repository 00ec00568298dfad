// The shader library on a Vulkan device (Mesa's lavapipe without a GPU) over a conformance vector
// set: the kernel (conformance.comp for GLSL, conformance.hlsl for HLSL, both in texture mode) runs
// every vector in one dispatch (f cos, pdf, albedo where the vector gives one, emission), f cos and
// the pdf are judged per group, and --results writes the results file for `dspbr conformance
// check` (CTest shader_glsl_conformance, shader_hlsl_conformance run both).
//   shader_vk_conformance KERNEL.spv VECTORS.json LUT_DIR LABEL [--results FILE] [--ids PREFIXES]
//                         [--no-albedo]
// (PREFIXES: comma-separated; only the vectors whose id starts with one of them are run;
// --no-albedo: f cos, pdf and emission alone.)
// Exit 0: every supported vector passes; 1: a failure; 2: bad arguments or a Vulkan error; 77: no
// Vulkan device (CTest reports the test skipped, never passed).
#include <cstdio>
#include <exception>
#include <sstream>
#include <string>

#include "dspbr/conformance/vector_file.h"
#include "shader_material.h"
#include "vk_queries.h"

int main(int argc, char** argv) {
  std::string results_path, ids;
  bool usage = argc < 5, albedo = true;
  for (int i = 5; i < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--no-albedo") albedo = false, --i;
    else if (i + 1 >= argc || (flag != "--results" && flag != "--ids")) usage = true;
    else (flag == "--results" ? results_path : ids) = argv[i + 1];
  }
  if (usage) {
    std::fprintf(stderr, "usage: shader_vk_conformance KERNEL.spv VECTORS.json LUT_DIR LABEL [--results FILE] [--ids PREFIXES] [--no-albedo]\n");
    return 2;
  }
  try {
    std::vector<dspbr::conformance::Vector> vectors = dspbr::conformance::read_vectors(argv[2]);
    if (!ids.empty()) {
      std::vector<std::string> prefixes;
      std::stringstream in(ids);
      for (std::string p; std::getline(in, p, ',');) prefixes.push_back(p);
      std::vector<dspbr::conformance::Vector> kept;
      for (auto& x : vectors)
        for (const std::string& p : prefixes)
          if (x.id.compare(0, p.size(), p) == 0) {
            kept.push_back(std::move(x));
            break;
          }
      if (kept.empty()) throw std::invalid_argument("no vector id starts with one of " + ids);
      vectors = std::move(kept);
    }
    shader_test::DeviceKernel kernel("dspbr shader conformance");
    if (!kernel.open(argv[1], argv[3], argv[4])) return 77;
    // Three dispatches (kernel_common.glsl says why): f cos, pdf and emission of every vector; one
    // cos-theta node of the albedo per invocation; one lobe choice per invocation for its Dirac lobes.
    auto dispatch = [&](const std::vector<const dspbr::conformance::Vector*>& xs, uint32_t mode, uint32_t per, size_t floats) {
      std::vector<float> records(xs.size() * shader_test::kRecordFloats);
      for (std::size_t k = 0; k < xs.size(); ++k) shader_test::pack_record(*xs[k], &records[k * shader_test::kRecordFloats]);
      const uint32_t push[2] = {uint32_t(xs.size()) * per, mode};
      return xs.empty() ? std::vector<float>() : kernel.run(records, push[0], floats, push, sizeof push);
    };
    std::vector<const dspbr::conformance::Vector*> all, with_albedo;
    for (const auto& x : vectors) {
      all.push_back(&x);
      if (x.albedo && albedo) with_albedo.push_back(&x);
    }
    const uint32_t nodes = uint32_t(shader_test::kAlbedoNodes);
    const std::vector<float> out = dispatch(all, 0, 1, shader_test::kResultFloats);
    const uint32_t choices = uint32_t(shader_test::kDeltaChoices);
    const std::vector<float> node_sums = dispatch(with_albedo, 1, nodes, 3), samples = dispatch(with_albedo, 2, choices, 7);
    std::vector<shader_test::Outcome> results(vectors.size());
    for (std::size_t k = 0, a = 0; k < vectors.size(); ++k) {
      const bool has = vectors[k].albedo && albedo;
      results[k] = shader_test::outcome_from_device(vectors[k], &out[k * shader_test::kResultFloats],
                                                    has ? &node_sums[a * nodes * 3] : nullptr,
                                                    has ? &samples[a * choices * 7] : nullptr);
      a += has ? 1 : 0;
    }
    if (!results_path.empty()) shader_test::write_results(results_path, vectors, results);
    return shader_test::judge(vectors, results, argv[4]) == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shader_vk_conformance: %s\n", e.what());
    return 2;
  }
}
