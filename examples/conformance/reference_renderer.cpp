// A stand-in "renderer" for the conformance harness: the reference BSDF of this project behind the
// harness's C interface (renderer.h). Replace this file with your renderer's eval.
#include <cmath>
#include <exception>
#include <nlohmann/json.hpp>

#include "dspbr/conformance/vector_set.h"
#include "renderer.h"

extern "C" int renderer_eval(const char* material_json, const char* options_json, const double v[3],
                             const double l[3], double f_cos[3], double* pdf) {
  try {
    dspbr::conformance::Vector x;
    x.material = nlohmann::ordered_json::parse(material_json);
    if (options_json[0] != '\0') x.options = nlohmann::ordered_json::parse(options_json);
    x.v = {v[0], v[1], v[2]};
    x.l = {l[0], l[1], l[2]};
    const dspbr::conformance::Evaluation e = dspbr::conformance::evaluate(x, dspbr::LutSet::builtin());
    f_cos[0] = e.f_cos.r, f_cos[1] = e.f_cos.g, f_cos[2] = e.f_cos.b;
    *pdf = e.pdf;
    return 0;
  } catch (const std::exception&) {
    return 1;
  }
}
