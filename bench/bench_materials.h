// The benchmarks' materials (bench_material.cpp: the reference BSDF; bench_shader.cpp: the shader
// library): the params-2025x.json subtypes at their defaults ("plastic", "metal", "glass",
// "carpaint"), a plastic with a thin film ("thin_film"), a plastic under a clearcoat
// ("coated_plastic"), a plastic with a perturbed normal as a normal map gives it ("bumped_plastic")
// and the full material with every component on ("full").
#pragma once
#include <string>

#include "dspbr/material.h"

namespace bench {

dspbr::Material material(const std::string& name);

}  // namespace bench
