// dspbr.lookup: the functions of the generated lookup headers (luts/dspbr_lookup.h and
// luts/dspbr_glass_lookup.h, renderer layout, float) as vectorised numpy functions, so that a
// Python user computes exactly what a renderer including the headers computes (arguments
// broadcast like numpy's; results float32). The headers are compiled in here as generated.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

// clang-format off: the glass header uses the main one's helpers.
#include "dspbr_lookup.h"
#include "dspbr_glass_lookup.h"
// clang-format on

namespace dspbr::python {

namespace py = pybind11;

namespace {

// "name(a: ArrayLike, b: ArrayLike) -> ..." then the description: the signature line the type
// stubs are made from (module.cpp).
std::string doc(const char* name, std::initializer_list<const char*> args, const char* text) {
  std::string s = std::string(name) + "(";
  bool first = true;
  for (const char* a : args) {
    s += std::string(first ? "" : ", ") + a + ": numpy.typing.ArrayLike";
    first = false;
  }
  return s + ") -> typing.Union[numpy.typing.NDArray[numpy.float32], float]\n\n" + text;
}

}  // namespace

void bind_lookup(py::module_& m) {
  auto l = m.def_submodule("lookup",
                           "The generated renderer-layout lookups (luts/dspbr_lookup.h, dspbr_glass_lookup.h) as "
                           "vectorised numpy functions: float32, arguments broadcast (docs/luts.md)");
  // Each entry: the C function without its dspbr_ prefix, its arguments as in the header.
#define DSPBR_LOOKUP(fn, text, ...) l.def(#fn, py::vectorize(dspbr_##fn), doc(#fn, {__VA_ARGS__}, text).c_str())
  DSPBR_LOOKUP(ggx_E, "E_m(mu; r), the single-scattering GGX albedo.", "cos_theta", "roughness");
  DSPBR_LOOKUP(ggx_E_avg, "E_m,avg(r).", "roughness");
  DSPBR_LOOKUP(ggx_E_avg_missing, "1 - E_m,avg(r), to its relative precision.", "roughness");
  DSPBR_LOOKUP(fresnel_ms, "F_ms(f0, f90; E_avg), the multiple-scattering Fresnel term.", "f0", "f90", "e_avg");
  DSPBR_LOOKUP(base_E, "E(mu; r, f0), the albedo of the metal or dielectric base.", "cos_theta", "roughness", "f0");
  DSPBR_LOOKUP(base_E_avg, "E_avg(r, f0).", "roughness", "f0");
  DSPBR_LOOKUP(sheen_E, "E_b(mu; alpha_b), the main sheen's albedo.", "cos_theta", "alpha_b");
  DSPBR_LOOKUP(sheen_ash_E, "E_b(mu; alpha_b), the alternative sheen's albedo.", "cos_theta", "alpha_b");
  DSPBR_LOOKUP(ms_lobe, "M_r,ms / F_ms, the multiple-scattering lobe per unit of F_ms [1/sr].", "cos_v", "cos_l",
               "roughness");
  DSPBR_LOOKUP(diffuse_bc, "B_c / rho, the energy-conserving diffuse term per unit of albedo [1/sr].", "cos_v",
               "cos_l", "roughness", "f0");
  DSPBR_LOOKUP(sheen_layer_scale, "The main sheen's albedo scaling of the layers below.", "cos_v", "cos_l", "alpha_b",
               "rho_hat");
  DSPBR_LOOKUP(sheen_ash_layer_scale, "The alternative sheen's albedo scaling of the layers below.", "cos_v",
               "cos_l", "alpha_b", "rho_hat");
  DSPBR_LOOKUP(glass_f0, "F_0 of an interface of index ior against 1.", "ior");
  DSPBR_LOOKUP(glass_E, "E_g(mu; r, ior) of the rough dielectric interface, v outside (inside = 0) or inside (1).",
               "cos_theta", "roughness", "ior", "inside");
  DSPBR_LOOKUP(glass_E_avg, "The cosine average of glass_E.", "roughness", "ior", "inside");
  DSPBR_LOOKUP(glass_core_E, "The albedo of the white transparent core, its M_r,ms term included.", "cos_theta",
               "roughness", "ior", "inside");
  DSPBR_LOOKUP(glass_core_E_avg, "The cosine average of glass_core_E.", "roughness", "ior", "inside");
  DSPBR_LOOKUP(glass_transmission_share, "The share of the missing energy the compensation transmits.", "roughness",
               "ior", "inside");
  DSPBR_LOOKUP(glass_compensation, "The volumetric glass compensation lobe per unit of colour [1/sr].", "cos_v",
               "cos_l", "roughness", "ior", "inside", "transmission");
  DSPBR_LOOKUP(thin_glass_compensation, "The thin-walled glass compensation lobe per unit of colour [1/sr].", "cos_v",
               "cos_l", "roughness", "ior", "transmission");
#undef DSPBR_LOOKUP
}

}  // namespace dspbr::python
