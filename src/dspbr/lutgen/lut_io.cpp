#include "dspbr/lutgen/lut_io.h"

#include "dspbr/io/json_write.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

#include "dspbr/io/atomic_file.h"
#include "dspbr/io/json_fields.h"
#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"
#include "dspbr/lutgen/table_image.h"
#include "dspbr/version.h"

namespace dspbr {

namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

std::string sampling_name(const std::string& table, Integrator i) {
  if (i == Integrator::Mc) return "uniform hemisphere (Pcg32)";
  if (i == Integrator::Quad)
    return "adaptive Gauss-Kronrod over the microfacet normal, azimuth split where a term switches";
  if (table.rfind("Sheen", 0) == 0) return "mixture of uniform hemisphere and Charlie half-vector sampling (Owen-scrambled Sobol')";
  return "GGX visible normals, Heitz 2018 (Owen-scrambled Sobol')";
}

// "0.03" style f0 labels for the Base_E slices: two decimals, more if needed for unique names.
std::vector<std::string> f0_labels(const Axis& a) {
  for (int digits = 2; digits < 17; ++digits) {
    std::vector<std::string> out;
    std::set<std::string> seen;
    for (int i = 0; i < a.size; ++i) {
      out.push_back(fmt::format("{:.{}f}", a.coord(i), digits));
      seen.insert(out.back());
    }
    if (seen.size() == out.size()) return out;
  }
  throw std::logic_error("f0 labels: cannot make unique names");
}

// A float literal that round-trips (max_digits10 = 9 significant digits) and is valid C/C++.
std::string float_literal(float v) {
  std::string s = fmt::format("{:.9g}", v);
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s + "f";
}

// Nested initializer of t.values from `offset` for axes level.., one innermost row per line.
void emit_braces(std::ostringstream& o, const Table& t, size_t level, size_t offset) {
  size_t stride = 1;
  for (size_t d = level + 1; d < t.axes.size(); ++d) stride *= size_t(t.axes[d].size);
  const int n = t.axes[level].size;
  o << "{";
  for (int i = 0; i < n; ++i) {
    if (i) o << (level + 1 == t.axes.size() ? ", " : ",\n" + std::string(level + 1, ' '));
    if (level + 1 == t.axes.size()) {
      const float v = float(t.values[offset + size_t(i)]);
      const bool wrap = is_lut(t.name, Lut::SheenAshE) && v > 1.0f;
      o << (wrap ? "PBRLUT_ASH(" + float_literal(v) + ")" : float_literal(v));
    } else {
      emit_braces(o, t, level + 1, offset + size_t(i) * stride);
    }
  }
  o << "}";
}

// The table's axes and conventions as image attributes (a file explains itself).
ImageAttributes table_attributes(const Table& t, const std::string& command) {
  std::string axes;
  for (size_t d = 0; d < t.axes.size(); ++d) {
    const Axis& a = t.axes[d];
    axes += (d ? ", " : "") + a.name + "[" + std::to_string(a.size) + "] on [" + fmt::format("{:g}", a.lo) + ", " +
            fmt::format("{:g}", a.hi) + "]";
  }
  ImageAttributes attrs{{"dspbr:table", t.name},
          {"dspbr:model", "DSPBR 2025x"},
          {"dspbr:layout", "published, version 1"},
          {"dspbr:axes", axes + " (slowest to fastest; columns = the fastest)"},
          {"dspbr:grid", t.axes.empty() || t.axes[0].kind == GridKind::CellCentred
                             ? "cell-centred: sample i of N at (i + 0.5) / N"
                             : "endpoint: sample i of N at i / (N - 1)"},
          {"dspbr:interpolation", "multilinear, clamp to edge"},
          {"dspbr:encoding", "value"}};
  if (!command.empty()) attrs.push_back({"dspbr:command", command});
  return attrs;
}

// How a 3D table's slices are stacked in its atlas image (EXR and PNG).
std::pair<std::string, std::string> atlas_attribute(const Table& t) {
  return {"dspbr:atlas", fmt::format("{} slices of {}x{} stacked vertically: row = {}_index * {} + {}_index",
                                     t.axes[0].size, t.axes[2].size, t.axes[1].size, t.axes[0].name,
                                     t.axes[1].size, t.axes[1].name)};
}

}  // namespace

std::vector<std::string> lut_exr_names(const Table& t) {
  if (is_lut(t.name, Lut::BaseE)) {
    std::vector<std::string> names;
    for (const std::string& l : f0_labels(t.axes[0])) names.push_back("Base_" + l + "_E.exr");
    return names;
  }
  return {t.name + ".exr"};
}

