// Goodness of fit of a BSDF's sample() against its pdf() (the test Mitsuba 3 and pbrt run on their
// BSDFs): a histogram of ~10^6 sampled directions over the sphere is compared with the expected
// counts N * Integral_bin pdf by Pearson's chi-square test. Bins with an expected count below 5
// are pooled into one cell; delta-lobe and failed (invalid) samples form one more cell whose
// expected count is N (1 - Integral_sphere pdf). The p-value is compared with a significance level
// corrected for the number of tests in the run (Sidak: alpha_1 = 1 - (1 - alpha)^(1/m)).
// The same pass over the samples also checks, per sample, that
//  - pdf(v, l) > 0 where a non-delta sample lands (no samples outside the pdf's support),
//  - sample.pdf equals pdf(v, l), and sample.weight equals eval(v, l) |l.n| / pdf(v, l).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dspbr/bsdf/bsdf.h"

namespace dspbr::validate {

struct Chi2Settings {
  std::size_t samples = 1000000;
  int theta_bins = 90;          // over [0, pi]; phi gets 2 * theta_bins bins over [0, 2 pi)
  int integration_order = 4;    // Gauss-Legendre nodes per cell and dimension for the expected counts
  int max_depth = 4;            // adaptive refinement levels (each splits a cell into 4)
  int max_support_depth = 8;    // levels for cells crossed by the boundary of the pdf's support (jumps to 0)
  double min_expected = 5.0;    // pooling threshold
  double significance = 0.01;   // family-wise level before the Sidak correction
  int num_tests = 1;            // m in the Sidak correction (tests in the whole run)
  double consistency_tol = 1e-5;  // relative tolerance for sample.pdf vs pdf() and weight vs f|cos|/pdf
  int consistency_stride = 1;     // check support and consistency on every k-th non-delta sample
  uint64_t seed = 1;
  uint64_t stream = 0;          // distinct per test in a run (chunks use stream * 2^20 + chunk)
  bool keep_histograms = false;  // copy observed/expected per bin into the result (figures)
};

struct Chi2Result {
  // chi-square
  double statistic = 0;
  int dof = 0;
  double p_value = 1;
  double alpha = 0;          // Sidak-corrected per-test level
  int cells = 0;             // cells used (after pooling)
  int pooled_bins = 0;       // bins merged into the pooled cell
  // support and normalisation
  std::size_t samples = 0, invalid = 0, delta = 0;
  std::size_t outside_support = 0;   // checked non-delta samples with pdf(v, l) <= 0 or not finite
  std::size_t non_finite = 0;        // samples with a non-finite direction, pdf or weight
  double pdf_integral = 0;           // Integral over the sphere of pdf(v, .) (quadrature)
  double pdf_integral_expected = 0;  // 1 - P(delta) - P(invalid), from the sample counts
  double pdf_integral_tol = 0;       // allowed |difference| (4 sigma binomial + quadrature)
  // consistency
  double max_pdf_rel_dev = 0;        // max |sample.pdf - pdf(v,l)| / pdf(v,l)
  double max_weight_rel_dev = 0;     // max |weight - f|cos|/pdf| / max(...)
  std::size_t pdf_mismatches = 0, weight_mismatches = 0;
  // verdicts
  bool chi2_passed = true, support_passed = true, integral_passed = true, consistency_passed = true;
  bool passed() const { return chi2_passed && support_passed && integral_passed && consistency_passed; }
  // Optional per-bin data [theta][phi], row-major (keep_histograms).
  int theta_bins = 0, phi_bins = 0;
  std::vector<double> observed, expected;
};

Chi2Result chi2_test(const Bsdf& bsdf, const Vec3& v, const Chi2Settings& s);

// Upper tail probability of the chi-square distribution with dof degrees of freedom.
double chi2_survival(double statistic, int dof);

// Per-test level for m tests at family-wise level alpha (Sidak).
double sidak_alpha(double alpha, int m);

}  // namespace dspbr::validate
