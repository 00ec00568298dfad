// The table registry: every energy-compensation table of both layouts declared once (docs/luts.md):
// its name, the layouts that hold it, what it stores, its published axes and default grid, its
// random-number stream and the component that reads it. Everything else (the CLI's choices and
// messages, --size, Python lut.names(), the scene analysis, the readers' schema checks, the
// generated lookup code) iterates or queries it; no other code compares a table name as a string.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace dspbr {

// The tables, in canonical order: DSPBR 2025x's tables, then the rough-glass tables beyond it.
// Each layout's order is this order restricted to its tables (published: GGX_E, GGX_E_avg,
// Base_E, ...; renderer: GGX_E, GGX_beta, GGX_E_avg, GGX_B_avg, Sheen_E, ...), the order of its
// files and generated code.
enum class Lut : uint8_t {
  GgxE,
  GgxBeta,  // renderer layout only
  GgxEAvg,
  GgxBAvg,  // renderer layout only
  BaseE,
  BaseEAvg,
  SheenE,
  SheenAshE,
  GlassE,
  GlassInvE,
  GlassEAvg,
  GlassInvEAvg,
};

// Layouts, as bits: a table may belong to both.
enum LayoutMask : unsigned { kPublishedLayout = 1u, kRendererLayout = 2u, kBothLayouts = 3u };

constexpr uint64_t kNoStream = ~uint64_t(0);

struct LutInfo {
  Lut id;
  const char* name;
  unsigned layouts;              // LayoutMask bits
  bool dspbr;                    // one of DSPBR 2025x's tables (false: beyond it)
  bool glass;                    // a rough-glass table (transmission compensation)
  bool average;                  // a cosine average (no cos_theta axis)
  bool inside;                   // glass: v inside the medium
  std::vector<const char*> axes;  // published layout: axis names, slowest first
  std::vector<int> size;          // published layout: default size per axis
  uint64_t stream;               // random-number stream, published layout (high 32 bits)
  uint64_t renderer_stream;      // ... renderer layout (kNoStream: derived from other tables)
  const char* stores;            // what a cell holds
  const char* serves;            // the component that reads it
};

// Every table, in canonical order.
const std::vector<LutInfo>& lut_registry();
const LutInfo& lut_info(Lut id);
const char* lut_name(Lut id);
// The table called `name` in one of `layouts`; nullptr when there is none.
const LutInfo* find_lut(const std::string& name, unsigned layouts = kBothLayouts);
// The same, throwing std::invalid_argument "unknown table 'NAME' (known: ...)" listing the
// registry's tables of those layouts.
const LutInfo& require_lut(const std::string& name, unsigned layouts = kBothLayouts);
// require_lut(name, kPublishedLayout).
const LutInfo& published_lut(const std::string& name);
// True when `name` is the name of table `id`.
bool is_lut(const std::string& name, Lut id);
// The names of the tables of `layouts` (canonical order), also as "A, B, C".
std::vector<std::string> lut_names(unsigned layouts);
std::string lut_names_list(unsigned layouts);


// The published layout as name lists.
// Canonical table names, in canonical order: GGX_E, GGX_E_avg, Base_E, Base_E_avg, Sheen_E,
// Sheen_ash_E (DSPBR 2025x), then the rough-glass tables beyond it (docs/luts.md, "Glass tables"):
//   Glass_E         [ior_x][roughness][cos_theta]  E_g(mu; r, ior), v outside   (lutgen/albedo.h glass_E)
//   Glass_inv_E     [ior_x][roughness][cos_theta]  E_g(mu; r, ior), v inside (eta_i = ior)
//   Glass_E_avg     [ior_x][roughness]             2 Integral E_g mu dmu, outside
//   Glass_inv_E_avg [ior_x][roughness]             the same, inside
// on endpoint grids whatever the `grid` option (they reach ior = 1, r = 0 and cos = 0), with
// ior_x = 2 (ior - 1) / (ior + 1) = 2 sqrt(F_0) in [0, 1] (ior 1 .. 3; above 3 a lookup clamps).
// (These are the registry's published layout.)
const std::vector<std::string>& lut_table_names();
bool is_lut_table_name(const std::string& name);
bool is_glass_table(const std::string& name);
// The glass tables' IOR axis glass_ior_of_x / glass_x_of_ior: tables/warped_table.h.
// Axis names (slowest -> fastest) and default sizes of a table.
std::vector<std::string> lut_axis_names(const std::string& table);
std::vector<int> lut_default_size(const std::string& table);

}  // namespace dspbr
