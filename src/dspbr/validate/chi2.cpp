#include "dspbr/validate/chi2.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <functional>
#include <numeric>

#include "dspbr/constants.h"
#include "dspbr/quadrature.h"
#include "dspbr/rng.h"

namespace dspbr::validate {

namespace {
constexpr std::size_t kChunk = 1u << 14;  // samples per independent RNG stream
// Points per bin edge for the support-boundary test (section 2): a convex part of the support of
// radius R that enters a bin between two edge points spaced d apart reaches in at most d^2 / (8 R);
// with 8 points on the 2.8 deg edge of a 64-bin run and the 7 deg flake cone (d = 0.35 deg), such
// a missed sliver holds ~3e-6 of the cone's mass (3 counts in 10^6, below the Poisson noise).
// More points cost pdf evaluations on every bin of every run.
constexpr int kBinEdgePoints = 8;

bool finite(const Rgb& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

struct ChunkStats {
  std::vector<uint32_t> hist;
  std::size_t invalid = 0, delta = 0, outside = 0, non_finite = 0, pdf_mis = 0, w_mis = 0;
  double max_pdf_dev = 0, max_w_dev = 0;
};
}  // namespace

double chi2_survival(double statistic, int dof) {
  if (dof <= 0) return 1.0;
  if (!(statistic > 0)) return 1.0;
  return boost::math::gamma_q(0.5 * dof, 0.5 * statistic);
}

double sidak_alpha(double alpha, int m) { return 1.0 - std::pow(1.0 - alpha, 1.0 / std::max(1, m)); }

Chi2Result chi2_test(const Bsdf& bsdf, const Vec3& v, const Chi2Settings& s) {
  const int nt = s.theta_bins, np = 2 * s.theta_bins;
  const std::size_t nbins = std::size_t(nt) * np;
  const double dtheta = kPi / nt, dphi = 2 * kPi / np;
  Chi2Result r;
  r.samples = s.samples;
  r.theta_bins = nt;
  r.phi_bins = np;

  // 1. Samples, in fixed chunks with one RNG stream each (thread-count independent).
  const std::size_t nchunks = (s.samples + kChunk - 1) / kChunk;
  std::vector<ChunkStats> chunks(nchunks);
  tbb::parallel_for(std::size_t(0), nchunks, [&](std::size_t c) {
    ChunkStats& st = chunks[c];
    st.hist.assign(nbins, 0);
    Pcg32 rng(s.seed, (s.stream << 20) + c);
    const std::size_t begin = c * kChunk, end = std::min(s.samples, begin + kChunk);
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3 u{rng.next_double(), rng.next_double(), rng.next_double()};
      const BsdfSample smp = bsdf.sample(v, u);
      if (!smp.valid) { ++st.invalid; continue; }
      const Vec3& l = smp.l;
      if (!std::isfinite(l.x) || !std::isfinite(l.y) || !std::isfinite(l.z) || !finite(smp.weight) ||
          !std::isfinite(smp.pdf)) {
        ++st.non_finite;
        continue;
      }
      if (smp.flags & kLobeDelta) { ++st.delta; continue; }
      // Bin of the direction (clamped: round-off may put z slightly outside [-1, 1]).
      const double z = std::clamp(l.z, -1.0, 1.0);
      const int ti = std::min(nt - 1, int(std::acos(z) / dtheta));
      double phi = std::atan2(l.y, l.x);
      if (phi < 0) phi += 2 * kPi;
      const int pi = std::min(np - 1, int(phi / dphi));
      ++st.hist[std::size_t(ti) * np + pi];
      // Support and consistency (on every consistency_stride-th sample: the pdf and eval calls
      // cost as much as the sample itself).
      if (s.consistency_stride > 1 && i % std::size_t(s.consistency_stride) != 0) continue;
      const double p = bsdf.pdf(v, l);
      if (!(p > 0) || !std::isfinite(p)) { ++st.outside; continue; }
      const double pdev = std::abs(smp.pdf - p) / p;
      st.max_pdf_dev = std::max(st.max_pdf_dev, pdev);
      if (!(pdev <= s.consistency_tol)) ++st.pdf_mis;
      const Rgb expect = bsdf.eval(v, l) * (std::abs(l.z) / p);
      double wdev = 0;
      for (int ch = 0; ch < 3; ++ch) {
        const double m = std::max(std::abs(expect[ch]), std::abs(smp.weight[ch]));
        if (m > 0) wdev = std::max(wdev, std::abs(expect[ch] - smp.weight[ch]) / m);
      }
      st.max_w_dev = std::max(st.max_w_dev, wdev);
      if (!(wdev <= s.consistency_tol)) ++st.w_mis;
    }
  });
  std::vector<double> observed(nbins, 0.0);
  for (const ChunkStats& st : chunks) {  // fixed order
    for (std::size_t b = 0; b < nbins; ++b) observed[b] += st.hist[b];
    r.invalid += st.invalid;
    r.delta += st.delta;
    r.outside_support += st.outside;
    r.non_finite += st.non_finite;
    r.pdf_mismatches += st.pdf_mis;
    r.weight_mismatches += st.w_mis;
    r.max_pdf_rel_dev = std::max(r.max_pdf_rel_dev, st.max_pdf_dev);
    r.max_weight_rel_dev = std::max(r.max_weight_rel_dev, st.max_w_dev);
  }
  chunks.clear();

