#include "dspbr/bsdf/thin_film.h"

#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <vector>

#include "dspbr/bsdf/thin_film_optics.h"
#include "dspbr/constants.h"
#include "dspbr/quadrature.h"

namespace dspbr {

using namespace thin_film_detail;

namespace {

using cplx = std::complex<double>;

// Spectral range of the CIE 1931 tables (nm); the fitted CMFs are < 1e-3 outside it.
constexpr double kLambdaMin = 360.0, kLambdaMax = 830.0;
// Composite Gauss-Legendre with 6 nodes per panel. The panel width is chosen per call from a
// ladder of precomputed rules (16, 8, ..., 1/64 nm): the coarsest one on which the Airy reflectance
// is resolved, where a 6-node rule is accurate to ~1e-9. The Airy phase must turn by at most
// kMaxPanelPhase times the width of its resonances, 1 - |r12 r23| (a legal film at moderate angles,
// d <= 1 um and eta_film <= 2.5, needs at most 8 nm; grazing incidence needs the finer rules, and
// beyond 1/64 nm accuracy degrades as |r12 r23| -> 1). Panel edges also sit on the kinks of the
// piecewise-Gaussian CMF fit. The Fourier-space sensitivity uses the 2 nm rule.
constexpr double kPanelWidthsNm[] = {16.0, 8.0, 4.0, 2.0, 1.0, 0.5, 0.25, 0.125, 1.0 / 16, 1.0 / 32, 1.0 / 64};
constexpr int kRuleLevels = 11;
constexpr double kMaxPanelPhase = 2.0;
constexpr int kNodesPerPanel = 6;

// cos of the refracted angle for sin^2 = s2 (complex when s2 > 1: evanescent wave). The +0
// imaginary part selects the branch Im(cos) >= 0, i.e. a field decaying away from the interface.
cplx refracted_cos(double s2) { return std::sqrt(cplx(1.0 - s2, 0.0)); }

// Fresnel amplitude coefficients from medium i into medium j (Born & Wolf sign convention):
// r_s = (n_i c_i - n_j c_j) / (n_i c_i + n_j c_j), r_p = (n_j c_i - n_i c_j) / (n_j c_i + n_i c_j).
cplx fresnel_rs(double ni, cplx ci, double nj, cplx cj) { return (ni * ci - nj * cj) / (ni * ci + nj * cj); }
cplx fresnel_rp(double ni, cplx ci, double nj, cplx cj) { return (nj * ci - ni * cj) / (nj * ci + ni * cj); }

}  // namespace

namespace thin_film_detail {

FilmSetup film_setup(double c1, double eta_base, double thickness_um, double eta_film) {
  const double s2_1 = 1.0 - c1 * c1;
  const double s2_2 = s2_1 / (eta_film * eta_film), s2_3 = s2_1 / (eta_base * eta_base);
  if (s2_2 <= 1.0 && s2_3 <= 1.0) {
    // Propagating waves in the film and the base: the same amplitudes in real arithmetic (the
    // complex division's scaling is not needed; equal to rounding).
    const double c2 = std::sqrt(1.0 - s2_2), c3 = std::sqrt(1.0 - s2_3);
    FilmSetup f;
    f.r12[0] = (c1 - eta_film * c2) / (c1 + eta_film * c2);
    f.r12[1] = (eta_film * c1 - c2) / (eta_film * c1 + c2);
    f.r23[0] = (eta_film * c2 - eta_base * c3) / (eta_film * c2 + eta_base * c3);
    f.r23[1] = (eta_base * c2 - eta_film * c3) / (eta_base * c2 + eta_film * c3);
    f.phase_nm = 4.0 * kPi * eta_film * (thickness_um * 1000.0) * c2;
    return f;
  }
  const cplx c2 = refracted_cos(s2_1 / (eta_film * eta_film));  // Snell: sin2 = sin1 / eta_film
  const cplx c3 = refracted_cos(s2_1 / (eta_base * eta_base));  // Snell: sin3 = sin1 / eta_base
  FilmSetup f;
  f.r12[0] = fresnel_rs(1.0, c1, eta_film, c2);
  f.r12[1] = fresnel_rp(1.0, c1, eta_film, c2);
  f.r23[0] = fresnel_rs(eta_film, c2, eta_base, c3);
  f.r23[1] = fresnel_rp(eta_film, c2, eta_base, c3);
  // BB17 eq. 3: phase difference of one round trip, 2 k eta_2 d cos(theta_2), k = 2 pi / lambda.
  f.phase_nm = 4.0 * kPi * eta_film * (thickness_um * 1000.0) * c2;
  return f;
}

// Airy summation of all inter-reflections (BB17 eq. 2): r = (r12 + r23 e^{i phi}) / (1 + r12 r23 e^{i phi}),
// R = (|r_s|^2 + |r_p|^2) / 2. |r12 r23 e^{i phi}| < 1 for c1 > 0, so the denominator is never 0.
double airy_reflectance(const FilmSetup& f, double lambda_nm) {
  // e^{i phi}, phi = phase_nm / lambda (complex when the field is evanescent in the film).
  const double pr = f.phase_nm.real() / lambda_nm, pi = f.phase_nm.imag() / lambda_nm;
  const double decay = std::exp(-pi);
  const double er = decay * std::cos(pr), ei = decay * std::sin(pr);
  double sum = 0;
  for (int p = 0; p < 2; ++p) {
    // Complex products written out: std::complex's operator* carries inf/NaN recovery code
    // (Annex G) that dominates the cost here; no operand can be inf or NaN.
    const double ar = f.r23[p].real() * er - f.r23[p].imag() * ei;  // a = r23 e^{i phi}
    const double ai = f.r23[p].real() * ei + f.r23[p].imag() * er;
    const double nr = f.r12[p].real() + ar, ni = f.r12[p].imag() + ai;  // r12 + a
    const double dr = 1.0 + f.r12[p].real() * ar - f.r12[p].imag() * ai;  // 1 + r12 a
    const double di = f.r12[p].real() * ai + f.r12[p].imag() * ar;
    sum += (nr * nr + ni * ni) / (dr * dr + di * di);
  }
  // Clamp rounding only (|R - clamp| < 1e-15): energy conservation bounds R to [0, 1].
  return std::clamp(0.5 * sum, 0.0, 1.0);
}

}  // namespace thin_film_detail

namespace {

// Half-Gaussian lobe of the WSS 2013 fit: exp(-((x - mu) / sigma)^2 / 2), sigma = s1 left of mu, s2 right.
double wss_lobe(double x, double mu, double s1, double s2) {
  const double t = (x - mu) / (x < mu ? s1 : s2);
  return std::exp(-0.5 * t * t);
}

SpectralRule make_spectral_rule(double max_panel_nm) {
  {
    // Kinks of the piecewise-Gaussian CMF fit (its lobe centres) become panel edges.
    const std::array<double, 9> edges{kLambdaMin, 437.0, 442.0, 459.0, 501.1, 530.9, 568.8, 599.8, kLambdaMax};
    const QuadratureRule gl = gauss_legendre(kNodesPerPanel);
    SpectralRule r;
    Rgb norm(0.0);
    for (std::size_t e = 0; e + 1 < edges.size(); ++e) {
      const int panels = int(std::ceil((edges[e + 1] - edges[e]) / max_panel_nm));
      const double h = (edges[e + 1] - edges[e]) / panels;
      for (int p = 0; p < panels; ++p) {
        const double mid = edges[e] + (p + 0.5) * h;
        for (int i = 0; i < kNodesPerPanel; ++i) {
          const double lambda = mid + 0.5 * h * gl.x[i];
          const Rgb w = cie1931_cmf_wss(lambda) * (0.5 * h * gl.w[i]);
          r.lambda.push_back(lambda);
          r.w_xyz.push_back(w);
          norm += w;
        }
      }
    }
    for (Rgb& w : r.w_xyz) w = w / norm;  // equal-energy white -> (1, 1, 1)
    return r;
  }
}

const std::vector<SpectralRule>& spectral_rules() {
  static const std::vector<SpectralRule> rules = [] {
    std::vector<SpectralRule> r;
    for (double w : kPanelWidthsNm) r.push_back(make_spectral_rule(w));
    return r;
  }();
  return rules;
}

}  // namespace

namespace thin_film_detail {

// The coarsest rule resolving the Airy oscillation: |d phase / d lambda| = |phase_nm| / lambda^2 is
// largest at the shortest wavelength.
const SpectralRule& spectral_rule(double phase_nm_abs, double resonance_width) {
  const double rate = phase_nm_abs / (kLambdaMin * kLambdaMin);  // rad per nm
  for (int level = 0; level < kRuleLevels; ++level)
    if (rate * kPanelWidthsNm[level] <= kMaxPanelPhase * resonance_width) return spectral_rules()[level];
  return spectral_rules()[kRuleLevels - 1];
}

const SpectralRule& spectral_rule_of_width(double panel_nm) {
  for (int level = 0; level < kRuleLevels; ++level)
    if (kPanelWidthsNm[level] <= panel_nm) return spectral_rules()[level];
  return spectral_rules()[kRuleLevels - 1];
}

double resonance_width(const FilmSetup& f) {
  return 1.0 - std::max(std::abs(f.r12[0] * f.r23[0]), std::abs(f.r12[1] * f.r23[1]));
}

}  // namespace thin_film_detail

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;
Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
  return c;
}
Mat3 inverse(const Mat3& m) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
      r[i][j] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;  // cofactor transpose
    }
  return r;
}
Rgb apply(const Mat3& m, const Rgb& v) {
  return {m[0][0] * v.r + m[0][1] * v.g + m[0][2] * v.b, m[1][0] * v.r + m[1][1] * v.g + m[1][2] * v.b,
          m[2][0] * v.r + m[2][1] * v.g + m[2][2] * v.b};
}

