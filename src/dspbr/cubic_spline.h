// Interpolating cubic spline on a uniform grid with not-a-knot end conditions (de Boor, "A
// Practical Guide to Splines", ch. IV): C2, exact on cubic polynomials, error O(h^4) up to the
// ends (the natural end condition is O(h^2) there). Stored as the cubic of each cell, so that a
// lookup is one Horner evaluation.
#pragma once
#include <vector>

namespace dspbr {

// Samples y_0 .. y_n (n >= 3 cells) at the grid points 0 .. n: the spline's cubic on each cell i
// in the fraction f in [0, 1] of the cell, as c[4 i .. 4 i + 3] = (a, b, c, d) with
// value = ((a f + b) f + c) f + d (d = y_i).
std::vector<double> not_a_knot_cubics(const std::vector<double>& y);

// The cubic of cell i of not_a_knot_cubics' output at fraction f.
inline double cubic_at(const double* c, double f) { return ((c[0] * f + c[1]) * f + c[2]) * f + c[3]; }

}  // namespace dspbr