  // 2. Expected counts: adaptive Gauss-Legendre over each bin of pdf(v, l) sin(theta) dtheta dphi.
  //    A cell's rule is compared with the sum of the same rule on its four quarters; cells where they
  //    differ by more than the tolerance are split again (up to max_depth levels), so narrow lobes
  //    and kinks inside a bin are resolved. Tolerance per cell: a tenth of the Poisson standard
  //    deviation of the cell's count, sqrt(N I) / 10 (so quadrature error stays well below the noise
  //    the test is sensitive to), or 0.02 expected counts scaled by the cell's share of its bin.
  //    A density with a jump to zero (a top-hat such as the flake cone, or a horizon cut) defeats
  //    that comparison: the rule converges only linearly at the jump, and a part of the support that
  //    falls between the nodes of both the cell and its quarters is missed entirely (coarse = fine =
  //    0). So a cell whose support boundary passes through it (some of its nodes or of the points
  //    on its edges have pdf > 0 and some pdf = 0) is always split, down to max_support_depth.
  const QuadratureRule rule = gauss_legendre(s.integration_order);
  struct Cell {
    double sum = 0;
    bool pos = false, zero = false;  // saw pdf > 0 / pdf = 0 at a node
    double max_p = 0;                // largest pdf seen at a node
  };
  auto density = [&](double theta, double phi) {
    const double st = std::sin(theta);
    const double p = bsdf.pdf(v, Vec3{st * std::cos(phi), st * std::sin(phi), std::cos(theta)});
    // Non-finite or negative densities are the stability check's business; count them as 0.
    return std::isfinite(p) && p > 0 ? p : 0.0;
  };
  auto gl_cell = [&](double t0, double t1, double p0, double p1) {
    Cell c;
    for (std::size_t a = 0; a < rule.x.size(); ++a) {
      const double theta = t0 + (0.5 + 0.5 * rule.x[a]) * (t1 - t0);
      double acc = 0;
      for (std::size_t b = 0; b < rule.x.size(); ++b) {
        const double p = density(theta, p0 + (0.5 + 0.5 * rule.x[b]) * (p1 - p0));
        (p > 0 ? c.pos : c.zero) = true;
        c.max_p = std::max(c.max_p, p);
        acc += 0.5 * rule.w[b] * p;
      }
      c.sum += 0.5 * rule.w[a] * std::sin(theta) * acc;
    }
    c.sum *= (t1 - t0) * (p1 - p0);
    return c;
  };
  // Support seen on the cell's edges (k points per edge): a connected part of the support that
  // enters the cell crosses its boundary. The points are inset by 1e-7 of the cell size so that a
  // bin edge lying exactly on the horizon (theta = pi/2) is not read as the support's boundary.
  auto edge_support = [&](double t0, double t1, double p0, double p1, int k, Cell& c) {
    const double et = 1e-7 * (t1 - t0), ep = 1e-7 * (p1 - p0);
    for (int i = 0; i <= k && !(c.pos && c.zero); ++i) {
      const double ft = double(i) / k;
      const double theta = t0 + et + ft * (t1 - t0 - 2 * et), phi = p0 + ep + ft * (p1 - p0 - 2 * ep);
      for (double p : {density(theta, p0 + ep), density(theta, p1 - ep), density(t0 + et, phi), density(t1 - et, phi)}) {
        (p > 0 ? c.pos : c.zero) = true;
        c.max_p = std::max(c.max_p, p);
      }
    }
  };
  const double n_samples = double(std::max<std::size_t>(1, s.samples));
  const double count_tol = 0.02 / n_samples;
  const int support_depth = std::max(s.max_depth, s.max_support_depth);
  std::function<double(double, double, double, double, const Cell&, int, double)> adaptive =
      [&](double t0, double t1, double p0, double p1, const Cell& coarse, int depth, double share) -> double {
    const double tm = 0.5 * (t0 + t1), pm = 0.5 * (p0 + p1);
    const Cell q[4] = {gl_cell(t0, tm, p0, pm), gl_cell(t0, tm, pm, p1), gl_cell(tm, t1, p0, pm),
                       gl_cell(tm, t1, pm, p1)};
    const double fine = q[0].sum + q[1].sum + q[2].sum + q[3].sum;
    const double noise_tol = 0.1 * std::sqrt(std::abs(fine) / n_samples);
    const double tol = std::max(noise_tol, count_tol * share);
    const bool converged = std::abs(fine - coarse.sum) <= tol;
    // Across a jump the rule may count the cell's mass on either side wrongly: the error is bounded
    // by max pdf x solid angle of the cell; a boundary cell whose bound is below the tolerance (a
    // jump where the density is small, e.g. a lobe's grazing guard near the horizon) is left alone.
    const double bound = coarse.max_p * (std::cos(t0) - std::cos(t1)) * (p1 - p0);
    const bool boundary = coarse.pos && coarse.zero && bound > tol;
    const int used = s.max_depth - depth;  // levels already split
    if ((converged || depth <= 0) && !(boundary && used < support_depth)) return fine;
    double sum = 0;
    const double ts[3] = {t0, tm, t1}, ps[3] = {p0, pm, p1};
    for (int k = 0; k < 4; ++k) {
      Cell c = q[k];
      const double a0 = ts[k / 2], a1 = ts[k / 2 + 1], b0 = ps[k % 2], b1 = ps[k % 2 + 1];
      if (!(c.pos && c.zero) && (c.pos || coarse.pos)) edge_support(a0, a1, b0, b1, s.integration_order, c);
      sum += adaptive(a0, a1, b0, b1, c, depth - 1, share / 4);
    }
    return sum;
  };
  std::vector<double> integral(nbins, 0.0);
  tbb::parallel_for(0, nt, [&](int ti) {
    for (int pi = 0; pi < np; ++pi) {
      const double t0 = ti * dtheta, t1 = t0 + dtheta, p0 = pi * dphi, p1 = p0 + dphi;
      Cell c = gl_cell(t0, t1, p0, p1);
      edge_support(t0, t1, p0, p1, kBinEdgePoints, c);
      integral[std::size_t(ti) * np + pi] = adaptive(t0, t1, p0, p1, c, s.max_depth, 1.0);
    }
  });
  r.pdf_integral = 0;
  for (double x : integral) r.pdf_integral += x;  // fixed order

