// The seeded mistakes (seeded_mistakes.json) over a conformance vector set: for each, the results
// file of its patched shader library (f cos, and the emission where a vector gives one), which
// `dspbr conformance check` then judges and diagnoses (tests/vulkan_shaders.cmake).
// Usage: seeded_mistakes VECTORS.json OUT_DIR  (writes OUT_DIR/NAME.json per mistake)
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "dspbr/conformance/results.h"
#include "dspbr/conformance/vector_file.h"
#include "dspbr/conformance/vector_set.h"
#include "dspbr/shader/material_mapping.h"
#include "seeded_eval.h"

namespace {

using Eval = void (*)(const float*, float*);

struct Mistake {
  const char* name;
  Eval eval;
};

void write(const std::string& path, const std::vector<dspbr::conformance::Vector>& vectors, Eval eval) {
  std::vector<dspbr::conformance::Result> results;
  std::vector<float> in(dspbr::shader::kShaderInputFloats);
  for (const dspbr::conformance::Vector& x : vectors) {
    dspbr::shader::pack_shader_inputs(dspbr::conformance::vector_material(x), dspbr::conformance::vector_options(x), x.v,
                                      x.l, in.data());
    float out[6];
    eval(in.data(), out);
    dspbr::conformance::Result r;
    r.id = x.id;
    r.f_cos = dspbr::Rgb(out[0], out[1], out[2]);
    if (x.emission) r.emission = dspbr::Rgb(out[3], out[4], out[5]);
    results.push_back(std::move(r));
  }
  std::ofstream f(path);
  f << dspbr::conformance::results_document(results).dump() << "\n";
  if (!f) throw std::runtime_error("cannot write " + path);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: seeded_mistakes VECTORS.json OUT_DIR\n");
    return 2;
  }
  const Mistake mistakes[] = {
#define SEEDED(name) {#name, &seeded_eval_##name},
#include "seeded_list.h"
#undef SEEDED
  };
  try {
    const std::vector<dspbr::conformance::Vector> vectors = dspbr::conformance::read_vectors(argv[1]);
    for (const Mistake& m : mistakes) write(std::string(argv[2]) + "/" + m.name + ".json", vectors, m.eval);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "seeded_mistakes: %s\n", e.what());
    return 2;
  }
}
