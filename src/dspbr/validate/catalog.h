// What `dspbr validate` checks: the DSPBR components and whole materials as Bsdf objects, with
// what the spec claims about their energy, plus the parameter corners of the stability sweep and
// the rows of furnace spheres. The checks themselves (furnace.h, reciprocity.h, chi2.h, ...) work
// on any const Bsdf&.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dspbr/bsdf/bsdf.h"
#include "dspbr/bsdf/lobe_assembly.h"
#include "dspbr/material.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/validate/albedo_quadrature.h"

namespace dspbr::validate {

// What the spec says about the energy of a case (spec sections cited in `note`).
enum class EnergyClaim {
  Conserving,            // E <= 1 only (no preservation claim): a loss is reported, not failed
  Preserving,            // E >= 1 - tol as well (energy-compensated white materials)
  GainsBySpec,           // the spec's own model gains energy here (conservation failures: waivers.h)
};

struct BsdfCase {
  std::string name;       // e.g. "metallic r=0.5"
  std::string component;  // component_name() or "material"
  std::string params;     // non-default parameters, for the report
  std::shared_ptr<const Bsdf> bsdf;
  EnergyClaim claim = EnergyClaim::Conserving;
  double preservation_tol = -1;   // < 0: the suite default
  std::string note;               // the spec's statement / our measurement context
  double eta_above = 1, eta_below = 1;  // media on the +z / -z side (eta^2 rule)
  bool viewer_below = false;      // also check viewers inside the object (v.z < 0)
  // Which eta^2 rule refraction must obey: the radiance rule f(v,l)/eta_v^2 = f(l,v)/eta_l^2, or
  // the adjoint one that the spec's M_t formula gives when eta_i is v's medium (docs/validation.md).
  bool adjoint_eta_rule = false;
  bool non_reciprocal_by_design = false;
  std::string non_reciprocal_reason;
  bool chi2 = true;               // include in the chi-square tests
  // Where f(v, .) jumps (the flake's cone), for the furnace's quadrature (albedo_quadrature.h);
  // empty: nowhere.
  std::function<std::vector<FeatureCone>(const Vec3& v)> cones;
  // The whole material and options the case was built from (none: not a material, e.g. the phase
  // function), so that another implementation of DSPBR can be checked on the same case.
  std::optional<Material> material;
  BsdfOptions options;
};

struct StabilityCase {
  std::string component;  // component or "random materials"
  std::string corner;     // e.g. "roughness=0"
  std::shared_ptr<const Bsdf> bsdf;
  std::optional<Material> material;  // as BsdfCase::material
  BsdfOptions options;
};

struct FurnaceRow {
  std::string name;                  // e.g. "metallic"
  std::string parameter;             // the parameter varied along the row, e.g. "roughness"
  std::vector<double> values;        // its values
  std::vector<std::shared_ptr<const Bsdf>> bsdfs;
  std::string note;
};

struct Catalog {
  std::vector<BsdfCase> cases;
  std::vector<StabilityCase> stability;
  std::vector<FurnaceRow> furnace_rows;
  std::vector<std::string> skipped;  // what could not be checked, and why
  const LutSet* luts = nullptr;      // the tables the BSDF cases read (waivers of table effects)
};

struct CatalogOptions {
  bool quick = false;
  std::size_t random_materials = 2000;  // random parameter sets for the stability sweep
  uint64_t seed = 1;
  const LutSet* luts = nullptr;  // tables of every BSDF (null: LutSet::builtin()); must outlive the catalog
  // Every BSDF with the transmission compensation (beyond DSPBR 2025x; validate
  // --transmission-compensation); the transparent cases then claim preservation. Off: the spec's
  // BSDF, plus compensated transparent cases and furnace rows for comparison.
  bool transmission_compensation = false;
};

// The DSPBR cases (the reference BSDF with opt.luts).
Catalog dspbr_catalog(const CatalogOptions& opt);

// The stability corners an implementation of whole materials is scanned on (the shader library:
// `dspbr validate`'s section, and shader_vk_stability on the device), in the reference's order:
// those with a material and without the transmission compensation (beyond DSPBR 2025x), every
// corner and one random material in four (500 of the full run's 2000: such an implementation
// recomputes per call what the reference caches per material, its thin film's R several times per
// call, and all 2000 took 8 s of the run's 73). A component's corner is its base material's.
std::vector<StabilityCase> whole_material_stability(const Catalog& reference);

}  // namespace dspbr::validate
