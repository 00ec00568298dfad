// Thin-film reflectance integrated over the spectrum in Fourier space (Belcour & Barla 2017, BB17
// sec. 4): the Airy reflectance is a Fourier series in the round-trip phase, and the spectral
// integral of each term is the Fourier transform of the colour-matching functions at a multiple
// of the optical path difference. Decisions and measured accuracy: docs/components.md.
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "dspbr/bsdf/thin_film.h"
#include "dspbr/bsdf/thin_film_optics.h"
#include "dspbr/tables/warped_table.h"

namespace dspbr {

using namespace thin_film_detail;

namespace {

// The sensitivity S_c(x) = Sum_i w_c,i exp(i x / lambda_i) of the normalized X, Y, Z weights of
// the 2 nm spectral rule (S_c(0) = 1), tabulated as its envelope E_c(x) = S_c(x) exp(-i x nu_c)
// (nu_c: the channel's mean wavenumber), which varies slowly, on x = k h. Catmull-Rom between the
// samples; |S_c(x)| < kSensitivityFloor beyond the table. The kinks of the piecewise-Gaussian CMF
// fit make S decay only like ~x^-3 (|S| ~ 1e-5 at x = 2e5 rad nm), hence the long table
// (~12500 samples per channel, built once on first use; with 64 rad nm steps the interpolation
// error reached 1e-4 in X).
constexpr double kSensitivityStep = 32.0;     // rad nm: (phase times lambda) per table step
constexpr double kSensitivityFloor = 2e-6;
constexpr double kSensitivityMaxX = 4e5;       // |S_c| < 4e-6 beyond (all three channels)
// The sensitivity from 6-node panels of 2 nm: 1 nm panels give the same FourierMatchesQuadrature
// figures (tests/test_thin_film.cpp).
constexpr double kSensitivityPanelNm = 2.0;

// One envelope sample of the three channels, real and imaginary parts.
struct EnvelopeSample {
  double re[3], im[3];
};

struct Sensitivity {
  double nu[3];                         // mean wavenumber of X, Y, Z (1/nm)
  std::vector<double> env[3][2];        // envelope samples, real and imaginary, k = 0..n-1
  // The same interleaved for the lookup, from k = -1 (the ghost sample E_c(-x) = conj(E_c(x))).
  std::vector<EnvelopeSample> samples;
  double x_end;                         // S_c(x) treated as 0 for x >= x_end
};

const Sensitivity& sensitivity() {
  static const Sensitivity s = [] {
    const SpectralRule& rule = spectral_rule_of_width(kSensitivityPanelNm);
    const std::size_t n_nodes = rule.lambda.size();
    Sensitivity t;
    for (int c = 0; c < 3; ++c) {
      double nu = 0;
      for (std::size_t i = 0; i < n_nodes; ++i) nu += rule.w_xyz[i][c] / rule.lambda[i];
      t.nu[c] = nu;
    }
    // S_c(k h) = Sum_i w_c,i z_i^k with z_i = exp(i h / lambda_i) advanced by one rotation per
    // node and step (rounding grows like k * 1e-16, below 1e-12 over the table), then
    // demodulated by exp(-i k h nu_c). Complex arithmetic written out (see airy_reflectance).
    std::vector<double> rot_re(n_nodes), rot_im(n_nodes), cur_re(n_nodes, 1.0), cur_im(n_nodes, 0.0);
    for (std::size_t i = 0; i < n_nodes; ++i) {
      rot_re[i] = std::cos(kSensitivityStep / rule.lambda[i]);
      rot_im[i] = std::sin(kSensitivityStep / rule.lambda[i]);
    }
    int last_significant = 0;
    // Samples up to kSensitivityMaxX, and 3 beyond: the Catmull-Rom support of a lookup just
    // below x_end reaches 2 samples past the last significant one (and the trim keeps 3).
    const int n_table = int(kSensitivityMaxX / kSensitivityStep) + 1, n_samples = n_table + 3;
    for (int k = 0; k < n_samples; ++k) {
      double sr[3] = {0, 0, 0}, si[3] = {0, 0, 0};
      for (std::size_t i = 0; i < n_nodes; ++i) {
        const Rgb& w = rule.w_xyz[i];
        sr[0] += w.r * cur_re[i], si[0] += w.r * cur_im[i];
        sr[1] += w.g * cur_re[i], si[1] += w.g * cur_im[i];
        sr[2] += w.b * cur_re[i], si[2] += w.b * cur_im[i];
        const double re = cur_re[i] * rot_re[i] - cur_im[i] * rot_im[i];
        cur_im[i] = cur_re[i] * rot_im[i] + cur_im[i] * rot_re[i];
        cur_re[i] = re;
      }
      double mag = 0;
      for (int c = 0; c < 3; ++c) {
        const double phase = -k * kSensitivityStep * t.nu[c];
        const double dr = std::cos(phase), di = std::sin(phase);
        t.env[c][0].push_back(sr[c] * dr - si[c] * di);
        t.env[c][1].push_back(sr[c] * di + si[c] * dr);
        mag = std::max(mag, std::hypot(sr[c], si[c]));
      }
      if (k < n_table && mag >= kSensitivityFloor) last_significant = k;
    }
    // Trimmed after the last significant sample, with margin for the Catmull-Rom support.
    for (int c = 0; c < 3; ++c)
      for (auto& part : t.env[c]) part.resize(std::min<std::size_t>(part.size(), last_significant + 4));
    t.x_end = (last_significant + 1) * kSensitivityStep;
    const std::size_t n = t.env[0][0].size();
    t.samples.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k)
      for (int c = 0; c < 3; ++c) {
        const std::size_t a = k == 0 ? 1 : k - 1;  // k = 0 holds sample -1
        t.samples[k].re[c] = t.env[c][0][a];
        t.samples[k].im[c] = k == 0 ? -t.env[c][1][a] : t.env[c][1][a];
      }
    return t;
  }();
  return s;
}

struct Complex {
  double re, im;
};

// The envelope E_c(x) for x >= 0 below x_end, the three channels at once.
void envelope_at(const Sensitivity& s, double x, Complex out[3]) {
  const double g = x / kSensitivityStep;
  const int k = int(g);
  double w[4];
  catmull_rom_weights(g - k, w);
  // Samples k - 1 .. k + 2 are samples[k .. k + 3] (samples[0] is the ghost sample -1).
  const EnvelopeSample* q = s.samples.data() + k;
  for (int c = 0; c < 3; ++c) {
    double re = 0, im = 0;
    for (int j = 0; j < 4; ++j) {
      re += w[j] * q[j].re[c];
      im += w[j] * q[j].im[c];
    }
    out[c] = {re, im};
  }
}

// The series is summed until the remaining terms are below this bound (absolute, per channel).
constexpr double kSeriesTolerance = 1e-7;
// Beyond this many terms (|r12 r23| -> 1 at grazing incidence over a strongly reflecting base, with
// a thin film whose terms stay inside the table) the per-wavelength quadrature is used instead.
// A term costs ~10 ns; the table ends after ~4e5 / P terms.
constexpr int kMaxTerms = 1024;

}  // namespace

