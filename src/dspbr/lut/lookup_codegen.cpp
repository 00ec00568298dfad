#include "dspbr/lut/lookup_codegen.h"

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

// Grid-coordinate expression of a warp applied to `v` (alpha: the GgxCos roughness term).
std::string warp_expr(const Warp& w, const std::string& v, const std::string& alpha) {
  switch (w.kind) {
    case WarpKind::Power: {
      std::string u = w.lo == 0 ? fmt::format("clamp({}, 0.0f, 1.0f)", v)
                                : fmt::format("((clamp({}, {}, 1.0f) - {}) / {})", v, flit(w.lo), flit(w.lo),
                                              flit(1.0 - w.lo));
      if (w.p == 1) return u;
      return fmt::format("pow({}, {})", u, flit(w.p));
    }
    case WarpKind::GgxCos:
      return fmt::format("dspbr_lut_ggx_cos_warp({}, {}, {})", v, alpha, flit(w.p));
    case WarpKind::LogRoughness:
      return fmt::format("(log(clamp({}, {}, 1.0f) / {}) * {})", v, flit(w.lo), flit(w.lo),
                         flit(1.0 / std::log(1.0 / w.lo)));
  }
  return "";
}

std::string ident(const WarpedTable& t) { return "dspbr_" + t.name; }