double write_lut_exrs(const Table& t, const std::string& dir, bool half, const std::string& command) {
  const std::vector<std::string> names = lut_exr_names(t);
  const int width = t.axes.back().size;
  const size_t per_image = t.size() / names.size();
  const int height = int(per_image / size_t(width));
  double max_rounding = 0;
  for (size_t k = 0; k < names.size(); ++k) {
    if (names[k] == lut_atlas_name(t)) continue;  // a 3D table without slice images: the atlas below
    std::vector<float> px(per_image), stored(per_image);
    for (size_t i = 0; i < per_image; ++i) px[i] = float(t.values[k * per_image + i]);
    stored = px;
    if (half) {  // round trip through OIIO's half conversion: what the file will hold
      std::vector<uint16_t> h(per_image);
      OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, px.data(), OIIO::TypeDesc::HALF, h.data(), int(per_image));
      OIIO::convert_pixel_values(OIIO::TypeDesc::HALF, h.data(), OIIO::TypeDesc::FLOAT, stored.data(), int(per_image));
    }
    for (size_t i = 0; i < per_image; ++i)
      max_rounding = std::max(max_rounding, std::abs(double(stored[i]) - t.values[k * per_image + i]));
    ImageAttributes attrs = table_attributes(t, command);
    if (names.size() > 1) attrs.push_back({"dspbr:slice", t.axes[0].name + " = " + fmt::format("{:.9g}", t.axes[0].coord(int(k)))});
    write_table_image((fs::path(dir) / names[k]).string(), px, width, height, 1,
                      half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT, attrs);
  }
  if (t.axes.size() == 3) {  // one 3D-ready atlas: the slices stacked vertically
    std::vector<float> px(t.values.begin(), t.values.end());
    for (size_t i = 0; i < px.size(); ++i) {  // what the file holds (half: after the round trip)
      float st = px[i];
      if (half) {
        uint16_t h16;
        OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, &px[i], OIIO::TypeDesc::HALF, &h16, 1);
        OIIO::convert_pixel_values(OIIO::TypeDesc::HALF, &h16, OIIO::TypeDesc::FLOAT, &st, 1);
      }
      max_rounding = std::max(max_rounding, std::abs(double(st) - t.values[i]));
    }
    ImageAttributes attrs = table_attributes(t, command);
    attrs.push_back(atlas_attribute(t));
    write_table_image((fs::path(dir) / lut_atlas_name(t)).string(), px, width, height * int(names.size()), 1,
                      half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT, attrs);
  }
  return max_rounding;
}

std::string lut_atlas_name(const Table& t) { return t.axes.size() == 3 ? t.name + ".exr" : ""; }

std::vector<std::string> lut_png_names(const Table& t) { return {t.name + ".png"}; }

double write_lut_png(const Table& t, const std::string& dir, const std::string& command) {
  const int width = t.axes.back().size;
  const int height = int(t.size() / size_t(width));
  ImageAttributes attrs = table_attributes(t, command);
  if (t.axes.size() == 3) attrs.push_back(atlas_attribute(t));
  return write_table_png((fs::path(dir) / lut_png_names(t)[0]).string(), t.values, width, height, attrs);
}

std::vector<float> read_lut_exr(const std::string& path, int* width, int* height) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error("cannot read '" + path + "': " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const int c = std::max(0, spec.channelindex("Y"));
  std::vector<float> px(size_t(spec.width) * size_t(spec.height));
  if (!in->read_image(0, 0, c, c + 1, OIIO::TypeDesc::FLOAT, px.data()))
    throw std::runtime_error("cannot read '" + path + "': " + in->geterror());
  *width = spec.width;
  *height = spec.height;
  return px;
}

