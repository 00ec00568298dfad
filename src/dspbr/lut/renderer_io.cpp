#include "dspbr/lut/renderer_io.h"

#include "dspbr/io/json_write.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "dspbr/io/atomic_file.h"
#include "dspbr/io/json_fields.h"
#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"
#include "dspbr/lut/lut_io.h"
#include "dspbr/lut/table_image.h"
#include "dspbr/lut/table_registry.h"
#include "dspbr/version.h"

namespace dspbr {

namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

const char* warp_kind_name(WarpKind k) {
  switch (k) {
    case WarpKind::Power: return "power";
    case WarpKind::GgxCos: return "ggx_cos";
    case WarpKind::LogRoughness: return "log";
    case WarpKind::GlassIor: return "glass_ior";
  }
  return "";
}

const char* encoding_name(Encoding e) { return e == Encoding::LogOneMinus ? "log_one_minus" : "value"; }

std::string axes_text(const WarpedTable& t) {
  std::string s;
  for (size_t d = 0; d < t.axes.size(); ++d)
    s += (d ? "; " : "") +
         std::string(d + 1 == t.axes.size() ? "columns: " : (d + 2 == t.axes.size() ? "rows: " : "row blocks: ")) +
         t.axes[d].name + "[" +
         std::to_string(t.axes[d].size) + "] " + t.axes[d].warp.describe();
  return s;
}

std::string decode_text(const WarpedTable& t) {
  std::string s = t.encoding == Encoding::LogOneMinus ? "quantity = 1 - exp(stored)" : "quantity = stored";
  if (is_lut(t.name, Lut::GgxBeta)) s = "beta = (1 - cos_theta)^5 + stored; B = beta E_m";
  return s;
}

}  // namespace

std::string renderer_json_text(const RendererLuts& luts, const LutOptions& opt, int scale) {
  ojson j;
  j["format"] = "dspbr_renderer_luts";
  j["version"] = kTableFileVersion;
  j["model"] = "DSPBR 2025x";
  j["generator"] = "dspbr lut";
  if (!opt.command.empty()) j["dspbr_version"] = project_version(), j["command"] = opt.command;
  j["layout"] = "renderer";
  j["scale"] = scale;
  j["stored_values"] = luts.stored_values();
  if (luts.has_glass()) j["glass_stored_values"] = luts.glass_stored_values();
  j["grid"] = "endpoint, x_i = i / (N - 1) of the warped coordinate";
  j["interpolation"] = "catmull-rom, linear extrapolation beyond the ends";
  const IntegratorSettings s = lut_settings(lut_name(Lut::GgxE), opt);
  j["integrator"] = {{"name", integrator_name(s.integrator)},
                     {"max_samples_per_cell", s.samples},
                     {"target_std_error", s.target_error},
                     {"randomizations", s.randomizations},
                     {"seed", s.seed}};
  if (luts.has_glass()) {
    const IntegratorSettings g = lut_settings(lut_name(Lut::GlassE), opt);
    j["glass_integrator"] = {{"name", integrator_name(g.integrator)}, {"target_error", g.target_error}};
  }
  ojson jt = ojson::object();
  for (const char* name : luts.held_names()) {
    const WarpedTable& t = *luts.table(name);
    ojson e;
    ojson axes = ojson::array();
    for (const WarpedAxis& a : t.axes)
      axes.push_back({{"name", a.name},
                      {"size", a.size},
                      {"warp", {{"kind", warp_kind_name(a.warp.kind)}, {"p", a.warp.p}, {"lo", a.warp.lo}}}});
    e["axes"] = axes;
    e["encoding"] = encoding_name(t.encoding);
    e["decode"] = decode_text(t);
    double max_err = 0;
    for (double x : t.errors) max_err = std::max(max_err, x);
    e["max_error"] = max_err;
    e["values"] = t.values;
    e["errors"] = t.errors;
    jt[name] = e;
  }
  j["tables"] = jt;
  return json_text(j, 1, "renderer table file") + "\n";
}

RendererLuts read_renderer_json(const std::string& path) {
  return read_renderer_json_value(read_json_file(path, "table file", limits::kTableFileBytes), path);
}

RendererLuts read_renderer_json_text(std::string_view text, const std::string& name) {
  return read_renderer_json_value(parse_json(text, name, "table file"), name);
}

