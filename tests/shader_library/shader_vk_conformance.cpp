// The shader library on a Vulkan device (Mesa's lavapipe without a GPU) over a conformance vector
// set: the kernel (conformance.comp for GLSL, conformance.hlsl for HLSL, both in texture mode) runs
// every vector in one dispatch, and f cos and the pdf are judged against each vector's tolerance
// (CTest shader_glsl_conformance, shader_hlsl_conformance).
//   shader_vk_conformance KERNEL.spv VECTORS.json LUT_DIR LABEL [ID_PREFIXES]
// (ID_PREFIXES: comma-separated; only the vectors whose id starts with one of them are run.)
// Exit 0: every supported vector passes; 1: a failure; 2: bad arguments or a Vulkan error; 77: no
// Vulkan device (CTest reports the test skipped, never passed).
#include <cstdio>
#include <exception>
#include <sstream>
#include <string>

#include "dspbr/conformance/vector_file.h"
#include "shader_material.h"
#include "vk_compute.h"

int main(int argc, char** argv) {
  if (argc != 5 && argc != 6) {
    std::fprintf(stderr, "usage: shader_vk_conformance KERNEL.spv VECTORS.json LUT_DIR LABEL [ID_PREFIXES]\n");
    return 2;
  }
  try {
    std::vector<dspbr::conformance::Vector> vectors = dspbr::conformance::read_vectors(argv[2]);
    if (argc == 6) {
      std::vector<std::string> prefixes;
      std::stringstream in(argv[5]);
      for (std::string p; std::getline(in, p, ',');) prefixes.push_back(p);
      std::vector<dspbr::conformance::Vector> kept;
      for (auto& x : vectors)
        for (const std::string& p : prefixes)
          if (x.id.compare(0, p.size(), p) == 0) {
            kept.push_back(std::move(x));
            break;
          }
      if (kept.empty()) throw std::invalid_argument(std::string("no vector id starts with one of ") + argv[5]);
      vectors = std::move(kept);
    }
    std::vector<float> records(vectors.size() * shader_test::kRecordFloats);
    for (size_t k = 0; k < vectors.size(); ++k) shader_test::pack_record(vectors[k], &records[k * shader_test::kRecordFloats]);
    vk_compute::Device device("dspbr shader conformance");
    if (!device.has_device()) {
      std::printf("no Vulkan device: skipped\n");
      return 77;
    }
    std::printf("%s on %s\n", argv[4], device.device_name().c_str());
    const std::vector<uint32_t> spirv = vk_compute::read_spirv(argv[1]);
    const std::vector<vk_compute::TableImage> textures = vk_compute::read_lookup_textures(argv[3], false);
    const uint32_t count = uint32_t(vectors.size());
    vk_compute::Job job;
    job.spirv = &spirv;
    job.input = records.data();
    job.input_bytes = records.size() * sizeof(float);
    job.output_floats = size_t(count) * 4;
    job.textures = &textures;
    job.texture_binding = 2;
    job.push = &count;
    job.push_bytes = sizeof count;
    job.groups[0] = (count + 63) / 64;
    const std::vector<float> out = device.run(job);
    std::vector<shader_test::Outcome> results(vectors.size());
    for (size_t k = 0; k < vectors.size(); ++k)
      results[k] = {dspbr_shader::vec3(out[4 * k], out[4 * k + 1], out[4 * k + 2]), out[4 * k + 3]};
    return shader_test::judge(vectors, results, argv[4]) == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shader_vk_conformance: %s\n", e.what());
    return 2;
  }
}
