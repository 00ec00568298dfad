// Deterministic quadrature of the rough-glass albedo E_g(mu; r, ior) (lut/albedo.h glass_E) in
// the microfacet domain, the Quad integrator's form for the Glass tables. With h at polar angle
// theta_h and azimuth phi, D(h) (h.n) dh = du dphi / (2 pi) for the GGX CDF variable
// u = tan^2 / (alpha^2 + tan^2) (as in validate/lut_reference.h), so
//   E_g = Integral (v.h) / (mu h.n) [F_d G2(v, l_r) + (1 - F_d) G2(v, l_t)] du dphi / (2 pi)
// (dl = 4 (v.h) dh for reflection, Walter et al. 2007's Jacobian for refraction with the spec's
// eta_o^2; the eta factors cancel). For fixed theta_h every condition that switches a term on or
// off is a threshold on v.h, which is linear in cos(phi): v.h > 0, the reflection above the
// horizon (v.h > mu / (2 h.n)), total internal reflection (v.h < sqrt(1 - 1/eta^2)) and the
// refraction below the horizon (a monotone condition on v.h, its threshold found by bisection).
// The azimuth is split at those thresholds and each piece integrated with the smoothstep
// substitution (square-root ends), so the azimuthal integral has no kink inside a piece; u = 1 - w^2
// removes the 1 / sqrt(1 - u) of 1 / (h.n), and w is integrated adaptively: a panel is accepted when
// its 8- and 16-node Gauss-Legendre values (both directions) agree within its share of the target.
// The error estimate is the sum over the panels of |I_16 - I_8|.
#pragma once
#include "dspbr/lut/albedo.h"

namespace dspbr {

// E_g with eta_i on v's side and eta_o on the other (ior >= 1 either way), Schlick F_0 = f0,
// alpha > 0; at eta_i = eta_o the limit eta -> 1+ of the rough M_t (glass_E). target: total error
// aimed at (> 0).
Estimate glass_albedo_quadrature(double mu, double alpha, double f0, double eta_i, double eta_o, double target);

}  // namespace dspbr