RendererLuts read_renderer_json_value(const nlohmann::json& j, const std::string& path) {
  namespace jf = json_fields;
  RendererLuts out;
  try {
    if (!j.is_object() || j.value("format", nlohmann::json()) != "dspbr_renderer_luts")
      throw std::runtime_error("not a renderer table file (missing \"format\": \"dspbr_renderer_luts\")");
    require_table_file_version(j);
    const auto& jt = jf::object_member(j, "tables", "");
    for (const auto& item : jt.items())
      if (find_lut(item.key(), kRendererLayout) == nullptr)
        throw std::runtime_error("tables." + item.key() + ": unknown table (known: " + lut_names_list(kRendererLayout) +
                                 ")");
    const RendererLuts expected_axes = [] {
      RendererLuts r;
      for (const char* n : RendererLuts::names()) r.table(n)->axes = renderer_default_axes(n);
      for (const char* n : RendererLuts::glass_names()) r.table(n)->axes = renderer_default_axes(n);
      return r;
    }();
    // The glass tables are optional, as a set.
    std::vector<const char*> wanted = RendererLuts::names();
    size_t glass_present = 0;
    for (const char* n : RendererLuts::glass_names()) glass_present += jt.contains(n) ? 1 : 0;
    if (glass_present > 0)
      wanted.insert(wanted.end(), RendererLuts::glass_names().begin(), RendererLuts::glass_names().end());
    for (const char* name : wanted) {
      if (!jt.contains(name))
        throw std::runtime_error(std::string("table ") + name + " is missing" +
                                 (glass_present > 0 && require_lut(name, kRendererLayout).glass
                                      ? " (the Glass tables come as a set of four)"
                                      : ""));
      const std::string where = std::string("tables.") + name;
      const auto& e = jf::object_member(jt, name, "tables");
      WarpedTable& t = *out.table(name);
      t.name = name;
      const auto& ref = expected_axes.table(name)->axes;
      const auto& ja = jf::array_member(e, "axes", where);
      if (ja.size() != ref.size())
        throw std::runtime_error(where + ".axes must hold " + std::to_string(ref.size()) + " axes");
      size_t cells = 1;  // axis sizes within limits.h: the product cannot overflow
      for (size_t d = 0; d < ref.size(); ++d) {
        const std::string at = jf::index_path(where + ".axes", d);
        WarpedAxis a;
        a.name = jf::string_member(ja[d], "name", at);
        if (a.name != ref[d].name) throw std::runtime_error(at + ".name must be " + ref[d].name);
        a.size = int(jf::integer_member(ja[d], "size", at, 2, limits::kTableAxisSize));
        const auto& jw = jf::object_member(ja[d], "warp", at);
        const std::string kind = jf::string_member(jw, "kind", at + ".warp");
        a.warp.p = jf::number_member(jw, "p", at + ".warp");
        a.warp.lo = jf::number_member(jw, "lo", at + ".warp");
        if (kind == "power") a.warp.kind = WarpKind::Power;
        else if (kind == "ggx_cos") a.warp.kind = WarpKind::GgxCos;
        else if (kind == "log") a.warp.kind = WarpKind::LogRoughness;
        else if (kind == "glass_ior") a.warp.kind = WarpKind::GlassIor;
        else throw std::runtime_error(at + ".warp.kind: unknown warp '" + kind + "'");
        if (a.warp.kind == WarpKind::GgxCos && !(d >= 1 && ref[d - 1].name == "roughness"))
          throw std::runtime_error(std::string(name) + ": the ggx_cos warp needs a roughness axis before it");
        if (a.warp.kind == WarpKind::GlassIor && !(d == 0 && ref.back().name == "cos_theta"))
          throw std::runtime_error(std::string(name) + ": the glass_ior warp needs a cos_theta axis after it");
        if (!(a.warp.p > 0 && a.warp.p <= 16) || !(a.warp.lo >= 0 && a.warp.lo < 1) ||
            (a.warp.kind == WarpKind::LogRoughness && !(a.warp.lo > 0)) ||
            (a.warp.kind == WarpKind::GlassIor && !(a.warp.p >= 1e-3)))  // k mu^2 stays >= 1e-15
          throw std::runtime_error(at + " has a bad warp");
        cells *= size_t(a.size);
        if (cells > limits::kTableCells)
          throw std::runtime_error(where + ": more than " + std::to_string(limits::kTableCells) + " cells");
        t.axes.push_back(a);
      }
      // GGX_E_avg stores ln(1 - E_m,avg) (the lookups decode it so), every other table the value.
      const std::string enc = jf::string_member(e, "encoding", where);
      const std::string want = is_lut(name, Lut::GgxEAvg) ? "log_one_minus" : "value";
      if (enc != want) throw std::runtime_error(where + ".encoding must be '" + want + "', not '" + enc + "'");
      t.encoding = enc == "log_one_minus" ? Encoding::LogOneMinus : Encoding::Value;
      t.values = jf::numbers_member(e, "values", where, cells);
      if (e.contains("errors")) t.errors = jf::numbers_member(e, "errors", where, cells);
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("'" + path + "': malformed table file (" + std::string(e.what()) + ")");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("'" + path + "': " + e.what());
  }
  return out;
}

std::vector<float> split_sum_pixels(const RendererLuts& luts, int size) {
  std::vector<float> px(size_t(size) * size_t(size) * 3);
  for (int i = 0; i < size; ++i) {
    const double r = (i + 0.5) / size;
    for (int k = 0; k < size; ++k) {
      const double mu = (k + 0.5) / size;
      float* p = &px[(size_t(i) * size_t(size) + size_t(k)) * 3];
      p[0] = float(luts.E_m(mu, r));
      p[1] = float(luts.B(mu, r));
      p[2] = float(luts.E_sheen(mu, r * r));
    }
  }
  return px;
}

void write_renderer_images(const RendererLuts& luts, const std::string& dir, bool half, int split_sum_size,
                           const std::string& command) {
  for (const char* name : luts.held_names()) {
    const WarpedTable& t = *luts.table(name);
    // Rank 3: the planes of the slowest axis stacked vertically (height = n0 n1).
    const int width = t.axes.back().size, height = int(t.size() / size_t(width));
    std::vector<float> px(t.values.begin(), t.values.end());
    ImageAttributes attrs{
        {"dspbr:table", name},
        {"dspbr:model", std::string(name).rfind("Glass_", 0) == 0 ? "beyond DSPBR 2025x (rough-glass compensation)"
                                                                   : "DSPBR 2025x"},
        {"dspbr:layout", "renderer, version 1"},
        {"dspbr:axes", axes_text(t)},
        {"dspbr:grid", "endpoint: sample i of N at warped coordinate i / (N - 1)"},
        {"dspbr:interpolation", "catmull-rom, linear extrapolation beyond the ends"},
        {"dspbr:encoding", encoding_name(t.encoding)},
        {"dspbr:decode", decode_text(t)}};
    if (!command.empty()) attrs.push_back({"dspbr:command", command});
    write_table_image((fs::path(dir) / (std::string(name) + ".exr")).string(), px, width, height, 1,
                      half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT, attrs);
    write_table_png((fs::path(dir) / (std::string(name) + ".png")).string(), t.values, width, height, attrs);
  }
  const std::vector<float> ss = split_sum_pixels(luts, split_sum_size);
  ImageAttributes attrs{
      {"dspbr:table", "split_sum"},
      {"dspbr:model", "DSPBR 2025x"},
      {"dspbr:axes", "rows: roughness[" + std::to_string(split_sum_size) + "] r, columns: cos_theta[" +
                         std::to_string(split_sum_size) + "], cell-centred x_i = (i + 0.5) / N"},
      {"dspbr:channels", "R: E_m = A (f0 scale), G: B = Schlick moment (bias), B: main sheen E_b at alpha_b = r^2"},
      {"dspbr:usage", "specular IBL: prefiltered radiance * (f0 (A - B) + f90 B), i.e. scale A - B, bias B"}};
  if (!command.empty()) attrs.push_back({"dspbr:command", command});
  write_table_image((fs::path(dir) / "dspbr_split_sum.exr").string(), ss, split_sum_size, split_sum_size, 3,
                    half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT, attrs);
  write_table_image((fs::path(dir) / "dspbr_split_sum.png").string(), ss, split_sum_size, split_sum_size, 3,
                    OIIO::TypeDesc::UINT16, attrs);
}

}  // namespace dspbr
