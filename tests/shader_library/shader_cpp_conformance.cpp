// The shader library's C++ compile (shaders/dspbr.h, float) over a conformance vector set: f cos
// and the pdf of each vector judged against its tolerance (CTest shader_cpp_conformance).
// Usage: shader_cpp_conformance VECTORS.json. Exit 0 when every supported vector passes.
#include <cstdio>
#include <exception>

#include "dspbr/conformance/vector_file.h"
#include "dspbr/conformance/vector_set.h"
#include "shader_material.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: shader_cpp_conformance VECTORS.json\n");
    return 2;
  }
  try {
    const std::vector<dspbr::conformance::Vector> vectors = dspbr::conformance::read_vectors(argv[1]);
    std::vector<shader_test::Outcome> results(vectors.size());
    for (size_t k = 0; k < vectors.size(); ++k) {
      const dspbr::conformance::Vector& x = vectors[k];
      const dspbr_shader::DspbrBsdf b = dspbr_shader::dspbr_prepare(
          shader_test::to_shader_material(dspbr::conformance::vector_material(x)), dspbr_shader::dspbr_identity_frame(),
          shader_test::to_shader_options(dspbr::conformance::vector_options(x)));
      const dspbr_shader::vec3 v(float(x.v.x), float(x.v.y), float(x.v.z)), l(float(x.l.x), float(x.l.y), float(x.l.z));
      results[k].f_cos = dspbr_shader::dspbr_eval(b, v, l) * std::abs(l.z);
      results[k].pdf = dspbr_shader::dspbr_pdf(b, v, l);
    }
    return shader_test::judge(vectors, results, "c++") == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shader_cpp_conformance: %s\n", e.what());
    return 2;
  }
}
