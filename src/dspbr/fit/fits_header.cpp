#include "dspbr/fit/fits_header.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "dspbr/constants.h"
#include "dspbr/fit/albedo_forms.h"
#include "dspbr/fit/flake_fit.h"

namespace dspbr::fit {

namespace {

std::string coef_list(const nlohmann::json& a) {
  std::string s;
  for (size_t i = 0; i < a.size(); ++i) {
    s += fmt::format("{:.8e}f", a[i].get<double>());  // 9 significant digits: round-trips a float
    if (i + 1 < a.size()) s += (i % 6 == 5) ? ",\n      " : ", ";
  }
  return s;
}

std::string err_line(const nlohmann::json& e) {
  return fmt::format("max abs error {:.2e}, mean {:.2e}", e["max"].get<double>(), e["mean"].get<double>());
}

// The shared evaluation code of the albedo fits, for the degree of albedo_forms.h.
std::string poly_code() {
  const int n = kPoly2Degree, n1 = n + 1, np = kPoly2Params;
  return fmt::format(R"(// Polynomials in shifted variables X = 2x - 1 in [-1, 1] (well conditioned in float).
// S(x; y1, y2) = sum_{{i,j=0..{0}}} q[{1} i + j] X^i Y1^j + sum_{{i=0..{0}, j=1..{0}}} q[{2} + {0} i + j - 1] X^i Y2^j
inline float dspbr_fit_detail_dual(const float* q, float x_, float y1_, float y2_) {{
  const float x = 2.0f * x_ - 1.0f, y1 = 2.0f * y1_ - 1.0f, y2 = 2.0f * y2_ - 1.0f;
  float acc = 0.0f;
  for (int i = {0}; i >= 0; --i) {{
    const float* b = q + {2} + i * {0};
    float row2 = b[{3}];
    for (int j = {4}; j >= 0; --j) row2 = row2 * y2 + b[j];
    row2 = row2 * y2;
    float row1 = q[i * {1} + {0}];
    for (int j = {3}; j >= 0; --j) row1 = row1 * y1 + q[i * {1} + j];
    acc = acc * x + (row1 + row2);
  }}
  return acc;
}}
// Q(x) = sum_{{k=0..7}} q[k] X^k, X = 2x - 1 (Horner)
inline float dspbr_fit_detail_poly1(const float* q, float x_) {{
  const float x = 2.0f * x_ - 1.0f;
  float acc = q[7];
  for (int k = 6; k >= 0; --k) acc = acc * x + q[k];
  return acc;
}}
inline float dspbr_fit_detail_clamp01(float x) {{ return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x); }}
)",
                     n, n1, np, n - 1, n - 2);
}

}  // namespace