namespace thin_film_detail {

bool try_fourier_xyz(double c1, double eta_base, double thickness_um, double eta_film, Rgb& xyz) {
  const FilmSetup f = film_setup(c1, eta_base, thickness_um, eta_film);
  // The series needs a real round-trip phase and real air|film amplitudes, i.e. a propagating wave
  // in the film (always the case for eta_film >= 1).
  if (f.phase_nm.imag() != 0.0 || f.r12[0].imag() != 0.0 || f.r12[1].imag() != 0.0) return false;
  const double P = f.phase_nm.real();
  const Sensitivity& sens = sensitivity();
  // Per polarization, with a = r12, r23 = b e^{i psi}, q = a b, theta = phi + psi:
  // |r|^2 = (a^2 + b^2 + 2 q cos theta) / (1 + q^2 + 2 q cos theta)
  //       = 1 - K (1 + 2 Sum_{m>=1} (-q)^m cos(m theta)),  K = (1 - a^2)(1 - b^2) / (1 - q^2)
  // (Poisson kernel), and the spectral mean of cos(m theta) is Re(e^{i m psi} S_c(m P)).
  double K[2], negq[2], psi_re[2], psi_im[2], tail[2];
  for (int p = 0; p < 2; ++p) {
    const double a = f.r12[p].real(), b = std::abs(f.r23[p]);
    const double q = a * b;
    K[p] = (1 - a * a) * (1 - b * b) / (1 - q * q);
    negq[p] = -q;
    psi_re[p] = b > 0 ? f.r23[p].real() / b : 1.0;
    psi_im[p] = b > 0 ? f.r23[p].imag() / b : 0.0;
    tail[p] = 2 * K[p] / (1 - std::abs(q));  // bound of the terms from m on, times |q|^m
  }
  // S_c(m P) = E_c(m P) z_c^m with z_c = e^{i P nu_c}.
  double z_re[3], z_im[3], zm_re[3] = {1, 1, 1}, zm_im[3] = {0, 0, 0};
  for (int c = 0; c < 3; ++c) {
    z_re[c] = std::cos(P * sens.nu[c]);
    z_im[c] = std::sin(P * sens.nu[c]);
  }
  double acc[2][3] = {{0, 0, 0}, {0, 0, 0}};
  double qm[2] = {1, 1};                           // (-q)^m
  double um_re[2] = {1, 1}, um_im[2] = {0, 0};     // e^{i m psi}
  for (int m = 1;; ++m) {
    const double x = m * P;
    bool done = x >= sens.x_end;  // S_c = 0 from here on
    if (!done) {
      Complex S[3];
      envelope_at(sens, x, S);
      for (int c = 0; c < 3; ++c) {
        const double r = zm_re[c] * z_re[c] - zm_im[c] * z_im[c];
        zm_im[c] = zm_re[c] * z_im[c] + zm_im[c] * z_re[c];
        zm_re[c] = r;
        S[c] = {S[c].re * zm_re[c] - S[c].im * zm_im[c], S[c].re * zm_im[c] + S[c].im * zm_re[c]};
      }
      for (int p = 0; p < 2; ++p) {
        qm[p] *= negq[p];
        const double r = um_re[p] * psi_re[p] - um_im[p] * psi_im[p];
        um_im[p] = um_re[p] * psi_im[p] + um_im[p] * psi_re[p];
        um_re[p] = r;
        for (int c = 0; c < 3; ++c) acc[p][c] += qm[p] * (um_re[p] * S[c].re - um_im[p] * S[c].im);
      }
      done = std::max(tail[0] * std::abs(qm[0] * negq[0]), tail[1] * std::abs(qm[1] * negq[1])) < kSeriesTolerance;
    }
    if (done) break;
    if (m == kMaxTerms) return false;
  }
  auto channel = [&](int c) { return 1.0 - 0.5 * (K[0] * (1 + 2 * acc[0][c]) + K[1] * (1 + 2 * acc[1][c])); };
  xyz = Rgb(channel(0), channel(1), channel(2));
  return true;
}

}  // namespace thin_film_detail

const ThinFilmSensitivity& thin_film_sensitivity() {
  static const ThinFilmSensitivity t = [] {
    const Sensitivity& s = sensitivity();
    ThinFilmSensitivity out;
    out.step = kSensitivityStep;
    out.x_end = s.x_end;
    for (int c = 0; c < 3; ++c) out.nu[c] = s.nu[c];
    for (const EnvelopeSample& e : s.samples)
      out.samples.push_back({e.re[0], e.re[1], e.re[2], e.im[0], e.im[1], e.im[2]});
    return out;
  }();
  return t;
}

}  // namespace dspbr
