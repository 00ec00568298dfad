// The shader library's C++ compile (shaders/dspbr.h, float) over a conformance vector set: f cos,
// pdf, the albedo, emission and Dirac lobes where the vectors give them, written as a results file
// for `dspbr conformance check` (CTest shader_cpp_conformance runs both), with a summary of f cos
// and pdf per group.
// Usage: shader_cpp_conformance VECTORS.json RESULTS.json. Exit 0 when f cos and pdf pass.
#include <cstdio>
#include <exception>
#include <tbb/parallel_for.h>

#include "dspbr/conformance/vector_file.h"
#include "shader_material.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: shader_cpp_conformance VECTORS.json RESULTS.json\n");
    return 2;
  }
  try {
    const std::vector<dspbr::conformance::Vector> vectors = dspbr::conformance::read_vectors(argv[1]);
    std::vector<shader_test::Outcome> results(vectors.size());
    // Each vector alone (the albedo quadrature and the Dirac sweep are most of the time): in parallel.
    tbb::parallel_for(std::size_t(0), vectors.size(), [&](std::size_t k) { results[k] = shader_test::evaluate(vectors[k]); });
    shader_test::write_results(argv[2], vectors, results);
    return shader_test::judge(vectors, results, "c++") == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shader_cpp_conformance: %s\n", e.what());
    return 2;
  }
}
