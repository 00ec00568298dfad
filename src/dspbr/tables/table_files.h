// Reading the table files `dspbr lut` writes (docs/luts.md, "Files"): dspbr_luts.json (the
// published layout) and dspbr_renderer_luts.json (the renderer layout). The readers check the
// schema against the table registry (tables/table_registry.h): table names, axis names and order,
// warps, sizes within limits.h, finite values, the format version. Writing is the generator's
// (lutgen/lut_io.h, lutgen/renderer_io.h).
#pragma once
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "dspbr/tables/renderer_luts.h"
#include "dspbr/tables/table.h"

namespace dspbr {

// Reads the tables of a dspbr_luts.json (any subset of the six). Throws std::runtime_error
// naming the file and the problem (file errors and malformed JSON: io/read_file.h).
std::vector<Table> read_lut_json(const std::string& path);
// The same from the file's text, or from its parsed JSON; `name` stands for the file in the
// messages.
std::vector<Table> read_lut_json_text(std::string_view text, const std::string& name);
std::vector<Table> read_lut_json_value(const nlohmann::json& j, const std::string& name);

// The version of both table file formats (dspbr_luts, dspbr_renderer_luts) this build writes and
// reads; a reader refuses another (std::runtime_error naming the field).
constexpr int kTableFileVersion = 1;
void require_table_file_version(const nlohmann::json& j);

// Reads a dspbr_renderer_luts.json; checks format, table set, axis names, warps and sizes
// (before allocating) and finite values. Throws std::runtime_error naming the file and the
// problem.
RendererLuts read_renderer_json(const std::string& path);
// The same from the file's text, or from its parsed JSON; `name` stands for the file in the
// messages.
RendererLuts read_renderer_json_text(std::string_view text, const std::string& name);
RendererLuts read_renderer_json_value(const nlohmann::json& j, const std::string& name);

}  // namespace dspbr