  // 3. The delta/invalid cell and the normalisation check.
  const double n = double(s.samples);
  const double p_other = double(r.delta + r.invalid + r.non_finite) / n;
  r.pdf_integral_expected = 1.0 - p_other;
  // 4 binomial sigmas of the sampled fraction + 2e-3 for the quadrature of the pdf.
  r.pdf_integral_tol = 4.0 * std::sqrt(std::max(p_other * (1 - p_other), 1.0 / n) / n) + 2e-3;
  r.integral_passed = std::abs(r.pdf_integral - r.pdf_integral_expected) <= r.pdf_integral_tol;

  std::vector<double> exp_cells(nbins + 1), obs_cells(nbins + 1);
  for (std::size_t b = 0; b < nbins; ++b) {
    exp_cells[b] = n * integral[b];
    obs_cells[b] = observed[b];
  }
  exp_cells[nbins] = std::max(0.0, n * (1.0 - r.pdf_integral));
  obs_cells[nbins] = double(r.delta + r.invalid + r.non_finite);

  // 4. Pool the cells with a small expected count (ascending order), then Pearson's statistic.
  std::vector<std::size_t> order(nbins + 1);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return exp_cells[a] < exp_cells[b]; });
  double pool_e = 0, pool_o = 0, stat = 0;
  int cells = 0;
  for (std::size_t idx : order) {
    const double e = exp_cells[idx], o = obs_cells[idx];
    if (e < s.min_expected) {
      pool_e += e;
      pool_o += o;
      ++r.pooled_bins;
    } else {
      stat += (o - e) * (o - e) / e;
      ++cells;
    }
  }
  if (pool_e > 0) {
    stat += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
    ++cells;
  } else if (pool_o > 0) {
    stat = std::numeric_limits<double>::infinity();  // samples where the pdf integrates to 0
    ++cells;
  }
  r.statistic = stat;
  r.cells = cells;
  r.dof = cells - 1;
  r.p_value = chi2_survival(stat, r.dof);
  if (std::isinf(stat)) r.p_value = 0;
  r.alpha = sidak_alpha(s.significance, s.num_tests);
  r.chi2_passed = r.p_value >= r.alpha;
  r.support_passed = r.outside_support == 0 && r.non_finite == 0;
  r.consistency_passed = r.pdf_mismatches == 0 && r.weight_mismatches == 0;
  if (s.keep_histograms) {
    r.observed = observed;
    r.expected.resize(nbins);
    for (std::size_t b = 0; b < nbins; ++b) r.expected[b] = exp_cells[b];
  }
  return r;
}

}  // namespace dspbr::validate
