#include "dspbr/tables/table_files.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "dspbr/io/json_fields.h"
#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"
#include "dspbr/tables/table_registry.h"

namespace dspbr {

std::vector<Table> read_lut_json(const std::string& path) {
  return read_lut_json_value(read_json_file(path, "table file", limits::kTableFileBytes), path);
}

std::vector<Table> read_lut_json_text(std::string_view text, const std::string& name) {
  return read_lut_json_value(parse_json(text, name, "table file"), name);
}

void require_table_file_version(const nlohmann::json& j) {
  const auto v = j.find("version");
  if (v == j.end() || !v->is_number_integer() || v->get<long long>() != kTableFileVersion)
    throw std::runtime_error("\"version\" must be " + std::to_string(kTableFileVersion) +
                             " (this build reads table files of that version)");
}

std::vector<Table> read_lut_json_value(const nlohmann::json& j, const std::string& path) {
  namespace jf = json_fields;
  try {
    if (!j.is_object() || j.value("format", nlohmann::json()) != "dspbr_luts")
      throw std::runtime_error("not a dspbr_luts file (missing \"format\": \"dspbr_luts\")");
    require_table_file_version(j);
    std::vector<Table> out;
    const auto& jt = jf::object_member(j, "tables", "");
    for (const auto& item : jt.items())
      if (find_lut(item.key(), kPublishedLayout) == nullptr)
        throw std::runtime_error("tables." + item.key() + ": unknown table (known: " + lut_names_list(kPublishedLayout) +
                                 ")");
    for (const std::string& name : lut_table_names()) {
      if (!jt.contains(name)) continue;
      const std::string where = "tables." + name;
      const auto& e = jf::object_member(jt, name, "tables");
      Table t;
      t.name = name;
      const auto& axes = jf::array_member(e, "axes", where);
      if (axes.size() != lut_axis_names(name).size())
        throw std::runtime_error(where + ".axes must hold " + std::to_string(lut_axis_names(name).size()) + " axes");
      // Sizes within limits.h, so that their product (the number of values) cannot overflow.
      size_t cells = 1;
      for (size_t d = 0; d < axes.size(); ++d) {
        const std::string at = jf::index_path(where + ".axes", d);
        Axis a;
        a.name = jf::string_member(axes[d], "name", at);
        if (a.name != lut_axis_names(name)[d]) throw std::runtime_error(at + ".name must be " + lut_axis_names(name)[d]);
        const std::string g = jf::string_member(axes[d], "grid", at);
        if (g != "cell" && g != "endpoint") throw std::runtime_error(at + ".grid: unknown grid '" + g + "'");
        a.kind = parse_grid_kind(g);
        a.size = int(jf::integer_member(axes[d], "size", at, a.kind == GridKind::Endpoint ? 2 : 1, limits::kTableAxisSize));
        a.lo = jf::number_member(axes[d], "lo", at);
        a.hi = jf::number_member(axes[d], "hi", at);
        if (!(a.lo < a.hi)) throw std::runtime_error(at + ": lo must be below hi");
        // The lookups divide by hi - lo: a span beyond the largest double made every cell index NaN,
        // a denormal one (lo 0, hi 5e-324) every coordinate infinite. Real axes span 0.1 to 3.
        if (!(std::isfinite(a.hi - a.lo) && a.hi - a.lo >= 1e-9))
          throw std::runtime_error(at + ": hi - lo must be finite and at least 1e-9");
        cells *= size_t(a.size);
        if (cells > limits::kTableCells)
          throw std::runtime_error(where + ": more than " + std::to_string(limits::kTableCells) + " cells");
        t.axes.push_back(a);
      }
      t.values = jf::numbers_member(e, "values", where, cells);
      if (e.contains("errors")) t.errors = jf::numbers_member(e, "errors", where, cells);
      out.push_back(std::move(t));
    }
    if (out.empty()) throw std::runtime_error("\"tables\" holds none of " + lut_names_list(kPublishedLayout));
    return out;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("'" + path + "': " + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("'" + path + "': " + e.what());
  }
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

}  // namespace dspbr
