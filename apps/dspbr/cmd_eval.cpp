// `dspbr eval` and `dspbr sample`: the reference BSDF for one pair of directions, as JSON.
//   dspbr eval   [--material FILE.json] [--set id=value]... --view x,y,z --light x,y,z
//   dspbr sample [--material FILE.json] [--set id=value]... --view x,y,z --u u1,u2,u3
// Directions are in the local shading frame (tangent +x, bitangent +y, normal +z) and are
// normalized here. The material starts from the generic defaults (or the instance file, any
// material type of params-2025x.json), then --set values apply in order, then validate_material.
// Conventions of f, pdf and weight: docs/bsdf.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <map>
#include <string>
#include <vector>

#include "commands.h"
#include "provenance.h"
#include "dspbr/io/json_write.h"
#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/io/json_values.h"
#include "dspbr/params/material_instance.h"
#include "dspbr/params/material_params.h"
#include "dspbr/scene/components.h"

namespace dspbr::cli {

namespace {

using Json = nlohmann::json;

struct EvalArgs {
  std::string material_file;
  std::vector<std::string> sets;
  std::string view, light, u;
  std::string sheen = "main";
  std::string position = "0,0,0";
  std::string object_normal = "0,0,1";
  double wavelength = 0;
  double area = 1;
  std::string components;  // comma-separated component names; empty: active components
  std::string tables = "renderer";  // table layout the BSDF reads
  bool transmission_compensation = false;
};

// The table set of --tables (renderer: the default, accurate everywhere; published: what a
// renderer using the published files computes).
const LutSet& table_set(const EvalArgs& a) {
  try {
    return LutSet::of_layout(parse_lut_layout(a.tables));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--tables: ") + e.what());
  }
}

std::vector<double> parse_numbers(const std::string& option, const std::string& text, size_t count) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    // The one number grammar (decimal.h); a subnormal such as 1e-320 is a number.
    const Decimal x = parse_decimal(item);
    if (x.status == Decimal::OutOfRange)
      throw UsageError(option + " expects " + std::to_string(count) + " comma-separated finite numbers, got '" +
                       quote_input(text) + "': '" + quote_input(item) + "' is beyond the range of a double");
    if (x.status != Decimal::Ok)
      throw UsageError(option + " expects " + std::to_string(count) + " comma-separated decimal numbers, got '" +
                       quote_input(text) + "'");
    out.push_back(x.value);
  }
  // getline drops an empty last field: "0,0,1," has 4 fields, the last one empty
  if (out.size() != count || (!text.empty() && text.back() == ','))
    throw UsageError(option + " expects " + std::to_string(count) + " comma-separated numbers, got '" + quote_input(text) + "'");
  return out;
}

// The unit vector along x,y,z. Scaled by its largest component first, so that finite vectors
// whose squared length overflows (1e308,1e308,1e308) or underflows (1e-320,0,0) keep their
// direction.
Vec3 parse_direction(const std::string& option, const std::string& text) {
  const auto x = parse_numbers(option, text, 3);
  const double scale = std::max({std::abs(x[0]), std::abs(x[1]), std::abs(x[2])});
  if (!(scale > 0)) throw UsageError(option + " must be a non-zero vector, got '" + quote_input(text) + "'");
  const Vec3 d = normalize(Vec3{x[0] / scale, x[1] / scale, x[2] / scale});
  if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z)))
    throw UsageError(option + " must be a finite non-zero vector, got '" + quote_input(text) + "'");
  return d;
}

// Prints the result; a value that overflows double precision (e.g. emission of a luminance near
// 1e308 times a colour above 1) is an error, never a null in the output.
void print_result(const Json& out) {
  if (const auto p = non_finite_path(out))
    throw UsageError("the result \"" + *p + "\" is not finite: the material values are too large to evaluate in double precision");
  std::cout << out.dump(2) << "\n";
}

