#include "dspbr/lutgen/renderer_io.h"

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
#include "dspbr/lutgen/lut_io.h"
#include "dspbr/lutgen/table_image.h"
#include "dspbr/tables/table_registry.h"
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