std::string lut_header_text(const std::vector<Table>& tables, const LutOptions& opt) {
  std::ostringstream o;
  o << "// pbrlut.hpp: energy-compensation tables of the Enterprise PBR Shading Model (DSPBR 2025x),\n"
       "// generated by `dspbr lut` (see docs/luts.md for definitions and conventions).\n"
       "// Grid: " << (opt.grid == GridKind::CellCentred ? "cell-centred, x_i = (i + 0.5) / N" : "endpoint, x_i = i / (N - 1)")
    << "; roughness axes hold r (alpha = r^2),\n"
       "// sheen rows hold alpha_b = r_b^2. Index order [slowest]...[cos_theta] as in the EXRs.\n"
       "// Declarations are always visible; define PBRLUT_IMPLEMENTATION in exactly one translation\n"
       "// unit before including this file to get the definitions.\n";
  const bool has_ash = std::any_of(tables.begin(), tables.end(), [](const Table& t) { return is_lut(t.name, Lut::SheenAshE); });
  if (has_ash)
    o << "// Sheen_ash_E keeps its unclamped values (some exceed 1: the alternative sheen gains energy\n"
         "// at low roughness and grazing angles). Define PBRLUT_CLAMP_SHEEN_ASH_E before including to\n"
         "// clamp them to 1 like the published header.\n";
  o << "#ifndef DSPBR_PBRLUT_HPP\n#define DSPBR_PBRLUT_HPP\n\n";
  auto dims = [](const Table& t) {
    std::string s;
    for (const Axis& a : t.axes) s += "[" + std::to_string(a.size) + "]";
    return s;
  };
  for (const Table& t : tables) {
    std::string axes;
    for (const Axis& a : t.axes) axes += (axes.empty() ? "" : ", ") + a.name;
    o << "// " << t.name << dims(t) << ": [" << axes << "]\n";
    o << "extern const float " << t.name << dims(t) << ";\n";
    o << "extern const int " << t.name << "_size[" << t.axes.size() << "];\n";
  }
  o << "\n#ifdef PBRLUT_IMPLEMENTATION\n";
  if (has_ash)
    o << "#ifdef PBRLUT_CLAMP_SHEEN_ASH_E\n#define PBRLUT_ASH(x) 1.0f\n#else\n#define PBRLUT_ASH(x) x\n#endif\n";
  for (const Table& t : tables) {
    o << "\nconst int " << t.name << "_size[" << t.axes.size() << "] = {";
    for (size_t d = 0; d < t.axes.size(); ++d) o << (d ? ", " : "") << t.axes[d].size;
    o << "};\n";
    o << "const float " << t.name << dims(t) << " = ";
    emit_braces(o, t, 0, 0);
    o << ";\n";
  }
  if (has_ash) o << "#undef PBRLUT_ASH\n";
  o << "#endif  // PBRLUT_IMPLEMENTATION\n\n#endif  // DSPBR_PBRLUT_HPP\n";
  return o.str();
}

std::string lut_json_text(const std::vector<Table>& tables, const LutOptions& opt) {
  ojson j;
  j["format"] = "dspbr_luts";
  j["version"] = kTableFileVersion;
  j["model"] = "DSPBR 2025x";
  j["generator"] = "dspbr lut";
  if (!opt.command.empty()) j["dspbr_version"] = project_version(), j["command"] = opt.command;
  j["grid"] = grid_kind_name(opt.grid);
  j["seed"] = opt.seed;
  j["notes"] = "values: directional/average albedos (docs/luts.md); errors: per-cell standard error (1 sigma)";
  ojson jt = ojson::object();
  for (const Table& t : tables) {
    ojson e;
    ojson axes = ojson::array();
    for (const Axis& a : t.axes)
      axes.push_back({{"name", a.name}, {"size", a.size}, {"lo", a.lo}, {"hi", a.hi}, {"grid", grid_kind_name(a.kind)}});
    e["axes"] = axes;
    const IntegratorSettings s = lut_settings(t.name, opt);
    e["integrator"] = {{"name", integrator_name(s.integrator)},
                       {"sampling", sampling_name(t.name, s.integrator)},
                       {"max_samples_per_cell", s.samples},
                       {"target_std_error", s.target_error},
                       {"randomizations", s.randomizations},
                       {"seed", s.seed}};
    double max_err = 0, max_v = -1e300, min_v = 1e300;
    for (double x : t.errors) max_err = std::max(max_err, x);
    for (double x : t.values) { max_v = std::max(max_v, x); min_v = std::min(min_v, x); }
    e["max_error"] = max_err;
    e["min_value"] = min_v;
    e["max_value"] = max_v;
    std::vector<std::string> files = lut_exr_names(t);
    if (!lut_atlas_name(t).empty()) files.push_back(lut_atlas_name(t));
    for (const std::string& f : lut_png_names(t)) files.push_back(f);
    e["files"] = files;
    e["values"] = t.values;
    e["errors"] = t.errors;
    jt[t.name] = e;
  }
  j["tables"] = jt;
  return json_text(j, 1, "table file") + "\n";
}

std::vector<double> write_luts(const std::vector<Table>& tables, const LutOptions& opt, const std::string& dir,
                               const LutFormats& formats) {
  std::vector<double> rounding(tables.size(), 0.0);
  if (formats.exr)
    for (size_t i = 0; i < tables.size(); ++i) rounding[i] = write_lut_exrs(tables[i], dir, formats.half, opt.command);
  if (formats.png)
    for (const Table& t : tables) write_lut_png(t, dir, opt.command);
  if (formats.hpp) write_text_atomically((fs::path(dir) / "pbrlut.hpp").string(), lut_header_text(tables, opt));
  if (formats.json) write_text_atomically((fs::path(dir) / "dspbr_luts.json").string(), lut_json_text(tables, opt));
  return rounding;
}

}  // namespace dspbr
