// The benchmarks' materials (bench_material.cpp: the reference BSDF; bench_shader.cpp: the shader
// library): the params-2025x.json subtypes at their defaults ("plastic", "metal", "glass",
// "carpaint"), a plastic with a thin film ("thin_film"), a plastic under a clearcoat
// ("coated_plastic"), a plastic with a perturbed normal as a normal map gives it ("bumped_plastic")
// and the full material with every component on ("full"); and the shading points their hits are
// at.
#pragma once
#include <string>
#include <vector>

#include "dspbr/material.h"
#include "dspbr/vec3.h"

namespace bench {

dspbr::Material material(const std::string& name);

// The benchmarks' 1024 shading points in a 1 m cube around the object's origin (object space, m)
// are these draws in [0, 1)^3 minus 0.5 (in each benchmark's precision), from a generator of their
// own (the benchmarks' directions stay those of their earlier runs). The flakes depend on the
// point: a car paint's flake, and whether one covers the point.
const std::vector<dspbr::Vec3>& shading_point_draws();

}  // namespace bench