Material build_material(const EvalArgs& a) {
  Material m;
  if (!a.material_file.empty()) {
    try {
      m = load_material_instance(a.material_file);
    } catch (const std::exception& e) {
      throw UsageError(e.what());
    }
  }
  std::map<std::string, std::string> given;  // id -> its --set, for a parameter given twice
  for (const std::string& s : a.sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--set expects id=value (e.g. --set roughness=0.3), got '" + s + "'");
    const std::string id = s.substr(0, eq), value = s.substr(eq + 1);
    // Two values for one parameter are a mistake, not an override (the eleventh fresh tester's
    // pass: the last one was taken silently).
    if (!given.emplace(id, s).second)
      throw UsageError("--set " + s + ": " + id + " is already set by --set " + given[id] + "; give each parameter once");
    try {
      set_material_parameter(m, id, parse_parameter_text(id, value));
    } catch (const std::exception& e) {
      throw UsageError(std::string("--set ") + s + ": " + e.what());
    }
  }
  try {
    validate_material(m);
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  return m;
}

uint32_t parse_components(const EvalArgs& a, const Material& m) {
  if (a.components.empty()) return active_components(m);
  std::vector<std::string> names;
  std::stringstream ss(a.components);
  std::string name;
  while (std::getline(ss, name, ',')) names.push_back(name);
  try {
    return parse_component_names(names);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--components: ") + e.what());
  }
}

BsdfOptions build_options(const EvalArgs& a) {
  BsdfOptions o;
  if (a.sheen == "main") o.sheen_model = SheenModel::Main;
  else if (a.sheen == "ash") o.sheen_model = SheenModel::Ash;
  else throw UsageError("--sheen expects 'main' or 'ash', got '" + a.sheen + "'");
  const auto p = parse_numbers("--position", a.position, 3);
  o.position = {p[0], p[1], p[2]};
  o.object_normal = parse_direction("--object-normal", a.object_normal);
  // 0, or 1 nm to 1 mm: beyond, the dispersion formula's 1/lambda^2 leaves the doubles' range
  // (1e-300 nm made "ior" infinite; the fourth fresh tester's pass).
  if (!std::isfinite(a.wavelength) || a.wavelength < 0 || (a.wavelength > 0 && (a.wavelength < 1 || a.wavelength > 1e6)))
    throw UsageError("--wavelength expects a wavelength in nm from 1 to 1000000 (0: no dispersion), got " +
                     nlohmann::json(a.wavelength).dump());
  o.wavelength_nm = a.wavelength;
  if (!std::isfinite(a.area) || !(a.area > 0)) throw UsageError("--area expects a positive area in m^2");
  o.object_area_m2 = a.area;
  o.transmission_compensation = a.transmission_compensation;
  return o;
}

Json flags_json(uint32_t f) {
  Json out = Json::array();
  if (f & kLobeReflection) out.push_back("reflection");
  if (f & kLobeTransmission) out.push_back("transmission");
  if (f & kLobeDelta) out.push_back("delta");
  if (f & kLobeGlossy) out.push_back("glossy");
  if (f & kLobeDiffuse) out.push_back("diffuse");
  return out;
}

void add_common_options(CLI::App* cmd, EvalArgs& a) {
  cmd->add_option("--material", a.material_file,
                  "Material instance file {\"material\": TYPE, \"values\": {...}} (default: generic defaults)");
  cmd->add_option("--set", a.sets, "Set a parameter by its JSON id: id=value (colours r,g,b); repeatable, once per parameter")
      ->take_all();
  cmd->add_option("--view", a.view, "View direction v as x,y,z (local frame, normal +z)")->required();
  cmd->add_option("--sheen", a.sheen, "Sheen visibility: main (spec Lambda fit) or ash (alternative)")
      ->capture_default_str();
  cmd->add_option("--position", a.position, "Object-space shading point x,y,z in metres (flakes)")
      ->capture_default_str();
  cmd->add_option("--object-normal", a.object_normal, "Object-space normal x,y,z (flakes' triplanar mapping)")
      ->capture_default_str();
  cmd->add_option("--wavelength", a.wavelength, "Wavelength in nm for dispersion (0: plain ior)")
      ->capture_default_str()
      ->check(decimal_number());
  cmd->add_option("--area", a.area, "Object area in m^2 (emission in lm)")->capture_default_str()->check(decimal_number());
  cmd->add_option("--tables", a.tables,
                  "Energy tables the BSDF reads: renderer (default; warped layout, accurate over the whole domain) "
                  "or published (the published grids, as a renderer using them gets)")
      ->capture_default_str();
  cmd->add_option("--components", a.components,
                  "Comma-separated components to include (default: the material's active ones)")
      ->check(non_empty_list());
  cmd->add_flag("--transmission-compensation", a.transmission_compensation,
                "Add the energy compensation of rough transmission (beyond DSPBR 2025x; docs/bsdf.md)");
}

// The version, the command line and the settings the result depends on besides the material.
Json provenance(const EvalArgs& a) {
  Json p = output_provenance();
  p["settings"] = {{"tables", a.tables},           {"sheen", a.sheen}, {"position", a.position},
                   {"object_normal", a.object_normal}, {"wavelength_nm", a.wavelength}, {"area_m2", a.area},
                   {"components", a.components.empty() ? "active" : a.components},
                   {"transmission_compensation", a.transmission_compensation}};
  return p;
}

// Fields shared by eval and sample.
Json header(const MaterialBsdf& b, const Vec3& v) {
  Json out;
  out["view"] = vec_json(v);
  out["components"] = component_names(b.mask());
  out["ior"] = b.ior();
  out["delta_probability"] = b.delta_probability(v);
  out["emission"] = rgb_json(b.emission(v));
  return out;
}

}  // namespace

