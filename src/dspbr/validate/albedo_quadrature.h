// Deterministic directional albedo of a BSDF's non-delta part, E(v) = Integral over the sphere of
// f(v, l) |l.n| dl, by nested adaptive Gauss-Kronrod quadrature of eval() alone (gauss_kronrod.h),
// with a stated error bound: the white furnace's second estimator (furnace.h), the one with
// power where the cosine-weighted eval estimator is too noisy (glossy lobes near the horizon).
//
// Each hemisphere is integrated in polar coordinates (psi, chi) about the direction where its
// lobes peak: the mirror direction on v's side, the refracted direction (Snell's law with the
// media's eta ratio; straight through for equal media) on the other side. The polar angle is
// integrated in s = log(psi): a lobe of width alpha is a smooth step of width ~1 in s whatever
// alpha, so lobes of every roughness share one rule (the disc psi < psi_0 is a panel in psi). The
// azimuth chi runs over the part of the cone that lies in the hemisphere (closed form); the polar
// integral is split where the cone first meets the horizon (a square-root kink) and every unit of
// s (the peaks' widths). The stated error is the sum of both levels' embedded estimates.
// A BSDF with a jump on a cone elsewhere (a flake's cone BSDF, spec "Flake BSDF") names the cone:
// both levels then split where a ring enters or leaves it, so that no panel straddles the jump.
#pragma once
#include <vector>

#include "dspbr/bsdf/bsdf.h"

namespace dspbr::validate {

// Where f(v, .) jumps: on the cone of directions l with l.axis = cos_half_angle (axis unit).
struct FeatureCone {
  Vec3 axis;
  double cos_half_angle = 1;
};

struct QuadratureAlbedo {
  Rgb value;          // the non-delta part of E(v)
  double error = 0;   // stated absolute error (max over channels, summed over panels of both levels)
  long evaluations = 0;
};

// eta_ratio = eta on v's side / eta on the other side (1: the same medium, or a thin-walled
// surface). tolerance: the absolute error aimed at (each level stops at 200 panels and states
// its larger error).
QuadratureAlbedo albedo_quadrature(const Bsdf& bsdf, const Vec3& v, double eta_ratio, double tolerance,
                                   const std::vector<FeatureCone>& cones = {});

// The direction in which light from v goes through a smooth interface with eta_ratio (above):
// the refracted direction, straight through at eta_ratio = 1; under total internal reflection
// the horizon direction on the far side (where a rough lobe's transmission then peaks).
Vec3 transmission_peak(const Vec3& v, double eta_ratio);

}  // namespace dspbr::validate
