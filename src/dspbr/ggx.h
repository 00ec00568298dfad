// Anisotropic GGX (GTR, gamma = 2) microfacet distribution and its height-correlated Smith
// shadowing-masking. Spec "Microfacet BSDF"; Heitz 2014 (Smith), Heitz 2018 (VNDF sampling).
// All directions are unit vectors in the local shading frame (t = +x, b = +y, n = +z).
#pragma once
#include "dspbr/vec3.h"

namespace dspbr {

// User roughness r to GGX alpha: the spec squares roughness ("perceptually linear").
inline double roughness_to_alpha(double r) { return r * r; }

// Anisotropic roughness from isotropic roughness r and anisotropy o: (r_u, r_v) = r (1, 1 - o).
struct Roughness2 { double u, v; };
inline Roughness2 anisotropic_roughness(double r, double o) { return {r, r * (1.0 - o)}; }

// D(h; a_u, a_v) = chi+(h.n) / (pi a_u a_v ((h.t/a_u)^2 + (h.b/a_v)^2 + (h.n)^2)^2).
// Requires a_u, a_v > 0.
double ggx_d(const Vec3& h, double alpha_u, double alpha_v);

// Smith Lambda for GGX: (-1 + sqrt(1 + 1/a^2)) / 2,
// 1/a^2 = ((x.t)^2 a_u^2 + (x.b)^2 a_v^2) / (x.n)^2. Returns +inf at x.n = 0 (grazing).
double smith_lambda(const Vec3& w, double alpha_u, double alpha_v);

// Smith masking G1(w, h) = chi+(w.h) / (1 + Lambda(w)) (Heitz 2014, eq. 43).
double ggx_g1(const Vec3& w, const Vec3& h, double alpha_u, double alpha_v);

// Height-correlated masking-shadowing (spec "Microfacet BSDF", Heitz 2014 eq. 99):
// G(v, l, h) = chi+(l.h) chi+(v.h) / (1 + Lambda(v) + Lambda(l)).
double ggx_g2(const Vec3& v, const Vec3& l, const Vec3& h, double alpha_u, double alpha_v);

// Visible-normal sampling (Heitz 2018, "Sampling the GGX Distribution of Visible Normals").
// v must have v.z > 0; (u1, u2) in [0,1)^2. Returns a microfacet normal h with h.z >= 0.
Vec3 ggx_sample_vndf(const Vec3& v, double alpha_u, double alpha_v, double u1, double u2);

// Density of ggx_sample_vndf over microfacet normals: D_v(h) = G1(v) max(0, v.h) D(h) / v.z.
double ggx_vndf_pdf(const Vec3& v, const Vec3& h, double alpha_u, double alpha_v);

// Single-scattering microfacet BRDF M_r = D G / (4 |v.n| |l.n|) (spec "Microfacet BSDF"),
// without Fresnel. Zero when v and l are not both above the surface.
double ggx_microfacet_brdf(const Vec3& v, const Vec3& l, double alpha_u, double alpha_v);

}  // namespace dspbr
