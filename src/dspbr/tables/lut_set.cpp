#include "dspbr/tables/lut_set.h"

#include "dspbr/limits.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "dspbr/io/read_file.h"
#include "dspbr/tables/table_files.h"
#include "dspbr/tables/table_registry.h"
#include "dspbr/nearest_name.h"

namespace dspbr {

// Defined in the sources CMake generates from luts/dspbr_luts.json and
// luts/dspbr_renderer_luts.json (cmake/generated_sources.cmake).
std::string_view dspbr_luts_json();
std::string_view dspbr_renderer_luts_json();

namespace {
bool is_renderer(const LutSet& s) { return s.layout == LutLayout::Renderer; }

// One parse of the file; its "format" tells the layout.
LutSet from_json(const nlohmann::json& j, const std::string& name) {
  LutSet set;
  if (j.is_object() && j.value("format", nlohmann::json()) == "dspbr_renderer_luts") {
    set.layout = LutLayout::Renderer;
    set.renderer = read_renderer_json_value(j, name);
    return set;
  }
  set.layout = LutLayout::Published;
  for (Table& t : read_lut_json_value(j, name)) {  // names checked against the registry there
    Table& slot = set.published_table(published_lut(t.name).id);
    slot = std::move(t);
  }
  return set;
}

}  // namespace

Table& LutSet::published_table(Lut id) {
  switch (id) {
    case Lut::GgxE: return ggx_e;
    case Lut::GgxEAvg: return ggx_e_avg;
    case Lut::BaseE: return base_e;
    case Lut::BaseEAvg: return base_e_avg;
    case Lut::SheenE: return sheen_e;
    case Lut::SheenAshE: return sheen_ash_e;
    case Lut::GlassE: return glass_e;
    case Lut::GlassInvE: return glass_inv_e;
    case Lut::GlassEAvg: return glass_e_avg;
    case Lut::GlassInvEAvg: return glass_inv_e_avg;
    case Lut::GgxBeta:
    case Lut::GgxBAvg: break;
  }
  throw std::invalid_argument(std::string("not a published table: ") + lut_name(id));
}

const Table& LutSet::published_table(Lut id) const { return const_cast<LutSet*>(this)->published_table(id); }

double LutSet::E_m_avg(double r) const { return is_renderer(*this) ? this->renderer.E_m_avg(r) : ggx_e_avg.lookup({r}); }
double LutSet::missing_E_m_avg(double r) const {
  return is_renderer(*this) ? this->renderer.missing_E_m_avg(r) : 1.0 - ggx_e_avg.lookup({r});
}
double LutSet::E_base(double c, double r, double f0) const {
  return is_renderer(*this) ? this->renderer.E_base(c, r, f0) : base_e.lookup({f0, r, c});
}
double LutSet::E_base_avg(double r, double f0) const {
  return is_renderer(*this) ? this->renderer.E_base_avg(r, f0) : base_e_avg.lookup({f0, r});
}
double LutSet::E_sheen(double c, double ab) const {
  return is_renderer(*this) ? this->renderer.E_sheen(c, ab) : sheen_e.lookup_2d(ab, c);
}
double LutSet::E_sheen_ash(double c, double ab) const {
  return is_renderer(*this) ? this->renderer.E_sheen_ash(c, ab) : sheen_ash_e.lookup_2d(ab, c);
}

bool LutSet::has_glass() const {
  if (is_renderer(*this)) return renderer.has_glass();
  return !glass_e.axes.empty() && !glass_inv_e.axes.empty() && !glass_e_avg.axes.empty() &&
         !glass_inv_e_avg.axes.empty();
}
double LutSet::E_glass(double c, double r, double ior, bool inside) const {
  if (is_renderer(*this)) return renderer.E_glass(c, r, ior, inside);
  return (inside ? glass_inv_e : glass_e).lookup({glass_x_of_ior(ior), r, c});
}
double LutSet::E_glass_avg(double r, double ior, bool inside) const {
  if (is_renderer(*this)) return renderer.E_glass_avg(r, ior, inside);
  return (inside ? glass_inv_e_avg : glass_e_avg).lookup({glass_x_of_ior(ior), r});
}

LutSet LutSet::load(const std::string& json_path) {
  return from_json(read_json_file(json_path, "table file", limits::kTableFileBytes), json_path);
}

LutSet LutSet::from_text(std::string_view text, const std::string& name) {
  return from_json(parse_json(text, name, "table file"), name);
}

const char* LutSet::builtin_name(LutLayout layout) {
  return layout == LutLayout::Renderer ? "built-in luts/dspbr_renderer_luts.json" : "built-in luts/dspbr_luts.json";
}

std::string_view LutSet::builtin_text(LutLayout layout) {
  return layout == LutLayout::Renderer ? dspbr_renderer_luts_json() : dspbr_luts_json();
}

const LutSet& LutSet::builtin() {
  // Function-local static: initialised once, thread-safe (C++11 magic statics).
  static const LutSet set = from_text(builtin_text(LutLayout::Renderer), builtin_name(LutLayout::Renderer));
  return set;
}

const LutSet& LutSet::published() {
  static const LutSet set = from_text(builtin_text(LutLayout::Published), builtin_name(LutLayout::Published));
  return set;
}

const LutSet& LutSet::of_layout(LutLayout layout) { return layout == LutLayout::Renderer ? builtin() : published(); }

const char* lut_layout_name(LutLayout layout) { return layout == LutLayout::Renderer ? "renderer" : "published"; }

LutLayout parse_lut_layout(const std::string& name) {
  if (name == "renderer") return LutLayout::Renderer;
  if (name == "published") return LutLayout::Published;
  throw std::invalid_argument("unknown table layout '" + name + "'" + did_you_mean(name, {"renderer", "published"}) +
                              " (choose renderer or published)");
}

}  // namespace dspbr