std::string flake_lobe_code(const nlohmann::json& fl) {
  return fmt::format(R"(// Far-field flake lobe f(v, l) (the flake layer's BRDF averaged over many flakes, without the
// flake colour): the mass of the flake-normal density D(n) n.z over the image of the cone cap
// around l under r -> n = normalize(v + r), divided by the cap's solid angle; the mass is the
// divergence-theorem integral of the GGX slope density along the image of the cap's rim
// ({} points). v, l: unit vectors, local frame (z = normal). Domain: flake_roughness in [0.05, 1]
// (clamped to [0.01, 1]), views 0-80 deg: relative L2 error of f l.z vs the aggregate up to
// {:.3f}, albedo error up to {:.1e}.
inline float dspbr_fit_flake_lobe(float vx, float vy, float vz, float lx, float ly, float lz, float flake_roughness) {{
  if (lz <= 0.0f) return 0.0f;
  const float rf = flake_roughness < 0.01f ? 0.01f : (flake_roughness > 1.0f ? 1.0f : flake_roughness);
  const float ac2 = std::fmin({}f, 0.5f * rf * rf);  // alpha_cone^2 (spec eq. alpha-cone)
  const float a2 = rf * rf - ac2;                    // alpha_ggx^2
  const float cc = (1.0f - ac2) / (1.0f + ac2), sn = 2.0f * std::sqrt(ac2) / (1.0f + ac2);
  const float vl = vx * lx + vy * ly + vz * lz;
  float px = vx - vl * lx, py = vy - vl * ly, pz = vz - vl * lz;
  float pn = px * px + py * py + pz * pz;
  if (pn < 1e-12f) {{  // v = l: any direction perpendicular to l
    if (std::fabs(lz) < 0.9f) {{ px = ly; py = -lx; pz = 0.0f; }} else {{ px = 0.0f; py = lz; pz = -ly; }}
    pn = px * px + py * py + pz * pz;
  }}
  const float ip = 1.0f / std::sqrt(pn);
  px *= ip; py *= ip; pz *= ip;
  const float bx = ly * pz - lz * py, by = lz * px - lx * pz, bz = lx * py - ly * px;
  const float cx = vx + cc * lx, cy = vy + cc * ly, cz = vz + cc * lz;
  const float rc = {}f, rs = {}f;  // rotation by 2 pi / points
  float ct = {}f, st = {}f;        // first point at pi / points
  float sum = 0.0f;
  for (int i = 0; i < {}; ++i) {{
    const float wx = cx + sn * (ct * px + st * bx), wy = cy + sn * (ct * py + st * by), wz = cz + sn * (ct * pz + st * bz);
    const float dx = sn * (ct * bx - st * px), dy = sn * (ct * by - st * py), dz = sn * (ct * bz - st * pz);
    if (wz <= 0.0f) return 0.0f;  // the cap reaches normals at the horizon
    const float iz = 1.0f / wz, x = wx * iz, y = wy * iz;
    const float sx = (dx - x * dz) * iz, sy = (dy - y * dz) * iz;
    sum += (x * sy - y * sx) / (a2 + x * x + y * y);
    const float c2 = ct * rc - st * rs;
    st = st * rc + ct * rs;
    ct = c2;
  }}
  const float mass = std::fmin(1.0f, std::fabs(sum) / {}.0f);
  return mass * (1.0f + ac2) / (4.0f * 3.14159265f * ac2);  // / Omega_cone = 2 pi (1 - cos) = 4 pi ac2 / (1 + ac2)
}}
)",
                     kFlakeRimPoints, fl["lobe_error_max"].get<double>(), fl["albedo_error_max"].get<double>(),
                     fmt::format("{:.8e}", flake_tan2_half_cone()), fmt::format("{:.8e}", std::cos(2 * kPi / kFlakeRimPoints)),
                     fmt::format("{:.8e}", std::sin(2 * kPi / kFlakeRimPoints)), fmt::format("{:.8e}", std::cos(kPi / kFlakeRimPoints)),
                     fmt::format("{:.8e}", std::sin(kPi / kFlakeRimPoints)), kFlakeRimPoints, kFlakeRimPoints);
}

void check_fit_document(const std::string& name, const nlohmann::json& doc) {
  // (JSON pointer, expected array length; 0: a number) of every value the generators read.
  std::vector<std::pair<std::string, std::size_t>> wanted;
  if (name == "sheen_lambda") {
    wanted = {{"/coefficients", 16}, {"/domain/alpha_b/0", 0}, {"/domain/cos_theta/0", 0}, {"/domain/cos_theta/1", 0},
              {"/error/models/ours_rich/lambda_rel_error/max", 0}, {"/error/models/ours_rich/lambda_rel_error/rms", 0}};
  } else if (name == "albedo") {
    wanted = {{"/coefficients/ggx_E", kDualParams}, {"/coefficients/ggx_E_avg", kAvgParams},
              {"/coefficients/ggx_E5", kDualParams}, {"/coefficients/ggx_E5_avg", kPoly1Params},
              {"/coefficients/sheen_E", kDualParams}, {"/coefficients/sheen_ash_E", kDualParams},
              {"/domain/cos_theta/0", 0}, {"/domain/alpha_b/0", 0}, {"/fit/ggx_E_avg_tolerance_units_max", 0}};
    for (const char* k : {"ggx_E", "ggx_E_avg", "base_E", "base_E_avg", "sheen_E", "sheen_ash_E"})
      for (const char* m : {"max", "mean"}) wanted.push_back({std::string("/error/") + k + "/" + m, 0});
  } else if (name == "flake_roughness") {
    wanted = {{"/coefficients", 3}, {"/domain/flake_roughness/0", 0}, {"/domain/flake_roughness/1", 0},
              {"/formula_error/max", 0}, {"/ggx_lobe_error_max", 0}, {"/ggx_albedo_error_max", 0},
              {"/lobe_error_max", 0}, {"/albedo_error_max", 0}};
  } else {
    throw std::invalid_argument("unknown fit '" + name + "'");
  }
  if (!doc.is_object()) throw std::invalid_argument("not the " + name + " fit's document (not a JSON object)");
  const auto number = [&](const nlohmann::json& x, const std::string& where) {
    if (!x.is_number() || !(std::fabs(x.get<double>()) <= double(std::numeric_limits<float>::max())))
      throw std::invalid_argument("not the " + name + " fit's document: " + where + " is not a number within the float range");
  };
  for (const auto& [ptr, length] : wanted) {
    const nlohmann::json::json_pointer p(ptr);
    // contains() follows the path without inserting and without throwing on a wrong type.
    if (!doc.contains(p)) throw std::invalid_argument("not the " + name + " fit's document: no " + ptr);
    const nlohmann::json& x = doc.at(p);
    if (length == 0) {
      number(x, ptr);
      continue;
    }
    if (!x.is_array() || x.size() != length)
      throw std::invalid_argument("not the " + name + " fit's document: " + ptr + " is not an array of " + std::to_string(length) +
                                  " numbers");
    for (std::size_t i = 0; i < length; ++i) number(x[i], ptr + "/" + std::to_string(i));
  }
}

