// Shading frames of the material (spec "Tangent Space").
//
// The caller's local frame is the unperturbed surface: tangent t' = +x (u axis of the texture
// coordinates), bitangent = +y, normal = +z. The material's `normal` (normal map) replaces the
// normal; t' is made orthogonal to it (Gram-Schmidt) and then rotated by beta = 2 pi b
// (b = anisotropyRotation) with the spec's formula
//     t = t' cos(beta) - (n x t') sin(beta),   b = n x t.
// NOTE: the spec's parameter table calls this a counter-clockwise rotation; the formula turns the
// tangent clockwise seen from above the surface (towards -y for small beta: t = (cos, -sin, 0) for
// n = +z). We follow the formula (decision recorded in docs/bsdf.md, test
// ShadingFrame.RotationFollowsTheFormula).
#pragma once
#include "dspbr/frame.h"
#include "dspbr/material.h"

namespace dspbr {

// t = t' cos(beta) - (n x t') sin(beta); n and t' unit and orthogonal.
Vec3 rotate_tangent(const Vec3& n, const Vec3& t_prime, double beta);

// Unit normal from a material normal field: normalized; a zero or non-finite vector gives +z.
Vec3 material_normal(const Vec3& n);

// Frame of the core BSDF: normal = material_normal(m.normal), tangent = +x projected and rotated
// by 2 pi m.anisotropyRotation.
Frame core_frame(const Material& m);

// Frame of the clearcoat: normal = material_normal(m.clearcoatNormal), tangent = +x projected
// (the coating is isotropic, its tangent does not matter).
Frame clearcoat_frame(const Material& m);

}  // namespace dspbr