void add_eval_commands(CLI::App& app) {
  static EvalArgs eval_args, sample_args;

  auto* eval = app.add_subcommand(
      "eval",
      "Evaluate the reference BSDF for one pair of directions; prints JSON {\"f\": [r,g,b], \"pdf\": p, ...} "
      "(f without the cosine, pdf the solid-angle density of sampling --light given --view)");
  add_common_options(eval, eval_args);
  eval->add_option("--light", eval_args.light, "Light direction l as x,y,z (local frame, normal +z)")->required();
  eval->callback([] {
    const EvalArgs& a = eval_args;
    const Vec3 v = parse_direction("--view", a.view), l = parse_direction("--light", a.light);
    const Material m = build_material(a);
    const MaterialBsdf b(m, table_set(a), build_options(a), parse_components(a, m));
    Json out;
    out["f"] = rgb_json(b.eval(v, l));
    out["provenance"] = provenance(a);
    out["pdf"] = b.pdf(v, l);
    out["cos_light"] = std::abs(l.z);
    out["light"] = vec_json(l);
    out.update(header(b, v));
    print_result(out);
  });

  auto* sample = app.add_subcommand(
      "sample",
      "Sample the reference BSDF for --view with the uniform numbers --u; prints JSON {\"l\", \"weight\", \"pdf\", "
      "\"flags\", ...} (weight = f |cos| / pdf; for a delta lobe pdf is the lobe's probability)");
  add_common_options(sample, sample_args);
  sample->add_option("--u", sample_args.u, "Three uniform numbers u1,u2,u3 in [0, 1)")->required();
  sample->callback([] {
    const EvalArgs& a = sample_args;
    const Vec3 v = parse_direction("--view", a.view);
    const auto u = parse_numbers("--u", a.u, 3);
    for (double x : u)
      if (x < 0 || x >= 1) throw UsageError("--u expects three numbers in [0, 1), got '" + a.u + "'");
    const Material m = build_material(a);
    const MaterialBsdf b(m, table_set(a), build_options(a), parse_components(a, m));
    const BsdfSample s = b.sample(v, {u[0], u[1], u[2]});
    Json out;
    out["valid"] = s.valid;
    out["provenance"] = provenance(a);
    if (s.valid) {
      out["l"] = vec_json(s.l);
      out["weight"] = rgb_json(s.weight);
      out["pdf"] = s.pdf;
      out["flags"] = flags_json(s.flags);
      out["f"] = rgb_json(b.eval(v, s.l));  // 0 for a delta sample (eval has no Dirac part)
    }
    out.update(header(b, v));
    print_result(out);
  });
}

}  // namespace dspbr::cli
