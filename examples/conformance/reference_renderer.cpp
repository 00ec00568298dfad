// A stand-in "renderer" for the conformance harness: the reference BSDF of this project behind the
// harness's C interface (renderer.h). Replace this file with your renderer's eval.
#include <cmath>
#include <exception>
#include <nlohmann/json.hpp>

#include "dspbr/component.h"
#include "dspbr/conformance/vector_set.h"
#include "renderer.h"

extern "C" int renderer_eval(const char* material_json, const char* options_json, const double v[3],
                             const double l[3], double f_cos[3], double* pdf) {
  return renderer_eval_batch(material_json, options_json, 1, v, l, f_cos, pdf);  // a batch of one
}

// The batched form: the material parsed and its BSDF built once, then every direction pair.
extern "C" int renderer_eval_batch(const char* material_json, const char* options_json, int n, const double* v,
                                   const double* l, double* f_cos, double* pdf) {
  try {
    dspbr::conformance::Vector x;
    x.material = nlohmann::ordered_json::parse(material_json);
    if (options_json[0] != '\0') x.options = nlohmann::ordered_json::parse(options_json);
    const dspbr::Material m = dspbr::conformance::vector_material(x);
    const dspbr::MaterialBsdf b(m, dspbr::LutSet::builtin(), dspbr::conformance::vector_options(x), dspbr::active_components(m));
    for (int i = 0; i < n; ++i) {
      const dspbr::Vec3 vi{v[3 * i], v[3 * i + 1], v[3 * i + 2]}, li{l[3 * i], l[3 * i + 1], l[3 * i + 2]};
      const dspbr::Rgb f = b.eval(vi, li) * std::abs(li.z);
      f_cos[3 * i] = f.r, f_cos[3 * i + 1] = f.g, f_cos[3 * i + 2] = f.b;
      pdf[i] = b.pdf(vi, li);
    }
    return 0;
  } catch (const std::exception&) {
    return 1;
  }
}