struct ColourTransform {
  Mat3 m;
  Rgb white;
};

const ColourTransform& colour_transform() {
  static const ColourTransform t = [] {
    // Bradford cone-response matrix (Lam 1985) and D65 white point (CIE 15, 2 deg observer).
    const Mat3 bradford{{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
    const Rgb d65(0.95047, 1.0, 1.08883);
    // XYZ (D65) -> linear sRGB, IEC 61966-2-1.
    const Mat3 srgb{{{3.2404542, -1.5371385, -0.4985314},
                     {-0.9692660, 1.8760108, 0.0415560},
                     {0.0556434, -0.2040259, 1.0572252}}};
    // von Kries scaling in Bradford space from the E white (1, 1, 1) to D65.
    const Rgb src = apply(bradford, Rgb(1.0)), dst = apply(bradford, d65);
    const Mat3 scale{{{dst.r / src.r, 0, 0}, {0, dst.g / src.g, 0}, {0, 0, dst.b / src.b}}};
    ColourTransform ct;
    ct.m = mul(srgb, mul(inverse(bradford), mul(scale, bradford)));
    // The published matrices are rounded to 4-7 digits: E white lands within 1e-4 of (1, 1, 1);
    // dividing by it makes a spectrally flat reflectance map exactly to a grey.
    ct.white = apply(ct.m, Rgb(1.0));
    return ct;
  }();
  return t;
}

// Rejects inputs outside the model's domain (NaN included) instead of returning NaN.
void check_film_arguments(double eta_base, double thickness_um, double eta_film) {
  if (!(eta_base > 0) || !(eta_film > 0) || !(thickness_um >= 0) || std::isinf(thickness_um) || std::isinf(eta_film))
    throw std::invalid_argument("thin film: need eta_base > 0, finite eta_film > 0 and finite thickness >= 0");
}

}  // namespace

Rgb cie1931_cmf_wss(double l) {
  // Wyman, Sloan & Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching
  // Functions", multi-lobe fit (their eq. 2; sigma in nm).
  const double x = 1.056 * wss_lobe(l, 599.8, 37.9, 31.0) + 0.362 * wss_lobe(l, 442.0, 16.0, 26.7) -
                   0.065 * wss_lobe(l, 501.1, 20.4, 26.2);
  const double y = 0.821 * wss_lobe(l, 568.8, 46.9, 40.5) + 0.286 * wss_lobe(l, 530.9, 16.3, 31.1);
  const double z = 1.217 * wss_lobe(l, 437.0, 11.8, 36.0) + 0.681 * wss_lobe(l, 459.0, 26.0, 13.8);
  return {x, y, z};
}

double fresnel_dielectric_exact(double cos_theta, double eta) {
  const double c1 = std::min(1.0, std::abs(cos_theta));
  if (eta == 1.0) return 0.0;        // no interface
  if (std::isinf(eta)) return 1.0;   // perfect mirror limit
  if (c1 == 0.0) return 1.0;         // grazing incidence on a real interface
  const double s2 = (1.0 - c1 * c1) / (eta * eta);  // Snell's law
  if (s2 >= 1.0) return 1.0;                         // total internal reflection
  const double c2 = std::sqrt(1.0 - s2);
  // Fresnel equations (Born & Wolf 1.5.2), unpolarized average.
  const double rs = (c1 - eta * c2) / (c1 + eta * c2);
  const double rp = (eta * c1 - c2) / (eta * c1 + c2);
  return 0.5 * (rs * rs + rp * rp);
}

double thin_film_metal_eta(const Rgb& rho) {
  // Spec "Thin Film": eta_rho = (1 + sqrt(max rho)) / (1 - sqrt(max rho)); max rho clamped to [0, 1].
  const double s = std::sqrt(std::clamp(rho.max_component(), 0.0, 1.0));
  if (s >= 1.0) return std::numeric_limits<double>::infinity();
  return (1.0 + s) / (1.0 - s);
}

double thin_film_reflectance_spectral(double cos_theta, double eta_base, double thickness_um,
                                      double eta_film, double lambda_nm) {
  check_film_arguments(eta_base, thickness_um, eta_film);
  const double c1 = std::min(1.0, std::abs(cos_theta));
  if (std::isinf(eta_base)) return 1.0;  // perfect mirror base: a lossless film cannot absorb
  if (thickness_um <= 0.0 || eta_film == 1.0) return fresnel_dielectric_exact(c1, eta_base);
  if (c1 == 0.0) return 1.0;  // grazing: r12 = -1, everything is reflected at the top interface
  return airy_reflectance(film_setup(c1, eta_base, thickness_um, eta_film), lambda_nm);
}

Rgb thin_film_reflectance_xyz(double cos_theta, double eta_base, double thickness_um, double eta_film,
                              ThinFilmIntegration how) {
  check_film_arguments(eta_base, thickness_um, eta_film);
  const double c1 = std::min(1.0, std::abs(cos_theta));
  if (std::isinf(eta_base)) return Rgb(1.0);
  if (thickness_um <= 0.0 || eta_film == 1.0) return Rgb(fresnel_dielectric_exact(c1, eta_base));
  if (c1 == 0.0) return Rgb(1.0);
  Rgb xyz(0.0);
  if (how == ThinFilmIntegration::Fourier && try_fourier_xyz(c1, eta_base, thickness_um, eta_film, xyz)) return xyz;
  const FilmSetup f = film_setup(c1, eta_base, thickness_um, eta_film);
  const SpectralRule& rule = spectral_rule(std::abs(f.phase_nm.real()), resonance_width(f));
  for (std::size_t i = 0; i < rule.lambda.size(); ++i) xyz += rule.w_xyz[i] * airy_reflectance(f, rule.lambda[i]);
  return xyz;
}

Rgb thin_film_xyz_to_linear_srgb(const Rgb& xyz) {
  const ColourTransform& t = colour_transform();
  return apply(t.m, xyz) / t.white;
}

Rgb thin_film_reflectance(double cos_theta, double eta_base, double thickness_um, double eta_film,
                          ThinFilmIntegration how) {
  check_film_arguments(eta_base, thickness_um, eta_film);
  const double c1 = std::min(1.0, std::abs(cos_theta));
  // The film vanishes optically: the result is exactly the base Fresnel, grey.
  if (std::isinf(eta_base)) return Rgb(1.0);
  if (thickness_um <= 0.0 || eta_film == 1.0) return Rgb(fresnel_dielectric_exact(c1, eta_base));
  const Rgb rgb = thin_film_xyz_to_linear_srgb(thin_film_reflectance_xyz(c1, eta_base, thickness_um, eta_film, how));
  // Saturated interference colours fall outside the sRGB gamut (negative channels) and pure
  // spectral peaks can exceed 1 in one channel: clamp each channel to [0, 1] (as BB17 do).
  return {std::clamp(rgb.r, 0.0, 1.0), std::clamp(rgb.g, 0.0, 1.0), std::clamp(rgb.b, 0.0, 1.0)};
}

}  // namespace dspbr