// Catmull-Rom interpolation function of one table: dspbr_lut_interp_<name>(x0[, x1]).
std::string interp_function(const WarpedTable& t) {
  const std::string id = ident(t);
  std::ostringstream o;
  const int n0 = t.axes[0].size;
  if (t.axes.size() == 1) {
    o << fmt::format(
        "float dspbr_lut_interp_{0}(float x) {{\n"
        "  float c = clamp(x, 0.0f, 1.0f) * {1};\n"
        "  int i = int(c);\n"
        "  if (i > {2}) i = {2};\n"
        "  float f = c - float(i);\n"
        "  float p1 = {0}_at(i), p2 = {0}_at(i + 1);\n"
        "  float q0 = {0}_at(i > 0 ? i - 1 : 0), q3 = {0}_at(i + 2 < {3} ? i + 2 : {3} - 1);\n"
        "  float p0 = i > 0 ? q0 : 2.0f * p1 - p2;\n"
        "  float p3 = i + 2 < {3} ? q3 : 2.0f * p2 - p1;\n"
        "  return dspbr_lut_catmull_rom(f, p0, p1, p2, p3);\n"
        "}}\n",
        id, flit(n0 - 1), n0 - 2, n0);
    return o.str();
  }
  const int n1 = t.axes[1].size;
  o << fmt::format(
      "float dspbr_lut_row_{0}(int r, int j, float f) {{\n"
      "  float p1 = {0}_at(r, j), p2 = {0}_at(r, j + 1);\n"
      "  float q0 = {0}_at(r, j > 0 ? j - 1 : 0), q3 = {0}_at(r, j + 2 < {1} ? j + 2 : {1} - 1);\n"
      "  float p0 = j > 0 ? q0 : 2.0f * p1 - p2;\n"
      "  float p3 = j + 2 < {1} ? q3 : 2.0f * p2 - p1;\n"
      "  return dspbr_lut_catmull_rom(f, p0, p1, p2, p3);\n"
      "}}\n",
      id, n1);
  o << fmt::format(
      "float dspbr_lut_interp_{0}(float x0, float x1) {{\n"
      "  float c0 = clamp(x0, 0.0f, 1.0f) * {1};\n"
      "  float c1 = clamp(x1, 0.0f, 1.0f) * {2};\n"
      "  int i = int(c0);\n"
      "  if (i > {3}) i = {3};\n"
      "  int j = int(c1);\n"
      "  if (j > {4}) j = {4};\n"
      "  float f0 = c0 - float(i), f1 = c1 - float(j);\n"
      "  float r1 = dspbr_lut_row_{0}(i, j, f1), r2 = dspbr_lut_row_{0}(i + 1, j, f1);\n"
      "  float q0 = dspbr_lut_row_{0}(i > 0 ? i - 1 : 0, j, f1);\n"
      "  float q3 = dspbr_lut_row_{0}(i + 2 < {5} ? i + 2 : {5} - 1, j, f1);\n"
      "  float r0 = i > 0 ? q0 : 2.0f * r1 - r2;\n"
      "  float r3 = i + 2 < {5} ? q3 : 2.0f * r2 - r1;\n"
      "  return dspbr_lut_catmull_rom(f0, r0, r1, r2, r3);\n"
      "}}\n",
      id, flit(n0 - 1), flit(n1 - 1), n0 - 2, n1 - 2, n0);
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
  o << "// E_m(mu; r): single-scattering GGX albedo.\n"
    << "float dspbr_ggx_E(float cos_theta, float roughness) {\n"
    << "  float r = clamp(roughness, 0.0f, 1.0f);\n"
    << "  return dspbr_lut_interp_dspbr_GGX_E(" << warp_expr(e.axes[0].warp, "r", "") << ", "
    << warp_expr(e.axes[1].warp, "cos_theta", "r * r") << ");\n}\n"
    << "// 1 - E_m,avg(r), stored as a logarithm (it vanishes like r^4).\n"
    << "float dspbr_ggx_E_avg_missing(float roughness) {\n"
    << "  return exp(dspbr_lut_interp_dspbr_GGX_E_avg(" << warp_expr(ea.axes[0].warp, "roughness", "") << "));\n}\n"
    << "float dspbr_ggx_E_avg(float roughness) { return 1.0f - dspbr_ggx_E_avg_missing(roughness); }\n"
    << "// Schlick moment B = Integral M_r (1 - v.h)^5 mu_l dl = beta E_m; stored beta - (1 - mu)^5.\n"
    << "float dspbr_lut_ggx_B(float cos_theta, float roughness) {\n"
    << "  float r = clamp(roughness, 0.0f, 1.0f);\n"
    << "  float mu = clamp(cos_theta, 0.0f, 1.0f);\n"
    << "  float m = 1.0f - mu, m2 = m * m;\n"
    << "  float beta = m2 * m2 * m + dspbr_lut_interp_dspbr_GGX_beta(" << warp_expr(b.axes[0].warp, "r", "") << ", "
    << warp_expr(b.axes[1].warp, "mu", "r * r") << ");\n"
    << "  return beta * dspbr_ggx_E(mu, r);\n}\n"
    << "// F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg = 20/21 f0 + 1/21 f90 (spec eq. multiscatter).\n"
    << "float dspbr_fresnel_ms(float f0, float f90, float e_avg) {\n"
    << "  float fa = f0 * (20.0f / 21.0f) + f90 * (1.0f / 21.0f);\n"
    << "  return fa * fa * e_avg / (1.0f - fa * (1.0f - e_avg));\n}\n"
    << "// E(mu; r, f0) = f0 E_m + (1 - f0) B + F_ms(f0, 1; E_m,avg) (1 - E_m) (spec \"Energy Preservation\").\n"
    << "float dspbr_base_E(float cos_theta, float roughness, float f0) {\n"
    << "  float em = dspbr_ggx_E(cos_theta, roughness);\n"
    << "  float fms = dspbr_fresnel_ms(f0, 1.0f, dspbr_ggx_E_avg(roughness));\n"
    << "  return f0 * em + (1.0f - f0) * dspbr_lut_ggx_B(cos_theta, roughness) + fms * (1.0f - em);\n}\n"
    << "// E_avg(r, f0) = f0 E_m,avg + (1 - f0) B_avg + F_ms (1 - E_m,avg).\n"
    << "float dspbr_base_E_avg(float roughness, float f0) {\n"
    << "  float missing = dspbr_ggx_E_avg_missing(roughness);\n"
    << "  float b_avg = dspbr_lut_interp_dspbr_GGX_B_avg(" << warp_expr(ba.axes[0].warp, "roughness", "") << ");\n"
    << "  return f0 * (1.0f - missing) + (1.0f - f0) * b_avg + dspbr_fresnel_ms(f0, 1.0f, 1.0f - missing) * missing;\n}\n"
    << "// E_b(mu; alpha_b) of the main sheen (Charlie D_b, the spec's Lambda fit).\n"
    << "float dspbr_sheen_E(float cos_theta, float alpha_b) {\n"
    << "  return dspbr_lut_interp_dspbr_Sheen_E(" << warp_expr(s.axes[0].warp, "alpha_b", "") << ", "
    << warp_expr(s.axes[1].warp, "cos_theta", "") << ");\n}\n"
    << "// E_b(mu; alpha_b) of the alternative sheen (visibility 1 / (4 (mu_v + mu_l - mu_v mu_l))).\n"
    << "float dspbr_sheen_ash_E(float cos_theta, float alpha_b) {\n"
    << "  return dspbr_lut_interp_dspbr_Sheen_ash_E(" << warp_expr(sa.axes[0].warp, "alpha_b", "") << ", "
    << warp_expr(sa.axes[1].warp, "cos_theta", "") << ");\n}\n"
    << "// M_r,ms / F_ms = (1 - E_m(mu_v)) (1 - E_m(mu_l)) / (pi (1 - E_m,avg)); 0 when 1 - E_m,avg <= 1e-9.\n"
    << "float dspbr_ms_lobe(float cos_v, float cos_l, float roughness) {\n"
    << "  float missing = dspbr_ggx_E_avg_missing(roughness);\n"
    << "  if (missing <= 1e-9f) return 0.0f;\n"
    << "  float mv = clamp(1.0f - dspbr_ggx_E(cos_v, roughness), 0.0f, 1.0f);\n"
    << "  float ml = clamp(1.0f - dspbr_ggx_E(cos_l, roughness), 0.0f, 1.0f);\n"
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
    << "float dspbr_sheen_layer_scale(float cos_v, float cos_l, float alpha_b, float rho_hat) {\n"
    << "  float ev = clamp(dspbr_sheen_E(cos_v, alpha_b), 0.0f, 1.0f);\n"
    << "  float el = clamp(dspbr_sheen_E(cos_l, alpha_b), 0.0f, 1.0f);\n"
    << "  return clamp(min(1.0f - rho_hat * ev, 1.0f - rho_hat * el), 0.0f, 1.0f);\n}\n"
    << "float dspbr_sheen_ash_layer_scale(float cos_v, float cos_l, float alpha_b, float rho_hat) {\n"
    << "  float ev = clamp(dspbr_sheen_ash_E(cos_v, alpha_b), 0.0f, 1.0f);\n"
    << "  float el = clamp(dspbr_sheen_ash_E(cos_l, alpha_b), 0.0f, 1.0f);\n"
    << "  return clamp(min(1.0f - rho_hat * ev, 1.0f - rho_hat * el), 0.0f, 1.0f);\n}\n";
  return o.str();
}

