#include "dspbr/validate/provenance.h"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "dspbr/version.h"

namespace dspbr::validate {

using nlohmann::json;

// Both from dspbr::version_string() (version.h): "<version>" or "<version> (<git describe>)".
std::string project_version() { return dspbr::project_version(); }
std::string git_describe() {
  const std::string v = version_string();
  const size_t open = v.find(" (");
  return open == std::string::npos ? "unknown" : v.substr(open + 2, v.size() - open - 3);
}

json table_text_settings(std::string_view bytes, const std::string& path) {
  uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ULL;
  json j = json::parse(bytes.begin(), bytes.end(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw std::runtime_error(path + ": not a JSON table file");
  json out = {{"file", path}, {"fnv1a64", fmt::format("{:016x}", h)}};
  for (const char* k : {"generator", "model", "grid", "seed", "version"})
    if (j.contains(k)) out[k] = j[k];
  // The renderer-layout file keeps its seed with its integrator settings.
  if (!out.contains("seed") && j.contains("integrator") && j["integrator"].is_object() && j["integrator"].contains("seed"))
    out["seed"] = j["integrator"]["seed"];
  json tables = json::object();
  if (j.contains("tables") && j["tables"].is_object())
    for (const auto& [name, t] : j["tables"].items()) {
      json size = json::array();
      if (t.contains("axes"))
        for (const auto& a : t["axes"]) size.push_back(a.value("size", 0));
      json tj = {{"size", size}};
      if (t.contains("integrator")) tj["integrator"] = t["integrator"];
      if (t.contains("max_error")) tj["max_error"] = t["max_error"];
      tables[name] = tj;
    }
  out["tables"] = tables;
  return out;
}

std::vector<std::string> process_arguments() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::vector<std::string> out;
  for (std::string arg; std::getline(in, arg, '\0');) out.push_back(arg);
  return out;
}

std::string process_command_line() {
  std::string s;
  for (const std::string& a : process_arguments()) s += (s.empty() ? "" : " ") + a;
  return s;
}

}  // namespace dspbr::validate