std::string generate_fits_header(const nlohmann::json& sl, const nlohmann::json& al, const nlohmann::json& fl) {
  std::string h;
  h += R"(// dspbr_fits.hpp -- LUT-free fits for the DSPBR 2025x (Enterprise PBR) shading model.
// GENERATED by `dspbr fit` from fits/*.json; do not edit. Self-contained: only <cmath>.
// Conventions follow the tables: roughness r (GGX alpha = r^2), sheen alpha_b = r_b^2,
// cos_theta = cosine to the normal. Errors were measured against the exact quantities on fresh
// grids (see fits/*.json and docs/fits.md).
#pragma once
#include <cmath>

)";
  if (!sl.is_null()) {
    const auto& q = sl["coefficients"];
    const auto& e = sl["error"]["models"]["ours_rich"]["lambda_rel_error"];
    h += fmt::format(R"(// Smith Lambda of the Charlie sheen distribution (spec "Sheen"):
//   Lambda = b (sqrt(1 + A^2 tan^2) - 1) exp(c mu / (1 + d mu)), b, A, c, d rational in sqrt(alpha_b).
// Domain: alpha_b in [{}, 1], cos_theta in [{}, {}] (valid and exact-limit behaved on (0, 1]:
// +inf at cos 0, 0 at cos 1). Relative error of Lambda: max {:.2e}, RMS {:.2e}.
inline float dspbr_fit_sheen_lambda(float cos_theta, float alpha_b) {{
  static const float q[16] = {{{}}};
  const float mu = std::fmin(std::fabs(cos_theta), 1.0f);
  if (mu <= 0.0f) return HUGE_VALF;  // grazing: fully masked
  if (mu >= 1.0f) return 0.0f;       // normal incidence: no masking
  // below cos 1e-6, Lambda > 1e5 and G = 1/(1 + Lambda + ...) changes by < 1e-5: clamping keeps
  // mu^2 out of float underflow (which would give inf/inf = NaN)
  const float m = std::fmax(mu, 1e-6f);
  const float s = std::sqrt(alpha_b);
  float f[4];
  for (int i = 0; i < 4; ++i) f[i] = (q[4 * i] + q[4 * i + 1] * s + q[4 * i + 2] * (s * s)) / (1.0f + q[4 * i + 3] * s);
  const float x = f[1] * f[1] * ((1.0f - m * m) / (m * m));
  return f[0] * x / (std::sqrt(1.0f + x) + 1.0f) * std::exp(f[2] * m / (1.0f + f[3] * m));
}}

)",
                     sl["domain"]["alpha_b"][0].get<double>(), sl["domain"]["cos_theta"][0].get<double>(),
                     sl["domain"]["cos_theta"][1].get<double>(), e["max"].get<double>(), e["rms"].get<double>(),
                     coef_list(q));
  }
  if (!al.is_null()) {
    const auto& c = al["coefficients"];
    const auto& e = al["error"];
    h += poly_code();
    h += fmt::format(R"(
// u = mu / (mu + r^2), the grazing boundary-layer variable (1 at mu = r = 0).
inline float dspbr_fit_detail_u(float cos_theta, float roughness) {{
  const float d = cos_theta + roughness * roughness;
  return d > 0.0f ? cos_theta / d : 1.0f;
}}

// 1 - E_m(mu; r) = (1 - u)^2 S(r; u, mu) (computed without cancellation: M_r,ms needs it).
inline float dspbr_fit_ggx_E_loss(float cos_theta, float roughness) {{
  static const float q[{}] = {{{}}};
  const float a = roughness * roughness, d = cos_theta + a;
  const float u = d > 0.0f ? cos_theta / d : 1.0f, w = d > 0.0f ? a / d : 0.0f;
  return dspbr_fit_detail_clamp01(w * w * dspbr_fit_detail_dual(q, roughness, u, cos_theta));
}}

// Directional albedo of single-scattering GGX, E_m(mu; r) = 1 - (1 - u)^2 S(r; u, mu), u = mu/(mu + r^2)
// (exact at the mirror r = 0). Domain: cos_theta in [{}, 1], roughness in [0, 1]. {}.
inline float dspbr_fit_ggx_E(float cos_theta, float roughness) {{ return 1.0f - dspbr_fit_ggx_E_loss(cos_theta, roughness); }}

// 1 - E_m,avg(r) = r^4 P(r), P of degree 6 on each of [0, 0.1) (in ln r), [0.1, 0.3), [0.3, 1],
// fitted to the cosine average of dspbr_fit_ggx_E_loss: the M_r,ms lobe built from both integrates
// to 1 - E_m (white furnace). Error vs that average, in units of its tolerance (1e-3 relative or
// 1e-4 absolute, whichever is smaller): {:.2f}. Use it, not 1 - E_avg, as M_r,ms's divisor: below
// r ~ 0.05 it is smaller than float resolution near 1.
inline float dspbr_fit_ggx_E_avg_loss(float roughness) {{
  static const float q[{}] = {{{}}};
  if (roughness <= 0.0f) return 0.0f;
  const float r = roughness > 1.0f ? 1.0f : roughness;
  const int k = r < 0.1f ? 0 : (r < 0.3f ? 1 : 2);
  const float z = k == 0 ? std::log(r * 500.0f) * {}f : (k == 1 ? (r - 0.1f) * 5.0f : (r - 0.3f) * (1.0f / 0.7f));
  const float x = 2.0f * z - 1.0f;
  const float* c = q + {} * k;
  float acc = c[{}];
  for (int j = {}; j >= 0; --j) acc = acc * x + c[j];
  const float r2 = r * r;
  return dspbr_fit_detail_clamp01(r2 * r2 * acc);
}}

// Average albedo of single-scattering GGX, E_m,avg(r). Domain: roughness in [0, 1]. {}.
inline float dspbr_fit_ggx_E_avg(float roughness) {{ return 1.0f - dspbr_fit_ggx_E_avg_loss(roughness); }}

// E_5(mu; r) = Integral M_r (1 - v.h)^5 mu_l dl (the Schlick part of Base_E), S(r; mu, u).
inline float dspbr_fit_detail_ggx_E5(float cos_theta, float roughness) {{
  static const float q[{}] = {{{}}};
  return dspbr_fit_detail_clamp01(dspbr_fit_detail_dual(q, roughness, cos_theta, dspbr_fit_detail_u(cos_theta, roughness)));
}}
inline float dspbr_fit_detail_ggx_E5_avg(float roughness) {{
  static const float q[8] = {{{}}};
  return dspbr_fit_detail_clamp01(dspbr_fit_detail_poly1(q, roughness));
}}
// F_ms(f0, 1) = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg = f0 20/21 + 1/21 (spec).
inline float dspbr_fit_detail_fms(float f0, float e_avg) {{
  const float fa = f0 * (20.0f / 21.0f) + 1.0f / 21.0f;
  return fa * fa * e_avg / (1.0f - fa * (1.0f - e_avg));
}}

// Base_E: albedo of Fresnel-weighted multiple-scattering GGX (spec "Diffuse BRDF"), exact
// decomposition f0 E_m + (1 - f0) E_5 + F_ms (1 - E_m). Domain: cos, roughness, f0 in [0, 1]. {}.
inline float dspbr_fit_base_E(float cos_theta, float roughness, float f0) {{
  const float loss = dspbr_fit_ggx_E_loss(cos_theta, roughness);
  return f0 * (1.0f - loss) + (1.0f - f0) * dspbr_fit_detail_ggx_E5(cos_theta, roughness) +
         dspbr_fit_detail_fms(f0, dspbr_fit_ggx_E_avg(roughness)) * loss;
}}

// Base_E_avg(r, f0). Domain: roughness, f0 in [0, 1]. {}.
inline float dspbr_fit_base_E_avg(float roughness, float f0) {{
  const float loss = dspbr_fit_ggx_E_avg_loss(roughness), ea = 1.0f - loss;
  return f0 * ea + (1.0f - f0) * dspbr_fit_detail_ggx_E5_avg(roughness) + dspbr_fit_detail_fms(f0, ea) * loss;
}}

// Sheen_E: albedo of the main sheen BRDF (spec's Lambda fit), S(l; 1 + log10(mu)/3, mu / (mu + sqrt(alpha_b)/2)),
// l = -log2(alpha_b)/8. Domain: cos_theta in [1e-3, 1] (clamped to it: with the spec's Lambda the
// albedo exceeds 1 at grazing and grows without bound below), alpha_b in [{}, 1] (clamped). {}.
inline float dspbr_fit_sheen_E(float cos_theta, float alpha_b) {{
  static const float q[{}] = {{{}}};
  const float a = alpha_b < 0.00390625f ? 0.00390625f : (alpha_b > 1.0f ? 1.0f : alpha_b);
  const float mu = cos_theta < 1e-3f ? 1e-3f : (cos_theta > 1.0f ? 1.0f : cos_theta);
  const float l = -std::log2(a) / 8.0f;
  const float u = cos_theta / (cos_theta + 0.5f * std::sqrt(a));
  const float e = dspbr_fit_detail_dual(q, l, 1.0f + std::log10(mu) / 3.0f, u);
  return e > 0.0f ? e : 0.0f;
}}

// Sheen_ash_E: albedo of the alternative sheen BRDF ([NP13] visibility; not energy conserving:
// up to ~6 at grazing for small alpha_b), S(l; sqrt(mu), mu / (mu + sqrt(alpha_b)/2)). Domain as
// dspbr_fit_sheen_E. {}.
inline float dspbr_fit_sheen_ash_E(float cos_theta, float alpha_b) {{
  static const float q[{}] = {{{}}};
  const float a = alpha_b < 0.00390625f ? 0.00390625f : (alpha_b > 1.0f ? 1.0f : alpha_b);
  const float l = -std::log2(a) / 8.0f;
  const float u = cos_theta / (cos_theta + 0.5f * std::sqrt(a));
  const float e = dspbr_fit_detail_dual(q, l, std::sqrt(cos_theta), u);
  return e > 0.0f ? e : 0.0f;
}}
)",
                     kDualParams, coef_list(c["ggx_E"]), al["domain"]["cos_theta"][0].get<double>(), err_line(e["ggx_E"]),
                     al["fit"]["ggx_E_avg_tolerance_units_max"].get<double>(), kAvgParams, coef_list(c["ggx_E_avg"]),
                     fmt::format("{:.8e}", 1.0 / std::log(kAvgBreak1 / kAvgLogLo)), kAvgDegree + 1, kAvgDegree,
                     kAvgDegree - 1, err_line(e["ggx_E_avg"]), kDualParams,
                     coef_list(c["ggx_E5"]), coef_list(c["ggx_E5_avg"]), err_line(e["base_E"]), err_line(e["base_E_avg"]),
                     al["domain"]["alpha_b"][0].get<double>(), err_line(e["sheen_E"]), kDualParams, coef_list(c["sheen_E"]),
                     err_line(e["sheen_ash_E"]), kDualParams, coef_list(c["sheen_ash_E"]));
  }
  if (!fl.is_null()) {
    const auto& a = fl["coefficients"];
    h += fmt::format(R"(
// Far-field flakes, the equivalent GGX roughness: r of the GGX lobe (alpha = r^2) that best fits
// the aggregate of many flakes of roughness r_f (cone BSDF over GGX flake normals, spec "Flakes"):
// r = sqrt(r_f) (a0 + a1 r_f)/(1 + b1 r_f). Domain: flake_roughness in [{}, {}]. Formula vs per-r_f
// fitted r: max abs error {:.2e}. A GGX lobe misses the aggregate's shape by up to {:.2f} (relative L2)
// and its albedo by up to {:.2f}: use dspbr_fit_flake_lobe below for the far-field flake layer.
inline float dspbr_fit_flake_roughness(float flake_roughness) {{
  const float a0 = {:.8e}f, a1 = {:.8e}f, b1 = {:.8e}f;
  return std::sqrt(flake_roughness) * (a0 + a1 * flake_roughness) / (1.0f + b1 * flake_roughness);
}}

)",
                     fl["domain"]["flake_roughness"][0].get<double>(), fl["domain"]["flake_roughness"][1].get<double>(),
                     fl["formula_error"]["max"].get<double>(), fl["ggx_lobe_error_max"].get<double>(),
                     fl["ggx_albedo_error_max"].get<double>(), a[0].get<double>(), a[1].get<double>(), a[2].get<double>());
    h += "\n" + flake_lobe_code(fl);
  }
  return h;
}

}  // namespace dspbr::fit
