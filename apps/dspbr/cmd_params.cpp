// `dspbr params`: parameter definition files (spec appendix "Parameter JSON file format") and
// material instance files.
//   dspbr params list [FILE] [--json]          materials of a definition file
//   dspbr params show [FILE] MATERIAL [--json]   resolved parameters in UI order and groups
//   dspbr params check INSTANCE... [--params FILE]
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "commands.h"
#include "provenance.h"
#include "dspbr/limits.h"
#include "dspbr/io/json_write.h"
#include "dspbr/io/read_file.h"
#include "dspbr/params/material_instance.h"
#include "dspbr/params/param_defs.h"

namespace dspbr::cli {

namespace {

// The definition file at `path`; default_param_defs() when `path` is empty.
ParamDefs load_defs(const std::string& path) {
  try {
    return path.empty() ? default_param_defs() : ParamDefs::load(path);
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
}

std::string range_text(const ParamDef& p) {
  if (p.min.is_null() && p.max.is_null()) return "";
  auto text = [](const nlohmann::json& v) {
    std::string s = v.dump();
    for (const char* key : {"{\"infinity\":true}", "{\"-infinity\":true}"}) {
      const std::string k = key, r = k[2] == '-' ? "-inf" : "inf";
      for (std::size_t pos; (pos = s.find(k)) != std::string::npos;) s.replace(pos, k.size(), r);
    }
    return s;
  };
  return "[" + text(p.min) + ", " + text(p.max) + "]";
}

void print_material(const MaterialDef& m) {
  std::printf("%s", one_line(m.id).c_str());
  if (!m.name.empty()) std::printf(" \"%s\"", one_line(m.name).c_str());
  for (const auto& base : m.inherits) std::printf(" <- %s", one_line(base).c_str());
  std::printf("\n");
  bool first = true;
  std::string group;
  for (const auto& p : m.parameters) {
    if (first || p.group != group) {
      std::printf("  [%s]\n", p.group.empty() ? "(no group)" : one_line(p.group).c_str());
      group = p.group;
      first = false;
    }
    std::printf("    %-3s %-28s %-8s default %-24s %-28s%s%s\n",
                p.ui_order < 0 ? "-" : std::to_string(p.ui_order).c_str(), one_line(p.id).c_str(), param_type_name(p.type),
                p.default_value.dump().c_str(), range_text(p).c_str(), p.uniform ? " uniform" : "",
                p.hidden ? " (hidden)" : "");
  }
}

}  // namespace

void add_params_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("params", "Parameter definition files (params-2025x.json format) and material instances");
  cmd->require_subcommand(1);

  struct Options {
    std::string file, material, params;
    std::vector<std::string> show_args;  // params show: [FILE] MATERIAL
    std::vector<std::string> instances;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();

  auto* list = cmd->add_subcommand("list", "List the materials of a parameter definition file");
  list->add_option("FILE", opt->file, "Parameter definition file (default: $DSPBR_PARAMS, else the built-in params-2025x.json)");
  list->add_flag("--json", opt->json, "Print {\"materials\": [{\"id\", \"name\", \"inherits\"}]}");
  list->callback([opt] {
    const ParamDefs defs = load_defs(opt->file);
    if (opt->json) {
      nlohmann::ordered_json out = {{"materials", nlohmann::ordered_json::array()}};
      for (const auto& id : defs.material_ids()) {
        const auto& m = defs.material(id);
        out["materials"].push_back({{"id", id}, {"name", m.name}, {"inherits", m.inherits}});
      }
      out["provenance"] = output_provenance();
      std::cout << json_text(out, 2, "params --json") << "\n";
      return;
    }
    for (const auto& id : defs.material_ids()) {
      const auto& m = defs.material(id);
      std::printf("%-12s %-32s %s\n", one_line(id).c_str(), one_line(m.name).c_str(),
                  m.inherits.empty() ? "" : one_line("inherits " + m.inherits.front()).c_str());
    }
  });

  auto* show = cmd->add_subcommand("show", "Show a material's resolved parameters in UI order and groups");
  show->add_option("[FILE] MATERIAL", opt->show_args,
                   "Parameter definition file (default: $DSPBR_PARAMS, else the built-in params-2025x.json), then "
                   "the material id, e.g. glass")
      ->expected(1, 2)
      ->required();
  show->add_flag("--json", opt->json,
                 "Print {\"parameters\": {\"<id>\": {\"name\", \"type\", \"default\", \"min\", \"max\", \"uniform\", "
                 "\"hidden\", \"group\", \"uiOrder\", ...}}}");
  show->callback([opt] {
    opt->material = opt->show_args.back();
    opt->file = opt->show_args.size() == 2 ? opt->show_args.front() : std::string();
    const ParamDefs defs = load_defs(opt->file);
    const MaterialDef* m = nullptr;
    try {
      m = &defs.material(opt->material);
    } catch (const std::exception& e) {
      throw UsageError(e.what());
    }
    if (opt->json) {
      nlohmann::ordered_json out = material_def_to_json(*m);
      out["provenance"] = output_provenance();
      std::cout << json_text(out, 2, "params --json") << "\n";
    }
    else print_material(*m);
  });

  auto* check = cmd->add_subcommand("check", "Validate material instance files {\"material\": ..., \"values\": {...}}");
  check->add_option("INSTANCE", opt->instances, "Material instance file(s)")->required();
  check->add_option("--params", opt->params,
                    "Parameter definition file (default: $DSPBR_PARAMS, else the built-in params-2025x.json)");
  check->callback([opt] {
    const ParamDefs defs = load_defs(opt->params);
    int bad = 0;
    // One file: its problems as the one error line; several: a line per problem, then the count.
    std::vector<std::string> errors;
    const auto report = [&](const std::string& line) {
      if (opt->instances.size() == 1)
        errors.push_back(line);
      else
        std::fprintf(stderr, "dspbr: error: %s\n", one_line(line).c_str());
    };
    for (const auto& path : opt->instances) {
      nlohmann::json doc;
      try {
        doc = read_json_file(path, "material instance file", limits::kDocumentBytes);
      } catch (const std::exception& e) {
        ++bad;
        report(e.what());  // names the file
        continue;
      }
      std::vector<std::string> problems;
      std::string type;
      try {
        problems = check_material_instance(defs, doc);
        if (problems.empty()) {
          material_from_instance(defs, doc);  // also proves it converts
          type = doc["material"].get<std::string>();
        }
      } catch (const std::exception& e) {
        problems.push_back(e.what());
      }
      if (problems.empty()) {
        std::printf("%s\n", one_line(path + ": ok (material '" + type + "')").c_str());
      } else {
        ++bad;
        for (const auto& p : problems) report(path + ": " + p);
      }
    }
    if (!errors.empty()) {
      std::string all = errors[0];
      for (std::size_t i = 1; i < errors.size(); ++i) all += "; " + errors[i];
      throw UsageError(all);
    }
    if (bad) throw UsageError(std::to_string(bad) + " of " + std::to_string(opt->instances.size()) +
                              " instance file(s) invalid against " + defs.source());
  });
}

}  // namespace dspbr::cli
