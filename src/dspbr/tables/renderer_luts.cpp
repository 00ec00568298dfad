#include "dspbr/tables/renderer_luts.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "dspbr/fresnel.h"

namespace dspbr {

namespace {

// Axis domains and warps, chosen by measuring the lookup error over the whole domain
// (docs/luts.md, "Renderer layout"): cos warps that follow the grazing features, samples where
// the functions bend.
WarpedAxis axis(const char* name, int size, WarpKind kind, double p, double lo) {
  return WarpedAxis{name, size, Warp{kind, p, lo}};
}
constexpr double kSheenMinAlphaB = 1.0 / 256.0;  // sheen tables: alpha_b below evaluates here
constexpr double kSheenMinCos = 1e-3;            // sheen tables: cos below evaluates here
constexpr double kAvgMinRoughness = 1e-3;        // GGX_E_avg: r below evaluates here
constexpr double kGlassIorScale = 1.0;           // the glass ior warp's k (docs/luts.md)

int scaled(int n, int scale) { return (n - 1) * scale + 1; }

}  // namespace

std::vector<WarpedAxis> renderer_default_axes(const std::string& name, int scale) {
  if (scale < 1) throw std::invalid_argument("renderer table scale must be >= 1");
  const int s = scale;
  switch (require_lut(name, kRendererLayout).id) {
    case Lut::GgxE:
      return {axis("roughness", scaled(32, s), WarpKind::Power, 1.0, 0.0),
              axis("cos_theta", scaled(64, s), WarpKind::GgxCos, 0.5, 0.0)};
    case Lut::GgxBeta:  // stores beta - (1 - mu)^5, which vanishes as r -> 0
      return {axis("roughness", scaled(32, s), WarpKind::Power, 1.0, 0.0),
              axis("cos_theta", scaled(32, s), WarpKind::GgxCos, 0.5, 0.0)};
    case Lut::GgxEAvg: return {axis("roughness", scaled(32, s), WarpKind::Power, 0.5, kAvgMinRoughness)};
    case Lut::GgxBAvg: return {axis("roughness", scaled(32, s), WarpKind::Power, 1.0, 0.0)};
    case Lut::SheenE:
    case Lut::SheenAshE:
      return {axis("alpha_b", scaled(32, s), WarpKind::Power, 0.25, kSheenMinAlphaB),
              axis("cos_theta", scaled(32, s), WarpKind::Power, 0.25, kSheenMinCos)};
    case Lut::GlassE:
    case Lut::GlassInvE:
      return {axis("ior", scaled(16, s), WarpKind::GlassIor, kGlassIorScale, 0.0),
              axis("roughness", scaled(16, s), WarpKind::Power, 1.0, 0.0),
              axis("cos_theta", scaled(64, s), WarpKind::GgxCos, 0.6, 0.0)};
    case Lut::GlassEAvg:
    case Lut::GlassInvEAvg:
      return {axis("ior_x", scaled(32, s), WarpKind::Power, 0.5, 0.0),  // dense near ior 1
              axis("roughness", scaled(32, s), WarpKind::Power, 1.0, 0.0)};
    case Lut::BaseE:
    case Lut::BaseEAvg: break;  // not in the renderer layout (require_lut refused them)
  }
  throw std::invalid_argument("unknown renderer table '" + name + "'");
}

namespace {

std::vector<const char*> renderer_names(bool glass) {
  std::vector<const char*> n;
  for (const LutInfo& t : lut_registry())
    if ((t.layouts & kRendererLayout) != 0 && t.glass == glass) n.push_back(t.name);
  return n;
}

}  // namespace

const std::vector<const char*>& RendererLuts::names() {
  static const std::vector<const char*> n = renderer_names(false);
  return n;
}

const std::vector<const char*>& RendererLuts::glass_names() {
  static const std::vector<const char*> n = renderer_names(true);
  return n;
}

std::vector<const char*> RendererLuts::held_names() const {
  std::vector<const char*> n = names();
  if (has_glass()) n.insert(n.end(), glass_names().begin(), glass_names().end());
  return n;
}

const WarpedTable* RendererLuts::table(const std::string& name) const {
  return const_cast<RendererLuts*>(this)->table(name);
}

WarpedTable* RendererLuts::table(const std::string& name) {
  const LutInfo* info = find_lut(name, kRendererLayout);
  if (info == nullptr) return nullptr;
  return &table(info->id);
}

WarpedTable& RendererLuts::table(Lut id) {
  switch (id) {
    case Lut::GgxE: return ggx_E;
    case Lut::GgxBeta: return ggx_beta;
    case Lut::GgxEAvg: return ggx_E_avg;
    case Lut::GgxBAvg: return ggx_B_avg;
    case Lut::SheenE: return sheen_E;
    case Lut::SheenAshE: return sheen_ash_E;
    case Lut::GlassE: return glass_E;
    case Lut::GlassInvE: return glass_inv_E;
    case Lut::GlassEAvg: return glass_E_avg;
    case Lut::GlassInvEAvg: return glass_inv_E_avg;
    case Lut::BaseE:
    case Lut::BaseEAvg: break;
  }
  throw std::invalid_argument(std::string("not a renderer table: ") + lut_name(id));
}

const WarpedTable& RendererLuts::table(Lut id) const { return const_cast<RendererLuts*>(this)->table(id); }

size_t RendererLuts::stored_values() const {
  size_t n = 0;
  for (const char* name : names()) n += table(name)->size();
  return n;
}

size_t RendererLuts::glass_stored_values() const {
  size_t n = 0;
  if (has_glass())
    for (const char* name : glass_names()) n += table(name)->size();
  return n;
}

bool RendererLuts::has_glass() const {
  for (const char* name : glass_names())
    if (table(name)->axes.empty()) return false;
  return true;
}

double RendererLuts::B(double cos_theta, double roughness) const {
  return beta(cos_theta, roughness) * E_m(cos_theta, roughness);
}

double RendererLuts::beta(double cos_theta, double roughness) const {
  const double r = std::clamp(roughness, 0.0, 1.0);
  const double mu = std::clamp(cos_theta, 0.0, 1.0);
  // stored: beta - (1 - mu)^5 (zero for the mirror, so the r = 0 row of the ggx_cos grid holds it)
  const double stored = ggx_beta.lookup_grid(ggx_beta.axes[0].warp.to_grid(r), ggx_beta.axes[1].warp.to_grid(mu, r * r));
  return decode_beta(mu, stored);
}

double RendererLuts::base_fresnel_ms(double f0, double e_m_avg) { return fresnel_ms(f0, 1.0, e_m_avg); }

double RendererLuts::missing_E_m_avg(double roughness) const {
  // Stored: ln(1 - E_m,avg); the decoded 1 - E_m,avg keeps its relative precision as it vanishes.
  return std::exp(ggx_E_avg.interpolate(ggx_E_avg.axes[0].warp.to_grid(roughness)));
}

double RendererLuts::E_m_avg(double roughness) const { return 1.0 - missing_E_m_avg(roughness); }

double RendererLuts::B_avg(double roughness) const {
  return ggx_B_avg.lookup_grid(ggx_B_avg.axes[0].warp.to_grid(roughness));
}

double RendererLuts::E_base(double cos_theta, double roughness, double f0) const {
  const double mu = std::clamp(cos_theta, 0.0, 1.0);
  return compose_E_base(f0, E_m(mu, roughness), beta(mu, roughness), base_fresnel_ms(f0, E_m_avg(roughness)));
}

double RendererLuts::E_base_avg(double roughness, double f0) const {
  const double missing = missing_E_m_avg(roughness);
  const double e_avg = 1.0 - missing;
  return f0 * e_avg + (1.0 - f0) * B_avg(roughness) + base_fresnel_ms(f0, e_avg) * missing;
}

// At least 0, as beta (the cubic undershoots where E_b nears 0, by 1.3e-5).
double RendererLuts::E_sheen(double cos_theta, double alpha_b) const {
  return kSheenERange.clamp(
      sheen_E.lookup_grid(sheen_E.axes[0].warp.to_grid(alpha_b), sheen_E.axes[1].warp.to_grid(cos_theta)));
}

double RendererLuts::E_sheen_ash(double cos_theta, double alpha_b) const {
  return kSheenERange.clamp(
      sheen_ash_E.lookup_grid(sheen_ash_E.axes[0].warp.to_grid(alpha_b), sheen_ash_E.axes[1].warp.to_grid(cos_theta)));
}

double RendererLuts::E_glass(double cos_theta, double roughness, double ior, bool inside) const {
  const WarpedTable& t = inside ? glass_inv_E : glass_E;
  const double r = std::clamp(roughness, 0.0, 1.0), mu = std::clamp(cos_theta, 0.0, 1.0);
  return t.lookup_grid(t.axes[0].warp.to_grid(ior, mu), t.axes[1].warp.to_grid(r), t.axes[2].warp.to_grid(mu, r * r));
}

double RendererLuts::E_glass_avg(double roughness, double ior, bool inside) const {
  const WarpedTable& t = inside ? glass_inv_E_avg : glass_E_avg;
  return t.lookup_grid(t.axes[0].warp.to_grid(glass_x_of_ior(ior)), t.axes[1].warp.to_grid(roughness));
}

std::array<double, 3> renderer_sample_coordinates(const WarpedTable& t, size_t index) {
  const size_t rank = t.axes.size();
  if (rank == 0 || rank > 3 || index >= t.size())
    throw std::invalid_argument("renderer_sample_coordinates: no sample " + std::to_string(index) + " in " + t.name);
  std::array<double, 3> x{}, v{};
  for (size_t k = rank, rest = index; k-- > 0; rest /= size_t(t.axes[k].size))
    x[k] = double(rest % size_t(t.axes[k].size)) / double(t.axes[k].size - 1);
  // The aux coordinates of the dependent warps (warped_table.h): alpha = r^2 for ggx_cos, mu for
  // glass_ior; so first the independent axes, then ggx_cos, then glass_ior.
  auto coordinate_of = [&](const char* axis_name) {
    for (size_t k = 0; k < rank; ++k)
      if (t.axes[k].name == axis_name) return v[k];
    throw std::invalid_argument("renderer_sample_coordinates: " + t.name + " has no " + axis_name + " axis");
  };
  for (const WarpKind pass : {WarpKind::Power, WarpKind::GgxCos, WarpKind::GlassIor}) {
    for (size_t k = 0; k < rank; ++k) {
      const Warp& w = t.axes[k].warp;
      const bool independent = w.kind == WarpKind::Power || w.kind == WarpKind::LogRoughness;
      if (independent ? pass != WarpKind::Power : w.kind != pass) continue;
      double aux = 0;
      if (w.kind == WarpKind::GgxCos) aux = coordinate_of("roughness") * coordinate_of("roughness");
      if (w.kind == WarpKind::GlassIor) aux = coordinate_of("cos_theta");
      v[k] = w.from_grid(x[k], aux);
    }
  }
  return v;
}

double renderer_sample_value(const WarpedTable& t, size_t index, const std::array<double, 3>& coordinates) {
  const double stored = t.values.at(index);
  if (is_lut(t.name, Lut::GgxBeta)) return RendererLuts::decode_beta(coordinates[1], stored);
  return decode(t.encoding, stored);
}

}  // namespace dspbr
