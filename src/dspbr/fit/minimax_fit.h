// Least-squares fitting with Ceres, pushed towards the minimax (smallest maximum error) fit by
// Lawson's iteratively reweighted least squares: after each solve every sample's weight is
// multiplied by its absolute residual (normalised), which concentrates the fit on the worst
// points (Lawson 1961; for linear models the weights converge to the minimax solution).
//
// Model: a functor with `template <class T> bool operator()(const T* p, T* residual) const`
// over N parameters, one residual per sample (ceres::AutoDiffCostFunction<Functor, 1, N>).
// Determinism: Ceres runs single-threaded here (its parallel evaluation sums in an order that
// depends on the thread count); the expensive exact reference values are computed beforehand.
#pragma once
#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace dspbr::fit {

struct MinimaxOptions {
  int lawson_rounds = 8;         // reweighting rounds after the plain least-squares solve
  int max_iterations = 200;      // Levenberg-Marquardt iterations per solve
  double weight_floor = 1e-3;    // weights never drop below this fraction of the mean (keeps
                                 // every sample in the fit and the normal equations regular)
  double ridge = 0;              // > 0: adds ridge * |p|^2 (Tikhonov) to the cost: keeps the
                                 // coefficients of ill-conditioned bases small (float evaluation)
};

struct MinimaxSummary {
  bool converged = false;        // last solve reported CONVERGENCE
  double max_abs_residual = 0;   // of the final parameters, over the samples
  double rms_residual = 0;
  int solves = 0;
};

namespace detail {
// Scales a sample residual by sqrt(weight); the weight is read at evaluation time.
template <class Functor, int N>
struct Weighted {
  Functor f;
  const double* weight;
  template <class T>
  bool operator()(const T* p, T* r) const {
    if (!f(p, r)) return false;
    r[0] *= T(std::sqrt(*weight));
    return true;
  }
};
// sqrt(ridge) * p[k] for all k (Tikhonov regularisation).
template <int N>
struct Ridge {
  double sqrt_ridge;
  template <class T>
  bool operator()(const T* p, T* r) const {
    for (int k = 0; k < N; ++k) r[k] = T(sqrt_ridge) * p[k];
    return true;
  }
};
}  // namespace detail

// Fits params (size N, in: starting point, out: result) to the samples.
template <int N, class Functor>
MinimaxSummary fit_minimax(const std::vector<Functor>& samples, std::array<double, N>& params,
                           const MinimaxOptions& opt = {}) {
  std::vector<double> weights(samples.size(), 1.0);
  ceres::Problem problem;
  for (size_t i = 0; i < samples.size(); ++i) {
    using W = detail::Weighted<Functor, N>;
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<W, 1, N>(new W{samples[i], &weights[i]}), nullptr,
                             params.data());
  }
  if (opt.ridge > 0)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<detail::Ridge<N>, N, N>(new detail::Ridge<N>{std::sqrt(opt.ridge)}),
                             nullptr, params.data());
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = opt.max_iterations;
  so.num_threads = 1;
  so.function_tolerance = 1e-12;
  so.parameter_tolerance = 1e-12;
  so.gradient_tolerance = 1e-14;
  so.logging_type = ceres::SILENT;
  MinimaxSummary out;
  auto residuals = [&](std::vector<double>& r) {
    r.resize(samples.size());
    for (size_t i = 0; i < samples.size(); ++i) {
      double v = 0;
      samples[i](params.data(), &v);
      r[i] = v;
    }
  };
  std::vector<double> r;
  std::array<double, N> best = params;
  double best_max = HUGE_VAL;
  for (int round = 0; round <= opt.lawson_rounds; ++round) {
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    out.converged = summary.termination_type == ceres::CONVERGENCE;
    ++out.solves;
    residuals(r);
    double mx = 0;
    for (double v : r) mx = std::max(mx, std::abs(v));
    if (std::isfinite(mx) && mx < best_max) {
      best_max = mx;
      best = params;
    }
    // Lawson update: w_i <- w_i |r_i|, normalised to mean 1, floored.
    double mean = 0;
    for (size_t i = 0; i < r.size(); ++i) mean += weights[i] * std::abs(r[i]);
    mean /= double(r.size());
    if (!(mean > 0)) break;
    for (size_t i = 0; i < r.size(); ++i) weights[i] = std::max(opt.weight_floor, weights[i] * std::abs(r[i]) / mean);
  }
  params = best;  // the round with the smallest maximum residual
  residuals(r);
  double ss = 0;
  out.max_abs_residual = 0;
  for (double v : r) {
    out.max_abs_residual = std::max(out.max_abs_residual, std::abs(v));
    ss += v * v;
  }
  out.rms_residual = std::sqrt(ss / double(std::max<size_t>(1, r.size())));
  return out;
}

}  // namespace dspbr::fit
