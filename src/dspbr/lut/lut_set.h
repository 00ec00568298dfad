// The set of DSPBR energy-compensation tables the BSDF reads (LUT issue):
// GGX_E, GGX_E_avg, Base_E, Base_E_avg, Sheen_E, Sheen_ash_E.
#pragma once
#include <string>

#include "dspbr/lut/table.h"

namespace dspbr {

struct LutSet {
  Table ggx_e;        // [roughness][cos_theta]
  Table ggx_e_avg;    // [roughness]
  Table base_e;       // [f0][roughness][cos_theta]
  Table base_e_avg;   // [f0][roughness]
  Table sheen_e;      // [alpha_b][cos_theta]
  Table sheen_ash_e;  // [alpha_b][cos_theta]

  // Interpolated lookups in the tables' own conventions (roughness r, alpha_b = r_b^2).
  double E_m(double cos_theta, double roughness) const { return ggx_e.lookup({roughness, cos_theta}); }
  double E_m_avg(double roughness) const { return ggx_e_avg.lookup({roughness}); }
  double E_base(double cos_theta, double roughness, double f0) const {
    return base_e.lookup({f0, roughness, cos_theta});
  }
  double E_base_avg(double roughness, double f0) const { return base_e_avg.lookup({f0, roughness}); }
  double E_sheen(double cos_theta, double alpha_b) const { return sheen_e.lookup({alpha_b, cos_theta}); }
  double E_sheen_ash(double cos_theta, double alpha_b) const {
    return sheen_ash_e.lookup({alpha_b, cos_theta});
  }

  // Reads the machine-readable table file (luts/dspbr_luts.json) written by `dspbr lut`.
  // Throws std::runtime_error with a message naming the file and the problem.
  static LutSet load(const std::string& json_path);
  // The committed default set: DSPBR_SOURCE_DIR/luts/dspbr_luts.json (loaded once, cached).
  static const LutSet& builtin();
};

}  // namespace dspbr
