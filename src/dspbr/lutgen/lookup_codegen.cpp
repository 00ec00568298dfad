#include "dspbr/lutgen/lookup_codegen.h"

#include "dspbr/bsdf/thin_film.h"
#include "dspbr/tables/table_registry.h"

#include <fmt/format.h>

#include <cmath>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace dspbr {

namespace {

// A float literal valid in C, GLSL and HLSL that reads back as exactly float(v).
std::string flit(double v) {
  std::string s = fmt::format("{:.9g}", float(v));
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s + "f";
}

// u^p as the warps evaluate it (warp_power, tables/warped_table.h): u, sqrt(u) for p = 1/2, else pow;
// p = 1/4 (the sheen's axes) as sqrt(sqrt(u)), within an ulp of pow in float and a tenth of its cost
// in C (a library call each).
std::string power_expr(const std::string& u, double p) {
  if (p == 1) return u;
  if (p == 0.5) return fmt::format("sqrt({})", u);
  if (p == 0.25) return fmt::format("sqrt(sqrt({}))", u);
  return fmt::format("pow({}, {})", u, flit(p));
}

// Grid-coordinate expression of a warp applied to `v` (alpha: the GgxCos roughness term); `v_in_unit`:
// the caller has clamped v to [0, 1] already.
std::string warp_expr(const Warp& w, const std::string& v, const std::string& alpha, bool v_in_unit = false) {
  switch (w.kind) {
    case WarpKind::Power: {
      std::string u = w.lo == 0 ? (v_in_unit ? v : fmt::format("clamp({}, 0.0f, 1.0f)", v))
                                : fmt::format("((clamp({}, {}, 1.0f) - {}) / {})", v, flit(w.lo), flit(w.lo),
                                              flit(1.0 - w.lo));
      return power_expr(u, w.p);
    }
    case WarpKind::GgxCos:
      return power_expr(fmt::format("dspbr_lut_ggx_cos_t({}, {})", v, alpha), w.p);
    case WarpKind::LogRoughness:
      return fmt::format("(log(clamp({}, {}, 1.0f) / {}) * {})", v, flit(w.lo), flit(w.lo),
                         flit(1.0 / std::log(1.0 / w.lo)));
    case WarpKind::GlassIor:  // aux: the view cosine
      return fmt::format("dspbr_lut_glass_ior_warp({}, {}, {})", v, alpha, flit(w.p));
  }
  return "";
}

// Whether warp_expr's value lies in [0, 1] for any v, without a further clamp: a power of v clamped
// to [0, 1], and the ggx_cos warp (t = mu / (mu + alpha sqrt(1 - mu^2)) <= 1 in float too, the
// sum rounding to at least mu); the other warps' divisions can round an ulp beyond 1.
bool warp_in_unit(const Warp& w) { return (w.kind == WarpKind::Power && w.lo == 0) || w.kind == WarpKind::GgxCos; }

std::string ident(const WarpedTable& t) { return "dspbr_" + t.name; }

// The Catmull-Rom taps of one axis (GLSL syntax): cell k<v> of n samples holding the coordinate x
// (clamped to [0, 1] unless `in_unit` says the caller's x is there already), the four sample indices
// k<v>0..k<v>3 (clamped to the table whatever x is) and their weights w<v>0..w<v>3, the linear
// extension beyond each end (p_-1 = 2 p_0 - p_1, p_n = 2 p_n-1 - p_n-2) folded into the weights: the
// same cubic as tables/warped_table.cpp's catmull_rom_taps.
std::string taps_text(const std::string& v, const std::string& x, int n, bool in_unit = false) {
  return fmt::format(
      "  float c{0} = {1} * {2};\n"
      "  int k{0} = int(c{0});\n"
      "  if (k{0} < 0) k{0} = 0;\n"
      "  if (k{0} > {3}) k{0} = {3};\n"
      "  float f{0} = c{0} - float(k{0}), g{0} = f{0} * f{0}, h{0} = g{0} * f{0};\n"
      "  float w{0}0 = 0.5f * (2.0f * g{0} - h{0} - f{0}), w{0}1 = 0.5f * (3.0f * h{0} - 5.0f * g{0} + 2.0f);\n"
      "  float w{0}2 = 0.5f * (4.0f * g{0} - 3.0f * h{0} + f{0}), w{0}3 = 0.5f * (h{0} - g{0});\n"
      "  if (k{0} == 0) {{\n    w{0}1 += 2.0f * w{0}0;\n    w{0}2 -= w{0}0;\n    w{0}0 = 0.0f;\n  }}\n"
      "  if (k{0} == {3}) {{\n    w{0}2 += 2.0f * w{0}3;\n    w{0}1 -= w{0}3;\n    w{0}3 = 0.0f;\n  }}\n"
      "  int k{0}0 = k{0} > 0 ? k{0} - 1 : 0, k{0}1 = k{0}, k{0}2 = k{0} + 1, k{0}3 = k{0} + 2 < {4} ? k{0} + 2 : {5};\n",
      v, in_unit ? x : "clamp(" + x + ", 0.0f, 1.0f)", flit(n - 1), n - 2, n, n - 1);
}

// The weighted sum over the taps of every axis (tap variables `axes`, slowest first) of the samples
// `at`(indices), as a balanced tree of products: sum_a w_a0 (sum_b w_b0 (...)).
std::string taps_sum(const std::string& at, const std::vector<std::string>& axes, const std::string& indices = "") {
  if (axes.empty()) return at + "(" + indices + ")";
  const std::string& v = axes.front();
  const std::vector<std::string> rest(axes.begin() + 1, axes.end());
  std::string term[4];
  for (int q = 0; q < 4; ++q)
    term[q] = fmt::format("{} * w{}{}", taps_sum(at, rest, indices + (indices.empty() ? "" : ", ") + fmt::format("k{}{}", v, q)), v, q);
  return fmt::format("(({} + {}) + ({} + {}))", term[0], term[1], term[2], term[3]);
}

// Catmull-Rom interpolation function of one table: dspbr_lut_interp_<id>(x0[, x1[, x2]]) over the
// sample accessor <id>_at (ident(t): the table's own).
std::string interp_function(const WarpedTable& t, const std::string& id) {
  std::string args, taps;
  std::vector<std::string> axes;
  for (size_t d = 0; d < t.axes.size(); ++d) {
    const std::string x = t.axes.size() == 1 ? "x" : "x" + std::to_string(d);
    args += (d ? ", float " : "float ") + x;
    axes.push_back(std::to_string(d));
    taps += taps_text(axes.back(), x, t.axes[d].size);
  }
  return fmt::format("float dspbr_lut_interp_{0}({1}) {{\n{2}  return {3};\n}}\n", id, args, taps,
                     taps_sum(id + "_at", axes));
}

// dspbr_lut_ggx_missing_beta: 1 - E_m at one (mu, r) (dspbr_ggx_E_missing is it), and beta there as
// dspbr_ggx_beta gives it (the same expressions), the warped coordinates and roughness taps
// computed once where the two tables share an axis; dspbr_ggx_E_missing_beta, both.
std::string ggx_missing_beta_function(const WarpedTable& e, const WarpedTable& b) {
  auto same = [](const WarpedAxis& x, const WarpedAxis& y) { return x.size == y.size && x.warp.describe() == y.warp.describe(); };
  const bool rows = same(e.axes[0], b.axes[0]);
  const bool cos_warp = e.axes[1].warp.describe() == b.axes[1].warp.describe();
  // beta's own coordinates and taps, read only with beta.
  std::string beta_taps;
  if (!rows)
    beta_taps += "  float yr = " + warp_expr(b.axes[0].warp, "r", "", true) + ";\n" +
                 taps_text("br", "yr", b.axes[0].size, warp_in_unit(b.axes[0].warp));
  if (!cos_warp) beta_taps += "  float yc = " + warp_expr(b.axes[1].warp, "mu", "r * r", true) + ";\n";
  beta_taps += taps_text("bc", cos_warp ? "xc" : "yc", b.axes[1].size, warp_in_unit(b.axes[1].warp));
  std::ostringstream o;
  o << "struct DspbrGgxMissingBeta {\n  float missing;\n  float beta;\n};\n"
    << "// 1 - E_m(mu; r) (as dspbr_ggx_E_missing) and, unless with_beta is 0 (then 0 and no read of\n"
    << "// GGX_beta), beta(mu; r) (as dspbr_ggx_beta): one call site serves a metal and a dielectric base.\n"
    << "DspbrGgxMissingBeta dspbr_lut_ggx_missing_beta(float cos_theta, float roughness, int with_beta) {\n"
    << "  float r = clamp(roughness, 0.0f, 1.0f);\n"
    << "  float mu = clamp(cos_theta, 0.0f, 1.0f);\n"
    << "  float xr = " << warp_expr(e.axes[0].warp, "r", "", true) << ";\n"
    << "  float xc = " << warp_expr(e.axes[1].warp, "mu", "r * r", true) << ";\n"
    << taps_text("er", "xr", e.axes[0].size, warp_in_unit(e.axes[0].warp))
    << taps_text("ec", "xc", e.axes[1].size, warp_in_unit(e.axes[1].warp))
    << "  DspbrGgxMissingBeta a;\n"
    << "  a.missing = clamp(" << taps_sum(ident(e) + "_missing_at", {"er", "ec"}) << ", 0.0f, 1.0f);\n"
    << "  a.beta = 0.0f;\n"
    << "  if (with_beta != 0) {\n"
    << std::regex_replace(beta_taps, std::regex("(^|\n)(.)"), "$1  $2")
    << "    float m = 1.0f - mu, m2 = m * m;\n"
    << "    a.beta = dspbr_lut_max0(m2 * m2 * m + " << taps_sum(ident(b) + "_at", {rows ? "er" : "br", "bc"}) << ");\n"
    << "  }\n"
    << "  return a;\n}\n"
    << "// 1 - E_m(mu; r) and beta(mu; r) at once, equal to dspbr_ggx_E_missing and dspbr_ggx_beta: the\n"
    << "// albedo of a dielectric base, E = f0 E_m + (1 - f0) beta E_m + F_ms (1 - E_m), reads both.\n"
    << "DspbrGgxMissingBeta dspbr_ggx_E_missing_beta(float cos_theta, float roughness) {\n"
    << "  return dspbr_lut_ggx_missing_beta(cos_theta, roughness, 1);\n}\n";
  return o.str();
}

// The public functions (GLSL syntax, shared by the three dialects).
std::string api_functions(const RendererLuts& L) {
  const auto& e = L.ggx_E;
  const auto& b = L.ggx_beta;
  const auto& ea = L.ggx_E_avg;
  const auto& ba = L.ggx_B_avg;
  const auto& s = L.sheen_E;
  const auto& sa = L.sheen_ash_E;
  std::ostringstream o;
  // 1 - E_m interpolated from 1 - each sample: exact in float for samples near 1 (Sterbenz), where
  // 1 - dspbr_ggx_E keeps only ~1e-7 absolute.
  o << "float " << ident(e) << "_missing_at(int r, int c) { return 1.0f - " << ident(e) << "_at(r, c); }\n"
    << ggx_missing_beta_function(e, b);
  o << "// E_m(mu; r): single-scattering GGX albedo, in [0, 1]. The cubic's undershoot (overshoot) is clamped\n"
    << "// here, in beta and in the sheen albedos, so that every albedo composed from them is >= 0.\n"
    << "float dspbr_ggx_E(float cos_theta, float roughness) {\n"
    << "  float r = clamp(roughness, 0.0f, 1.0f);\n"
    << "  return clamp(dspbr_lut_interp_dspbr_GGX_E(" << warp_expr(e.axes[0].warp, "r", "", true) << ", "
    << warp_expr(e.axes[1].warp, "cos_theta", "r * r") << "), 0.0f, 1.0f);\n}\n"
    << "// 1 - E_m(mu; r), in [0, 1], to full float precision where E_m is near 1 (1 - dspbr_ggx_E keeps about\n"
    << "// 1e-7 absolute: at roughness ~1e-3 that is all of 1 - E_m near normal incidence).\n"
    << "float dspbr_ggx_E_missing(float cos_theta, float roughness) {\n"
    << "  return dspbr_lut_ggx_missing_beta(cos_theta, roughness, 0).missing;\n}\n"
    << "// 1 - E_m,avg(r), stored as a logarithm (it vanishes like r^4).\n"
    << "float dspbr_ggx_E_avg_missing(float roughness) {\n"
    << "  return exp(dspbr_lut_interp_dspbr_GGX_E_avg(" << warp_expr(ea.axes[0].warp, "roughness", "") << "));\n}\n"
    << "float dspbr_ggx_E_avg(float roughness) { return 1.0f - dspbr_ggx_E_avg_missing(roughness); }\n"
    << "// beta(mu; r) = B / E_m, B = Integral M_r (1 - v.h)^5 mu_l dl the Schlick moment; stored beta - (1 - mu)^5.\n"
    << "float dspbr_ggx_beta(float cos_theta, float roughness) {\n"
    << "  float r = clamp(roughness, 0.0f, 1.0f);\n"
    << "  float mu = clamp(cos_theta, 0.0f, 1.0f);\n"
    << "  float m = 1.0f - mu, m2 = m * m;\n"
    << "  return dspbr_lut_max0(m2 * m2 * m + dspbr_lut_interp_dspbr_GGX_beta(" << warp_expr(b.axes[0].warp, "r", "", true)
    << ", " << warp_expr(b.axes[1].warp, "mu", "r * r", true) << "));\n}\n"
    << "float dspbr_lut_ggx_B(float cos_theta, float roughness) {\n"
    << "  return dspbr_ggx_beta(cos_theta, roughness) * dspbr_ggx_E(cos_theta, roughness);\n}\n"
    << "// F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg = 20/21 f0 + 1/21 f90 (spec eq. multiscatter);\n"
    << "// f0, f90, e_avg clamped to [0, 1]; 1 (the limit along F_avg = 1) when F_avg = 1 and E_avg = 0.\n"
    << "float dspbr_fresnel_ms(float f0, float f90, float e_avg) {\n"
    << "  float e = clamp(e_avg, 0.0f, 1.0f);\n"
    << "  float fa = clamp(f0, 0.0f, 1.0f) * (20.0f / 21.0f) + clamp(f90, 0.0f, 1.0f) * (1.0f / 21.0f);\n"
    << "  float d = 1.0f - fa * (1.0f - e);\n"
    << "  return d > 0.0f ? fa * fa * e / d : 1.0f;\n}\n"
    << "// E(mu; r, f0) = f0 E_m + (1 - f0) B + F_ms(f0, 1; E_m,avg) (1 - E_m) (spec \"Energy Preservation\");\n"
    << "// f0 clamped to [0, 1].\n"
    << "float dspbr_base_E(float cos_theta, float roughness, float f0_in) {\n"
    << "  float f0 = clamp(f0_in, 0.0f, 1.0f);\n"
    << "  float em = dspbr_ggx_E(cos_theta, roughness);\n"
    << "  float fms = dspbr_fresnel_ms(f0, 1.0f, dspbr_ggx_E_avg(roughness));\n"
    << "  return f0 * em + (1.0f - f0) * dspbr_lut_ggx_B(cos_theta, roughness) + fms * (1.0f - em);\n}\n"
    << "// E_avg(r, f0) = f0 E_m,avg + (1 - f0) B_avg + F_ms (1 - E_m,avg), given missing = 1 - E_m,avg(r) (as\n"
    << "// dspbr_ggx_E_avg_missing(r) gives it, for a caller that reads it anyway: one exponential, not two).\n"
    << "float dspbr_base_E_avg_given(float roughness, float f0_in, float missing) {\n"
    << "  float f0 = clamp(f0_in, 0.0f, 1.0f);\n"
    << "  float b_avg = dspbr_lut_interp_dspbr_GGX_B_avg(" << warp_expr(ba.axes[0].warp, "roughness", "") << ");\n"
    << "  return f0 * (1.0f - missing) + (1.0f - f0) * b_avg + dspbr_fresnel_ms(f0, 1.0f, 1.0f - missing) * missing;\n}\n"
    << "// E_avg(r, f0).\n"
    << "float dspbr_base_E_avg(float roughness, float f0) {\n"
    << "  return dspbr_base_E_avg_given(roughness, f0, dspbr_ggx_E_avg_missing(roughness));\n}\n"
    << "// E_b(mu; alpha_b) of the main sheen (Charlie D_b, the spec's Lambda fit).\n"
    << "float dspbr_sheen_E(float cos_theta, float alpha_b) {\n"
    << "  return dspbr_lut_max0(dspbr_lut_interp_dspbr_Sheen_E(" << warp_expr(s.axes[0].warp, "alpha_b", "") << ", "
    << warp_expr(s.axes[1].warp, "cos_theta", "") << "));\n}\n"
    << "// E_b(mu; alpha_b) of the alternative sheen (visibility 1 / (4 (mu_v + mu_l - mu_v mu_l))).\n"
    << "float dspbr_sheen_ash_E(float cos_theta, float alpha_b) {\n"
    << "  return dspbr_lut_max0(dspbr_lut_interp_dspbr_Sheen_ash_E(" << warp_expr(sa.axes[0].warp, "alpha_b", "") << ", "
    << warp_expr(sa.axes[1].warp, "cos_theta", "") << "));\n}\n"
    << "// M_r,ms / F_ms = (1 - E_m(mu_v)) (1 - E_m(mu_l)) / (pi (1 - E_m,avg)); 0 when 1 - E_m,avg <= 1e-9.\n"
    << "float dspbr_ms_lobe(float cos_v, float cos_l, float roughness) {\n"
    << "  float missing = dspbr_ggx_E_avg_missing(roughness);\n"
    << "  if (missing <= 1e-9f) return 0.0f;\n"
    << "  float mv = dspbr_ggx_E_missing(cos_v, roughness);\n"
    << "  float ml = dspbr_ggx_E_missing(cos_l, roughness);\n"
    << "  return mv * ml / (3.14159265f * missing);\n}\n"
    << "// B_c / rho = (1 - E(mu_v)) (1 - E(mu_l)) / (pi (1 - E_avg)) (spec eq. b_c); 0 when 1 - E_avg <= 1e-9.\n"
    << "float dspbr_diffuse_bc(float cos_v, float cos_l, float roughness, float f0) {\n"
    << "  float missing = 1.0f - dspbr_base_E_avg(roughness, f0);\n"
    << "  if (missing <= 1e-9f) return 0.0f;\n"
    << "  float mv = clamp(1.0f - dspbr_base_E(cos_v, roughness, f0), 0.0f, 1.0f);\n"
    << "  float ml = clamp(1.0f - dspbr_base_E(cos_l, roughness, f0), 0.0f, 1.0f);\n"
    << "  return mv * ml / (3.14159265f * missing);\n}\n"
    << "// Sheen layer scale min(1 - rho_hat E_b(mu_v), 1 - rho_hat E_b(mu_l)), E_b clamped to [0, 1]\n"
    << "// (spec \"Sheen\": albedo scaling of the layers below; rho_hat = max component of the sheen colour).\n"
    << "float dspbr_sheen_layer_scale(float cos_v, float cos_l, float alpha_b, float rho_in) {\n"
    << "  float rho_hat = clamp(rho_in, 0.0f, 1.0f);\n"
    << "  float ev = clamp(dspbr_sheen_E(cos_v, alpha_b), 0.0f, 1.0f);\n"
    << "  float el = clamp(dspbr_sheen_E(cos_l, alpha_b), 0.0f, 1.0f);\n"
    << "  return clamp(min(1.0f - rho_hat * ev, 1.0f - rho_hat * el), 0.0f, 1.0f);\n}\n"
    << "float dspbr_sheen_ash_layer_scale(float cos_v, float cos_l, float alpha_b, float rho_in) {\n"
    << "  float rho_hat = clamp(rho_in, 0.0f, 1.0f);\n"
    << "  float ev = clamp(dspbr_sheen_ash_E(cos_v, alpha_b), 0.0f, 1.0f);\n"
    << "  float el = clamp(dspbr_sheen_ash_E(cos_l, alpha_b), 0.0f, 1.0f);\n"
    << "  return clamp(min(1.0f - rho_hat * ev, 1.0f - rho_hat * el), 0.0f, 1.0f);\n}\n";
  return o.str();
}

const char* kHelpers =
    "// NaN-safe clamp: NaN maps to lo (every comparison with NaN is false), +-inf to the nearer end.\n"
    "float dspbr_lut_clampf(float x, float lo, float hi) { return x >= lo ? (x <= hi ? x : hi) : lo; }\n"
    "// x where positive, else 0 (NaN too), alike in every dialect: the max of GLSL and HLSL leaves NaN\n"
    "// undefined, and C's fmaxf is a library call.\n"
    "float dspbr_lut_max0(float x) { return x > 0.0f ? x : 0.0f; }\n"
    "// ggx_cos warp x = t^p: t = mu / (mu + alpha sqrt(1 - mu^2)) (t = 1 when alpha = 0); 1 - mu^2 >= 0\n"
    "// exactly for mu in [0, 1] (mu^2 rounds to at most 1).\n"
    "float dspbr_lut_ggx_cos_t(float cos_theta, float alpha) {\n"
    "  float mu = clamp(cos_theta, 0.0f, 1.0f);\n"
    "  float d = mu + alpha * sqrt(1.0f - mu * mu);\n"
    "  return d > 0.0f ? mu / d : 1.0f;\n"
    "}\n";

// The glass file's shared text: its ior warp (tables/warped_table.h GlassIor).
const char* kGlassHelpers =
    "// x_F = 2 sqrt(F_0) = 2 (ior - 1) / (ior + 1) in [0, 1], ior clamped to [1, 3] first (the tables'\n"
    "// range, kGlassMaxIor: +-inf and -3 go to the nearer end, NaN to 1).\n"
    "float dspbr_lut_glass_x(float ior) {\n"
    "  float n = clamp(ior, 1.0f, 3.0f);\n"
    "  return 2.0f * (n - 1.0f) / (n + 1.0f);\n"
    "}\n"
    "// glass_ior warp: x = (x_F + ln(1 + x_F / (k mu^2)) / ln(1 + 1 / (k mu^2))) / 2, x_F = 2 sqrt(F_0),\n"
    "// mu clamped to 1e-6.\n"
    "float dspbr_lut_glass_ior_warp(float ior, float cos_theta, float k) {\n"
    "  float xf = dspbr_lut_glass_x(ior);\n"
    "  float m = clamp(cos_theta, 1e-6f, 1.0f);\n"
    "  float km = k * m * m;\n"
    "  return 0.5f * xf + 0.5f * log(1.0f + xf / km) / log(1.0f + 1.0f / km);\n"
    "}\n";

// The glass file's public functions (GLSL syntax; `inside` and `transmission` are 0 or 1).
std::string glass_api_functions(const RendererLuts& L) {
  const auto& e = L.glass_E;
  const auto& ea = L.glass_E_avg;
  std::ostringstream o;
  auto e_call = [&](const char* id) {
    return fmt::format("dspbr_lut_interp_{}({}, {}, {})", id, warp_expr(e.axes[0].warp, "ior", "mu"),
                       warp_expr(e.axes[1].warp, "r", "", true), warp_expr(e.axes[2].warp, "mu", "r * r"));
  };
  auto avg_call = [&](const char* id) {
    return fmt::format("dspbr_lut_interp_{}({}, {})", id, warp_expr(ea.axes[0].warp, "xf", ""),
                       warp_expr(ea.axes[1].warp, "roughness", ""));
  };
  o << "// Schlick F_0 of the interface, ((ior - 1) / (ior + 1))^2, ior clamped to [1, 3] as the\n"
    << "// tables clamp it (kGlassMaxIor; NaN: 1).\n"
    << "float dspbr_glass_f0(float ior) {\n  float a = 0.5f * dspbr_lut_glass_x(ior);\n  return a * a;\n}\n"
    << "// E_g(mu; r, ior): albedo of the rough dielectric interface (M_r F + M_t (1 - F), specular 1),\n"
    << "// v outside (inside = 0) or inside (inside = 1, total internal reflection included).\n"
    << "float dspbr_glass_E(float cos_theta, float roughness, float ior, int inside) {\n"
    << "  float r = clamp(roughness, 0.0f, 1.0f);\n"
    << "  float mu = clamp(cos_theta, 0.0f, 1.0f);\n"
    << "  return inside != 0 ? " << e_call("dspbr_Glass_inv_E") << "\n"
    << "                     : " << e_call("dspbr_Glass_E") << ";\n}\n"
    << "// 2 Integral E_g mu dmu (the cosine average of dspbr_glass_E).\n"
    << "float dspbr_glass_E_avg(float roughness, float ior, int inside) {\n"
    << "  float xf = dspbr_lut_glass_x(ior);\n"
    << "  return inside != 0 ? " << avg_call("dspbr_Glass_inv_E_avg") << " : " << avg_call("dspbr_Glass_E_avg")
    << ";\n}\n"
    << "// Albedo of the white transparent core on one side: E_g + F_ms (1 - E_m) (the spec's M_r,ms F_ms).\n"
    << "float dspbr_glass_core_E(float cos_theta, float roughness, float ior, int inside) {\n"
    << "  float fms = dspbr_fresnel_ms(dspbr_glass_f0(ior), 1.0f, clamp(dspbr_ggx_E_avg(roughness), 0.0f, 1.0f));\n"
    << "  return dspbr_glass_E(cos_theta, roughness, ior, inside) + fms * (1.0f - dspbr_ggx_E(cos_theta, roughness));\n}\n"
    << "float dspbr_glass_core_E_avg(float roughness, float ior, int inside) {\n"
    << "  float fms = dspbr_fresnel_ms(dspbr_glass_f0(ior), 1.0f, clamp(dspbr_ggx_E_avg(roughness), 0.0f, 1.0f));\n"
    << "  return dspbr_glass_E_avg(roughness, ior, inside) + fms * dspbr_ggx_E_avg_missing(roughness);\n}\n"
    << "// Share x of the compensated energy that crosses the interface, for a viewer outside (x_o = 1 - F_avg)\n"
    << "// or inside (x_i = x_o (1 - E_o,avg) / (ior^2 (1 - E_i,avg)), the eta^2 rule; x_i <= 1 bounds x_o).\n"
    << "float dspbr_glass_transmission_share(float roughness, float ior_in, int inside) {\n"
    << "  float ior = clamp(ior_in, 1.0f, 3.0f);\n"
    << "  float f0 = dspbr_glass_f0(ior);\n"
    << "  float x_out = 1.0f - (f0 * (20.0f / 21.0f) + 1.0f / 21.0f);\n"
    << "  float m_out = max(1.0f - dspbr_glass_core_E_avg(roughness, ior, 0), 0.0f);\n"
    << "  float m_in = max(1.0f - dspbr_glass_core_E_avg(roughness, ior, 1), 0.0f);\n"
    << "  if (m_in <= 1e-9f) return 0.0f;\n"
    << "  float x_in = x_out * m_out / (ior * ior * m_in);\n"
    << "  if (x_in > 1.0f) {\n    x_in = 1.0f;\n    x_out = ior * ior * m_in / max(m_out, 1e-9f);\n  }\n"
    << "  return inside != 0 ? x_in : x_out;\n}\n"
    << "// Compensation lobe of volumetric glass, per unit of colour (reflection: times w_t rho_s,\n"
    << "// transmission: times w_t rho): share (1 - E_v(mu_v)) (1 - E_l(mu_l)) / (pi (1 - E_l,avg)), E_v on the\n"
    << "// viewer's side, E_l on the light's (the other side for transmission = 1).\n"
    << "float dspbr_glass_compensation(float cos_v, float cos_l, float roughness, float ior, int inside,\n"
    << "                               int transmission) {\n"
    << "  int side_v = inside != 0 ? 1 : 0;  // any non-zero is inside, as in the other glass functions\n"
    << "  int side_l = transmission != 0 ? 1 - side_v : side_v;\n"
    << "  float missing_avg = 1.0f - dspbr_glass_core_E_avg(roughness, ior, side_l);\n"
    << "  if (missing_avg <= 1e-9f) return 0.0f;\n"
    << "  float mv = clamp(1.0f - dspbr_glass_core_E(abs(cos_v), roughness, ior, inside), 0.0f, 1.0f);\n"
    << "  float ml = clamp(1.0f - dspbr_glass_core_E(abs(cos_l), roughness, ior, side_l), 0.0f, 1.0f);\n"
    << "  float x = dspbr_glass_transmission_share(roughness, ior, inside);\n"
    << "  return (transmission != 0 ? x : 1.0f - x) * mv * ml / (3.14159265f * missing_avg);\n}\n"
    << "// The same for thin-walled glass: one albedo for both sides, 1 - E = (1 - F_ms)(1 - E_m), x = 1 - F_avg.\n"
    << "float dspbr_thin_glass_compensation(float cos_v, float cos_l, float roughness, float ior, int transmission) {\n"
    << "  float f0 = dspbr_glass_f0(ior);\n"
    << "  float fms = dspbr_fresnel_ms(f0, 1.0f, clamp(dspbr_ggx_E_avg(roughness), 0.0f, 1.0f));\n"
    << "  float missing_avg = (1.0f - fms) * dspbr_ggx_E_avg_missing(roughness);\n"
    << "  if (missing_avg <= 1e-9f) return 0.0f;\n"
    << "  float mv = clamp((1.0f - fms) * (1.0f - dspbr_ggx_E(abs(cos_v), roughness)), 0.0f, 1.0f);\n"
    << "  float ml = clamp((1.0f - fms) * (1.0f - dspbr_ggx_E(abs(cos_l), roughness)), 0.0f, 1.0f);\n"
    << "  float x = 1.0f - (f0 * (20.0f / 21.0f) + 1.0f / 21.0f);\n"
    << "  return (transmission != 0 ? x : 1.0f - x) * mv * ml / (3.14159265f * missing_avg);\n}\n";
  return o.str();
}

// GLSL body text -> C: math functions, casts, static inline.
std::string to_c(const std::string& glsl) {
  std::string s = glsl;
  const std::pair<const char*, const char*> fns[] = {
      {"min", "fminf"}, {"max", "fmaxf"}, {"sqrt", "sqrtf"},
      {"pow", "powf"},            {"exp", "expf"},  {"log", "logf"}, {"abs", "fabsf"}};
  for (const auto& [from, to] : fns) s = std::regex_replace(s, std::regex(std::string("\\b") + from + "\\("), std::string(to) + "(");
  s = std::regex_replace(s, std::regex("\\bfloat\\("), "(float)(");
  s = std::regex_replace(s, std::regex("\\bint\\("), "(int)(");
  s = std::regex_replace(s, std::regex("(^|\\n)(float|Dspbr\\w+) (\\w+)\\("), "$1static inline $2 $3(");
  s = std::regex_replace(s, std::regex("(^|\\n)struct (\\w+) \\{([^}]*)\\};"), "$1typedef struct $2 {$3} $2;");
  return s;
}

void emit_values(std::ostringstream& o, const WarpedTable& t) {
  for (size_t i = 0; i < t.values.size(); ++i) {
    o << (i % 8 == 0 ? "\n  " : " ") << flit(t.values[i]) << (i + 1 < t.values.size() ? "," : "");
  }
}

std::string table_comment(const WarpedTable& t) {
  std::string s = "// " + t.name + ": ";
  for (size_t d = 0; d < t.axes.size(); ++d)
    s += (d ? " x " : "") + t.axes[d].name + "[" + std::to_string(t.axes[d].size) + "] " + t.axes[d].warp.describe();
  s += t.encoding == Encoding::LogOneMinus ? ", stored ln(1 - value)" : "";
  if (is_lut(t.name, Lut::GgxBeta)) s += ", stored beta - (1 - mu)^5";
  return s + "\n";
}


// What one generated file holds.
struct FileSpec {
  std::string title;                // first comment line after the file name
  std::vector<const char*> tables;  // in order; texture bindings follow it
  int binding_offset = 0;           // first texture binding / register of the file
  std::string guard;                // include guard stem (C: <stem>_H, shaders: <stem>_INCLUDED)
  std::string floats_macro;         // #define <macro> <stored values>
  size_t floats = 0;
  std::string preamble;             // comment lines after the table list (may be empty)
  std::string helpers;              // shared function text (GLSL syntax)
  std::string api;                  // the public functions (GLSL syntax)
};

// Sample accessor <id>_at(...) of a table stored as an array <id>_table.
std::string array_accessor(const WarpedTable& t, bool c) {
  const std::string id = ident(t), pre = c ? "static inline float " : "float ";
  if (t.axes.size() == 3)
    return fmt::format("{0}{1}_at(int p, int r, int c) {{ return {1}_table[(p * {2} + r) * {3} + c]; }}\n", pre, id,
                       t.axes[1].size, t.axes[2].size);
  if (t.axes.size() == 2)
    return fmt::format("{0}{1}_at(int r, int c) {{ return {1}_table[r * {2} + c]; }}\n", pre, id, t.axes[1].size);
  return fmt::format("{0}{1}_at(int i) {{ return {1}_table[i]; }}\n", pre, id);
}

// Sample accessor reading a texture (width = fastest axis; a rank-3 table's planes stacked).
std::string texture_accessor(const WarpedTable& t, bool glsl) {
  const std::string id = ident(t);
  std::string args, xy;
  if (t.axes.size() == 3) {
    args = "int p, int r, int c";
    xy = fmt::format("c, p * {} + r", t.axes[1].size);
  } else if (t.axes.size() == 2) {
    args = "int r, int c";
    xy = "c, r";
  } else {
    args = "int i";
    xy = "i, 0";
  }
  if (glsl) return fmt::format("float {0}_at({1}) {{ return texelFetch({0}_tex, ivec2({2}), 0).r; }}\n", id, args, xy);
  return fmt::format("float {0}_at({1}) {{ return {0}_tex.Load(int3({2}, 0)); }}\n", id, args, xy);
}

int texture_height(const WarpedTable& t) { return int(t.size() / size_t(t.axes.back().size)); }

std::string file_text(const RendererLuts& L, LookupDialect dialect, const std::string& provenance, const FileSpec& f,
                      const char* file_name) {
  std::ostringstream o;
  o << "// " << file_name << ": " << f.title << "\n"
    << "// Generated by `dspbr lut`; do not edit. " << provenance << "\n"
    << "// Tables (endpoint grids x_i = i / (N - 1) over warped coordinates, Catmull-Rom interpolation\n"
    << "// with linear extrapolation beyond the ends; row-major, fastest axis last):\n";
  for (const char* n : f.tables) o << table_comment(*L.table(n));
  o << "// Arguments out of range are clamped to it (cosines, roughness, f0, alpha_b, rho_hat: [0, 1];\n"
    << "// ior: [1, 3]); NaN gives the result at the low end, +-inf at the nearer end; every cell index\n"
    << "// is clamped on both sides (docs/luts.md, \"Limits\").\n";
  o << f.preamble;
  int binding = f.binding_offset;
  if (dialect != LookupDialect::C) {
    o << "// With DSPBR_LOOKUP_TEXTURES defined, the tables are read from single-channel float\n"
      << "// textures (R32F; width = fastest axis, height = slowest axis or 1; a three-axis table's\n"
      << "// planes stacked: row = plane * rows + row), fetched with texelFetch / Load at integer texel\n"
      << "// coordinates (no filtering). GLSL: `uniform sampler2D` at binding N of descriptor set 0, in\n"
      << "// Vulkan a combined image sampler (VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER; any sampler:\n"
      << "// texelFetch ignores its state), in OpenGL the texture unit N; HLSL: Texture2D<float> at tN:\n";
    for (const char* n : f.tables) {
      const WarpedTable& t = *L.table(n);
      o << "//   " << ident(t) << "_tex  binding " << binding++ << "  " << t.axes.back().size << " x "
        << texture_height(t) << "\n";
    }
    o << "// (DSPBR_LOOKUP_BINDING_BASE shifts the GLSL bindings; DSPBR_LOOKUP_REGISTER_SPACE selects the\n"
      << "// HLSL space.) Without it, the tables are constant arrays.\n";
  }
  if (dialect == LookupDialect::C) {
    o << "#ifndef " << f.guard << "_H\n#define " << f.guard << "_H\n#include <math.h>\n\n";
  } else {
    o << "#ifndef " << f.guard << "_INCLUDED\n#define " << f.guard << "_INCLUDED\n\n";
  }
  o << "#define " << f.floats_macro << " " << f.floats << "\n\n";
  if (dialect == LookupDialect::C) {
    for (const char* n : f.tables) {
      const WarpedTable& t = *L.table(n);
      o << "static const float " << ident(t) << "_table[" << t.size() << "] = {";
      emit_values(o, t);
      o << "};\n" << array_accessor(t, true);
    }
  } else {
    const bool glsl = dialect == LookupDialect::Glsl;
    if (f.binding_offset == 0) {
      o << "#ifndef DSPBR_TABLE\n";
      if (glsl) o << "#define DSPBR_TABLE(name, n) const float name[n] = float[n](\n#define DSPBR_TABLE_END );\n";
      else o << "#define DSPBR_TABLE(name, n) static const float name[n] = {\n#define DSPBR_TABLE_END };\n";
      o << "#endif\n";
      if (glsl) o << "#ifndef DSPBR_LOOKUP_BINDING_BASE\n#define DSPBR_LOOKUP_BINDING_BASE 0\n#endif\n";
      else o << "#ifndef DSPBR_LOOKUP_REGISTER_SPACE\n#define DSPBR_LOOKUP_REGISTER_SPACE space0\n#endif\n";
    }
    o << "#ifdef DSPBR_LOOKUP_TEXTURES\n";
    binding = f.binding_offset;
    for (const char* n : f.tables) {
      const WarpedTable& t = *L.table(n);
      const std::string id = ident(t);
      if (glsl)
        o << "layout(binding = DSPBR_LOOKUP_BINDING_BASE + " << binding << ") uniform sampler2D " << id << "_tex;\n";
      else
        o << "Texture2D<float> " << id << "_tex : register(t" << binding << ", DSPBR_LOOKUP_REGISTER_SPACE);\n";
      o << texture_accessor(t, glsl);
      ++binding;
    }
    o << "#else\n";
    for (const char* n : f.tables) {
      const WarpedTable& t = *L.table(n);
      o << "DSPBR_TABLE(" << ident(t) << "_table, " << t.size() << ")";
      emit_values(o, t);
      o << "\nDSPBR_TABLE_END\n" << array_accessor(t, false);
    }
    o << "#endif\n";
  }
  std::string body = f.helpers;
  for (const char* n : f.tables) body += interp_function(*L.table(n), ident(*L.table(n)));
  body += f.api;
  // Every clamp of the generated code is the NaN-safe dspbr_lut_clampf (GLSL/HLSL clamp leave NaN undefined).
  body = std::regex_replace(body, std::regex("\\bclamp\\("), "dspbr_lut_clampf(");
  o << "\n" << (dialect == LookupDialect::C ? to_c(body) : body);
  o << "\n#endif\n";
  return o.str();
}

}  // namespace