const char* kHelpers =
    "float dspbr_lut_catmull_rom(float f, float p0, float p1, float p2, float p3) {\n"
    "  float f2 = f * f, f3 = f2 * f;\n"
    "  return 0.5f * ((-f3 + 2.0f * f2 - f) * p0 + (3.0f * f3 - 5.0f * f2 + 2.0f) * p1 +\n"
    "                 (-3.0f * f3 + 4.0f * f2 + f) * p2 + (f3 - f2) * p3);\n"
    "}\n"
    "// ggx_cos warp: x = t^p, t = mu / (mu + alpha sqrt(1 - mu^2)) (t = 1 when alpha = 0).\n"
    "float dspbr_lut_ggx_cos_warp(float cos_theta, float alpha, float p) {\n"
    "  float mu = clamp(cos_theta, 0.0f, 1.0f);\n"
    "  float d = mu + alpha * sqrt(max(1.0f - mu * mu, 0.0f));\n"
    "  float t = d > 0.0f ? mu / d : 1.0f;\n"
    "  return pow(t, p);\n"
    "}\n";

// GLSL body text -> C: math functions, casts, static inline.
std::string to_c(const std::string& glsl) {
  std::string s = glsl;
  const std::pair<const char*, const char*> fns[] = {
      {"clamp", "dspbr_lut_clampf"}, {"min", "fminf"}, {"max", "fmaxf"}, {"sqrt", "sqrtf"},
      {"pow", "powf"},            {"exp", "expf"},  {"log", "logf"}};
  for (const auto& [from, to] : fns) s = std::regex_replace(s, std::regex(std::string("\\b") + from + "\\("), std::string(to) + "(");
  s = std::regex_replace(s, std::regex("\\bfloat\\("), "(float)(");
  s = std::regex_replace(s, std::regex("\\bint\\("), "(int)(");
  s = std::regex_replace(s, std::regex("(^|\\n)float "), "$1static inline float ");
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
  if (t.name == "GGX_beta") s += ", stored beta - (1 - mu)^5";
  return s + "\n";
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

std::string lookup_code(const RendererLuts& L, LookupDialect dialect, const std::string& provenance) {
  std::ostringstream o;
  const size_t floats = L.stored_values();
  const char* names[] = {"GGX_E", "GGX_beta", "GGX_E_avg", "GGX_B_avg", "Sheen_E", "Sheen_ash_E"};
  o << "// " << lookup_file_name(dialect)
    << ": DSPBR 2025x energy-compensation lookups, renderer layout (docs/luts.md).\n"
    << "// Generated by `dspbr lut`; do not edit. " << provenance << "\n"
    << "// Tables (endpoint grids x_i = i / (N - 1) over warped coordinates, Catmull-Rom interpolation\n"
    << "// with linear extrapolation beyond the ends; row-major, fastest axis last):\n";
  int binding = 0;
  for (const char* n : names) o << table_comment(*L.table(n));
  if (dialect != LookupDialect::C) {
    o << "// With DSPBR_LOOKUP_TEXTURES defined, the tables are read from single-channel float\n"
      << "// textures (R32F; width = fastest axis, height = slowest axis or 1), fetched with texelFetch /\n"
      << "// Load at integer texel coordinates (no filtering, no sampler state needed):\n";
    for (const char* n : names) {
      const WarpedTable& t = *L.table(n);
      o << "//   " << ident(t) << "_tex  binding " << binding++ << "  " << t.axes.back().size << " x "
        << (t.axes.size() == 2 ? t.axes[0].size : 1) << "\n";
    }
    o << "// (DSPBR_LOOKUP_BINDING_BASE shifts the GLSL bindings; DSPBR_LOOKUP_REGISTER_SPACE selects the\n"
      << "// HLSL space.) Without it, the tables are constant arrays.\n";
  }
  if (dialect == LookupDialect::C) {
    o << "#ifndef DSPBR_LOOKUP_H\n#define DSPBR_LOOKUP_H\n#include <math.h>\n\n";
  } else {
    o << "#ifndef DSPBR_LOOKUP_INCLUDED\n#define DSPBR_LOOKUP_INCLUDED\n\n";
  }
  o << "#define DSPBR_LOOKUP_FLOATS " << floats << "\n\n";
  if (dialect == LookupDialect::C) {
    o << "static inline float dspbr_lut_clampf(float x, float lo, float hi) { return x < lo ? lo : (x > hi ? hi : x); }\n";
    for (const char* n : names) {
      const WarpedTable& t = *L.table(n);
      o << "static const float " << ident(t) << "_table[" << t.size() << "] = {";
      emit_values(o, t);
      o << "};\n";
      if (t.axes.size() == 2)
        o << fmt::format("static inline float {0}_at(int r, int c) {{ return {0}_table[r * {1} + c]; }}\n", ident(t),
                         t.axes[1].size);
      else
        o << fmt::format("static inline float {0}_at(int i) {{ return {0}_table[i]; }}\n", ident(t));
    }
  } else {
    const bool glsl = dialect == LookupDialect::Glsl;
    o << "#ifndef DSPBR_TABLE\n";
    if (glsl) o << "#define DSPBR_TABLE(name, n) const float name[n] = float[n](\n#define DSPBR_TABLE_END );\n";
    else o << "#define DSPBR_TABLE(name, n) static const float name[n] = {\n#define DSPBR_TABLE_END };\n";
    o << "#endif\n";
    if (glsl) o << "#ifndef DSPBR_LOOKUP_BINDING_BASE\n#define DSPBR_LOOKUP_BINDING_BASE 0\n#endif\n";
    else o << "#ifndef DSPBR_LOOKUP_REGISTER_SPACE\n#define DSPBR_LOOKUP_REGISTER_SPACE space0\n#endif\n";
    o << "#ifdef DSPBR_LOOKUP_TEXTURES\n";
    binding = 0;
    for (const char* n : names) {
      const WarpedTable& t = *L.table(n);
      const std::string id = ident(t);
      if (glsl) {
        o << "layout(binding = DSPBR_LOOKUP_BINDING_BASE + " << binding << ") uniform sampler2D " << id << "_tex;\n";
        if (t.axes.size() == 2)
          o << "float " << id << "_at(int r, int c) { return texelFetch(" << id << "_tex, ivec2(c, r), 0).r; }\n";
        else
          o << "float " << id << "_at(int i) { return texelFetch(" << id << "_tex, ivec2(i, 0), 0).r; }\n";
      } else {
        o << "Texture2D<float> " << id << "_tex : register(t" << binding << ", DSPBR_LOOKUP_REGISTER_SPACE);\n";
        if (t.axes.size() == 2)
          o << "float " << id << "_at(int r, int c) { return " << id << "_tex.Load(int3(c, r, 0)); }\n";
        else
          o << "float " << id << "_at(int i) { return " << id << "_tex.Load(int3(i, 0, 0)); }\n";
      }
      ++binding;
    }
    o << "#else\n";
    for (const char* n : names) {
      const WarpedTable& t = *L.table(n);
      const std::string id = ident(t);
      o << "DSPBR_TABLE(" << id << "_table, " << t.size() << ")";
      emit_values(o, t);
      o << "\nDSPBR_TABLE_END\n";
      if (t.axes.size() == 2)
        o << fmt::format("float {0}_at(int r, int c) {{ return {0}_table[r * {1} + c]; }}\n", id, t.axes[1].size);
      else
        o << fmt::format("float {0}_at(int i) {{ return {0}_table[i]; }}\n", id);
    }
    o << "#endif\n";
  }
  std::string body = kHelpers;
  for (const char* n : names) body += interp_function(*L.table(n));
  body += api_functions(L);
  o << "\n" << (dialect == LookupDialect::C ? to_c(body) : body);
  o << "\n#endif\n";
  return o.str();
}

}  // namespace dspbr