const char* lookup_file_name(LookupDialect d) {
  switch (d) {
    case LookupDialect::C: return "dspbr_lookup.h";
    case LookupDialect::Glsl: return "dspbr_lookup.glsl";
    case LookupDialect::Hlsl: return "dspbr_lookup.hlsl";
  }
  return "";
}

const char* glass_lookup_file_name(LookupDialect d) {
  switch (d) {
    case LookupDialect::C: return "dspbr_glass_lookup.h";
    case LookupDialect::Glsl: return "dspbr_glass_lookup.glsl";
    case LookupDialect::Hlsl: return "dspbr_glass_lookup.hlsl";
  }
  return "";
}

std::string lookup_code(const RendererLuts& L, LookupDialect dialect, const std::string& provenance) {
  FileSpec f;
  f.title = "DSPBR 2025x energy-compensation lookups, renderer layout (docs/luts.md).";
  f.tables = RendererLuts::names();
  f.guard = "DSPBR_LOOKUP";
  f.floats_macro = "DSPBR_LOOKUP_FLOATS";
  f.floats = L.stored_values();
  f.helpers = kHelpers;
  f.api = api_functions(L);
  return file_text(L, dialect, provenance, f, lookup_file_name(dialect));
}

const char* thin_film_lookup_file_name() { return "dspbr_thin_film_lookup.h"; }

std::string thin_film_lookup_code() {
  const ThinFilmSensitivity& s = thin_film_sensitivity();
  std::ostringstream o;
  o << "// " << thin_film_lookup_file_name() << ": the thin film's spectral sensitivity for the shader library's\n"
    << "// C++ compile (shaders/dspbr/thin_film.glsl, the Fourier evaluation of Belcour & Barla 2017 sec. 4).\n"
    << "// S_c(x) = Integral cmf_c(lambda) exp(i x / lambda) dlambda / Integral cmf_c (c = X, Y, Z; the CIE 1931\n"
    << "// fit of Wyman, Sloan & Shirley 2013, 2 nm Gauss-Legendre panels) as its envelope\n"
    << "// E_c(x) = S_c(x) exp(-i x nu_c), sampled every DSPBR_THIN_FILM_S_STEP rad nm from x = -STEP\n"
    << "// (sample k at x = (k - 1) STEP: Re E_X, Re E_Y, Re E_Z, Im E_X, Im E_Y, Im E_Z), Catmull-Rom between\n"
    << "// samples, S_c = 0 from DSPBR_THIN_FILM_S_X_END on (|S_c| < 2e-6 there). The reference's table\n"
    << "// (src/dspbr/bsdf/thin_film_fourier.cpp) in float. Generated by dspbr lut (the same for any\n"
    << "// settings); do not edit.\n"
    << "#ifndef DSPBR_THIN_FILM_LOOKUP_H\n#define DSPBR_THIN_FILM_LOOKUP_H\n\n"
    << "#define DSPBR_THIN_FILM_S_SAMPLES " << s.samples.size() << "\n"
    << "#define DSPBR_THIN_FILM_S_STEP " << flit(s.step) << "\n"
    << "#define DSPBR_THIN_FILM_S_X_END " << flit(s.x_end) << "\n"
    << "static const float dspbr_thin_film_S_nu[3] = {" << flit(s.nu[0]) << ", " << flit(s.nu[1]) << ", "
    << flit(s.nu[2]) << "};\n"
    << "static const float dspbr_thin_film_S_table[" << 6 * s.samples.size() << "] = {\n";
  for (const auto& e : s.samples) {
    o << " ";
    for (double x : e) o << " " << flit(x) << ",";
    o << "\n";
  }
  o << "};\n"
    << "static inline float dspbr_thin_film_S_at(int k, int i) { return dspbr_thin_film_S_table[6 * k + i]; }\n"
    << "\n#endif\n";
  return o.str();
}

std::string glass_lookup_code(const RendererLuts& L, LookupDialect dialect, const std::string& provenance) {
  if (!L.has_glass()) throw std::invalid_argument("glass lookup code: the set holds no Glass tables");
  FileSpec f;
  f.title = "rough-glass energy-compensation lookups, beyond DSPBR 2025x (docs/luts.md, \"Glass tables\";\n"
            "// docs/bsdf.md, \"Transmission compensation\").";
  f.tables = RendererLuts::glass_names();
  f.binding_offset = int(RendererLuts::names().size());
  f.guard = "DSPBR_GLASS_LOOKUP";
  f.floats_macro = "DSPBR_GLASS_LOOKUP_FLOATS";
  f.floats = L.glass_stored_values();
  f.preamble = std::string("// Include ") + lookup_file_name(dialect) + " first (same folder, same table mode).\n";
  f.helpers = kGlassHelpers;
  f.api = glass_api_functions(L);
  return file_text(L, dialect, provenance, f, glass_lookup_file_name(dialect));
}

}  // namespace dspbr
