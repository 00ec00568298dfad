#include "dspbr/conformance/vector_set.h"
#include "dspbr/io/message.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <optional>
#include <array>
#include <cmath>
#include <limits>
#include <filesystem>
#include <functional>
#include <stdexcept>

#include "dspbr/bsdf/emission.h"
#include "dspbr/bsdf/flakes.h"
#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/component.h"
#include "dspbr/constants.h"
#include "dspbr/gltf/gltf_export.h"
#include "dspbr/gltf/gltf_file.h"
#include "dspbr/gltf/gltf_material.h"
#include "dspbr/io/json_values.h"
#include "dspbr/limits.h"
#include "dspbr/tables/lut_set.h"
#include "dspbr/params/material_instance.h"
#include "dspbr/params/material_params.h"
#include "dspbr/params/param_defs.h"
#include "dspbr/rng.h"
#include "dspbr/quadrature.h"

namespace dspbr::conformance {

namespace {

using OJson = nlohmann::ordered_json;

// One material of the set and how its directions are chosen.
struct Case {
  std::string group, name;
  Material m;
  OJson options;             // null: default BSDF options
  OJson gltf;                // the glTF material object, or null
  bool extreme = false;      // the extremes' directions (cos theta down to 1e-4) instead of the usual ones
};

// The instance form of a generic material: the values that differ from the defaults.
OJson instance_json(const Material& m) {
  const Material defaults;
  OJson values = OJson::object();
  for (const std::string& id : material_parameter_ids()) {
    const nlohmann::json x = get_material_parameter(m, id);
    if (x != get_material_parameter(defaults, id)) values[id] = x;
  }
  return OJson{{"material", "generic"}, {"values", values}};
}

Vec3 direction(double cos_theta, double phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return {s * std::cos(phi), s * std::sin(phi), cos_theta};
}

bool transmits(const Material& m) { return m.transparency > 0 || m.translucency > 0 || m.cutoutOpacity < 1; }

// The usual directions of a material: v from normal incidence to cos 0.01 (then random), l the
// mirror direction (every fifth; every other one about an opaque flake's normal), else random on v's side, or on the other side (every other
// one) for a material that transmits; a volumetric material is also seen from inside (every
// fourth, k = 1 mod 4: cos 0.9 below the critical angle, cos 0.15 and others beyond it).
std::vector<std::pair<Vec3, Vec3>> usual_pairs(const Case& c, const BsdfOptions& opt, int n, Pcg32& rng) {
  // With an opaque flake at the shading point, the mirror direction is that of the flake's normal
  // (its cone is narrow: elsewhere the flake reflects nothing).
  const Flake flake = flake_at(opt.position, opt.object_normal, c.m);
  const bool flake_mirror = c.m.flakeCoverage > 0 && flake.opacity > 0;
  static constexpr std::array<double, 8> kCosV = {1.0, 0.9, 0.7, 0.5, 0.3, 0.15, 0.05, 0.01};
  const bool volumetric = !c.m.thinWalled && c.m.transparency > 0;
  std::vector<std::pair<Vec3, Vec3>> out;
  for (int k = 0; k < n; ++k) {
    const double cv = k < int(kCosV.size()) ? kCosV[std::size_t(k)] : 0.02 + 0.98 * rng.next_double();
    Vec3 v = direction(cv, 2 * kPi * rng.next_double());
    if (volumetric && k % 4 == 1) v = Vec3{v.x, v.y, -v.z};
    const double side = v.z < 0 ? -1.0 : 1.0;
    Vec3 l;
    const Vec3 nf = flake.normal;
    if (flake_mirror && k % 2 == 0 && dot(v, nf) > 0) {
      l = nf * (2 * dot(v, nf)) - v;  // the flake's mirror direction
    } else if (k % 5 == 0) {
      l = Vec3{-v.x, -v.y, v.z};  // the mirror direction
    } else {
      const double cl = 0.01 + 0.99 * rng.next_double(), phi = 2 * kPi * rng.next_double();
      l = direction(cl, phi);
      const bool other_side = transmits(c.m) && k % 2 == 1;
      l.z *= other_side ? -side : side;
    }
    out.emplace_back(v, l);
  }
  return out;
}

// Transmission seen from both sides: kTransmittedPairs more pairs for a material with
// transparency or translucency, l on the other side of the surface drawn from the reference's own
// sampler (a rough transmission lobe is narrow: uniform directions mostly miss it and expect 0),
// kept when its non-delta value is not 0 (else, after 64 draws, a uniform direction there); a
// volumetric material is seen from inside in every other pair: inside the escape cone (cos theta
// from the critical angle's, sqrt(1 - 1 / ior^2), to 1) or, every third of them, just beyond it
// (0.97 of its cosine: near total internal reflection, where only the rough lobe's tail gets out).
constexpr int kTransmittedPairs = 12;
std::vector<std::pair<Vec3, Vec3>> transmitted_pairs(const Case& c, const Bsdf& ref, Pcg32& rng) {
  if (!(c.m.transparency > 0 || c.m.translucency > 0)) return {};
  const bool volumetric = !c.m.thinWalled && c.m.transparency > 0;
  std::vector<std::pair<Vec3, Vec3>> out;
  for (int k = 0; k < kTransmittedPairs; ++k) {
    Vec3 v = direction(0.02 + 0.98 * rng.next_double(), 2 * kPi * rng.next_double());
    if (volumetric && k % 2 == 1) {
      const double critical = std::sqrt(std::max(0.0, 1 - 1 / (c.m.ior * c.m.ior)));
      const double cv = k % 6 == 5 ? 0.97 * critical : critical + (1 - critical) * rng.next_double();
      v = direction(cv, 2 * kPi * rng.next_double());
      v.z = -v.z;
    }
    std::optional<Vec3> l;
    for (int t = 0; t < 64 && !l; ++t) {
      const BsdfSample s = ref.sample(v, {rng.next_double(), rng.next_double(), rng.next_double()});
      if (s.valid && !(s.flags & kLobeDelta) && s.l.z * v.z < 0 && ref.eval(v, s.l).max_component() > 0) l = s.l;
    }
    if (!l) {
      l = direction(0.01 + 0.99 * rng.next_double(), 2 * kPi * rng.next_double());
      l->z = v.z < 0 ? l->z : -l->z;
    }
    out.emplace_back(v, *l);
  }
  return out;
}

// The extremes' directions: grazing (cos theta 1e-4) views and lights, mirror and not.
std::vector<std::pair<Vec3, Vec3>> extreme_pairs(const Case& c) {
  const Vec3 graze_v = direction(1e-4, 0.3);
  std::vector<std::pair<Vec3, Vec3>> out = {
      {graze_v, Vec3{-graze_v.x, -graze_v.y, graze_v.z}},
      {graze_v, direction(1.0, 0.0)},
      {direction(1.0, 0.0), direction(1e-4, 2.0)},
      {graze_v, direction(0.5, 2.5)},
      {direction(0.5, 1.0), direction(1e-4, 4.0)},
  };
  if (transmits(c.m)) {
    out.push_back({graze_v, Vec3{-graze_v.x, -graze_v.y, -graze_v.z}});
    out.push_back({direction(0.7, 0.2), direction(-1e-4, 3.0)});
  }
  return out;
}

// The delta lobes at v, found by sweeping the lobe choice u.x over kSweep stratified values: a
// lobe's interval of u.x is contiguous (docs/bsdf.md, "Sampling"), its samples have the same
// direction, weight and probability, and its probability times kSweep is the interval's length, so
// a run of k identical samples is round(k / (pdf kSweep)) lobes (several when identical lobes are
// adjacent). Lobes towards the same direction are summed. The probabilities found must not exceed
// p_delta, the probability of the delta lobes at v (infinite: unknown, not checked).
std::vector<DeltaExpectation> delta_lobes(const Bsdf& b, const Vec3& v, double p_delta) {
  if (!(p_delta > 0)) return {};
  constexpr int kSweep = 8192;
  std::vector<DeltaExpectation> out;
  double p_found = 0;
  auto add = [&](const BsdfSample& s, int run) {
    const double lobes = std::max(1.0, std::round(run / (s.pdf * kSweep)));
    p_found += lobes * s.pdf;
    const Rgb value = s.weight * (s.pdf * lobes);
    for (DeltaExpectation& d : out)
      if (length(d.l - s.l) < 1e-12) {
        d.value = d.value + value;
        return;
      }
    out.push_back({s.l, value});
  };
  BsdfSample prev;
  int run = 0;
  for (int k = 0; k < kSweep; ++k) {
    const BsdfSample s = b.sample(v, {(k + 0.5) / kSweep, 0.5, 0.5});
    const bool delta = s.valid && (s.flags & kLobeDelta);
    const bool same = delta && run > 0 && s.l.x == prev.l.x && s.l.y == prev.l.y && s.l.z == prev.l.z &&
                      s.pdf == prev.pdf && s.weight.r == prev.weight.r && s.weight.g == prev.weight.g &&
                      s.weight.b == prev.weight.b;
    if (!same && run > 0) add(prev, run), run = 0;
    if (delta) prev = s, ++run;
  }
  if (run > 0) add(prev, run);
  // A delta lobe whose sample fails (refraction under total internal reflection) counts in
  // delta_probability but transmits nothing (docs/bsdf.md, "Conventions": P(fail)).
  if (p_found > p_delta + 1e-6)
    throw std::logic_error("conformance: the delta lobes found (probability " + std::to_string(p_found) +
                           ") exceed delta_probability(v) = " + std::to_string(p_delta));
  return out;
}

// Table sets whose lookups are off by +-kTableError (ln(1 - q) encoded averages move 1 - q by the
// same amount, never below half of it). A value's table tolerance is the larger of two changes:
// - together: its largest change over the four sign combinations of every directional table
//   moved by s_dir and every cosine average by s_avg (sets 0-3);
// - apart: the sum over the six tables of its larger change when that table alone moves by + or -
//   (sets 4 + 2 t + k), a first-order bound for tables that err independently. Together alone
//   missed two tables erring apart: the pdf of a sheen over a base, whose lobe selection reads both
//   albedos, failed for tables nearer the exact albedos than the reference's (docs/design/renderer.md,
//   "sixth run"); apart alone gives less than together where the tables' errors interact (933 of
//   the default vectors' f cos; half of it for the metal of anisotropy 1, whose 1 - E_avg is tiny).
constexpr int kPerturbedTables = 6;    // GGX_E, GGX_beta, Sheen_E, Sheen_ash_E; GGX_E_avg, GGX_B_avg
constexpr int kDirectionalTables = 4;  // the first four
constexpr std::size_t kTogetherSets = 4;
constexpr std::size_t kPerturbedSets = kTogetherSets + 2 * kPerturbedTables;
const std::array<LutSet, kPerturbedSets>& perturbed_tables() {
  static const std::array<LutSet, kPerturbedSets> sets = [] {
    auto shift = [](WarpedTable& t, double s) {
      for (double& x : t.values)
        x = t.encoding == Encoding::LogOneMinus ? std::log(std::max(std::exp(x) - s * kTableError, 0.5 * std::exp(x)))
                                                : x + s * kTableError;
    };
    auto tables = [](RendererLuts& r) {
      return std::array<WarpedTable*, kPerturbedTables>{&r.ggx_E, &r.ggx_beta, &r.sheen_E, &r.sheen_ash_E, &r.ggx_E_avg, &r.ggx_B_avg};
    };
    std::array<LutSet, kPerturbedSets> out;
    for (std::size_t i = 0; i < kTogetherSets; ++i) {
      const double s_dir = (i & 1) ? -1.0 : 1.0, s_avg = (i & 2) ? -1.0 : 1.0;
      LutSet p = LutSet::builtin();
      const auto t = tables(p.renderer);
      for (int k = 0; k < kPerturbedTables; ++k) shift(*t[std::size_t(k)], k < kDirectionalTables ? s_dir : s_avg);
      out[i] = std::move(p);
    }
    for (int t = 0; t < kPerturbedTables; ++t)
      for (int k = 0; k < 2; ++k) {
        LutSet p = LutSet::builtin();
        shift(*tables(p.renderer)[std::size_t(t)], k ? -1.0 : 1.0);
        out[kTogetherSets + std::size_t(2 * t + k)] = std::move(p);
      }
    return out;
  }();
  return sets;
}

double max_channel_difference(const Rgb& a, const Rgb& b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

// The directional albedo of the non-delta lobes at v: a product rule over both hemispheres,
// mu_panels x 4 Gauss-Legendre nodes in cos theta_l and phi_steps midpoints in phi
// (integral of f |cos theta_l| dl = integral of f mu dmu dphi).
Rgb albedo_quadrature(const Bsdf& b, const Vec3& v, int mu_panels, int phi_steps) {
  static const QuadratureRule rule = gauss_legendre(4);
  Rgb sum{0, 0, 0};
  const double h = 1.0 / mu_panels, dphi = 2 * kPi / phi_steps;
  for (double side : {1.0, -1.0})
    for (int p = 0; p < mu_panels; ++p)
      for (std::size_t i = 0; i < rule.x.size(); ++i) {
        const double mu = (p + 0.5) * h + 0.5 * h * rule.x[i], w = rule.w[i] * 0.5 * h * mu * dphi;
        for (int j = 0; j < phi_steps; ++j) {
          Vec3 l = direction(mu, (j + 0.5) * dphi);
          l.z *= side;
          sum = sum + b.eval(v, l) * w;
        }
      }
  return sum;
}

// generate's finer albedo quadrature (32 panels x 128 azimuths), the one a vector's albedo is
// (generate, expect_with and implementation_result alike) ...
Rgb fine_albedo_quadrature(const Bsdf& b, const Vec3& v) { return albedo_quadrature(b, v, 32, 128); }
// ... with the delta lobes at v added.
Rgb albedo_with_delta_lobes(const Rgb& non_delta, const std::vector<DeltaExpectation>& delta) {
  Rgb a = non_delta;
  for (const DeltaExpectation& d : delta) a = a + d.value;
  return a;
}

// The material with every number rounded to single precision: what an implementation in float
// reads (the tolerance's input part, docs/conformance.md "Tolerances").
Material float_rounded(Material m) {
  // Beyond the float range the value becomes +-inf (a double -> float conversion out of range is
  // undefined behaviour).
  auto f = [](double& x) {
    x = std::abs(x) <= double(std::numeric_limits<float>::max()) ? double(float(x)) : std::copysign(HUGE_VAL, x);
  };
  auto c = [&](Rgb& x) { f(x.r), f(x.g), f(x.b); };
  auto v = [&](Vec3& x) { f(x.x), f(x.y), f(x.z); };
  c(m.albedo), f(m.metallic), f(m.roughness), f(m.anisotropy), f(m.anisotropyRotation), v(m.normal);
  v(m.displacement), f(m.translucency), c(m.translucencyColor), f(m.transparency), f(m.cutoutOpacity);
  f(m.specular), c(m.specularTint), f(m.thinFilm), f(m.thinFilmThickness), f(m.thinFilmIor), c(m.sheenColor);
  f(m.sheenRoughness), f(m.flakeCoverage), c(m.flakeColor), f(m.flakeSize), f(m.flakeRoughness), f(m.flipFlop);
  c(m.flipFlopColor), f(m.clearcoat), f(m.clearcoatRoughness), v(m.clearcoatNormal), c(m.emissionColor);
  f(m.emissionValue), f(m.ior), f(m.abbeNumber), c(m.attenuationColor), f(m.attenuationDistance);
  c(m.subsurfaceColor), f(m.subsurfaceAnisotropy);
  return m;
}
Vec3 float_rounded(const Vec3& w) { return {double(float(w.x)), double(float(w.y)), double(float(w.z))}; }

// The vectors of one material (its index seeds its directions).
std::vector<Vector> case_vectors(const Case& c, std::size_t index, const GenerateSettings& s) {
  Pcg32 rng(s.seed, index);
  Vector proto;
  proto.group = c.group;
  proto.material = instance_json(c.m);
  proto.gltf_material = c.gltf;
  proto.options = c.options;
  // The expected values come from the instance as an implementer reads it.
  const Material m = vector_material(proto);
  // A built-in material as glTF too, when glTF can express it (gltf_export.h: mapped back exactly).
  if (proto.gltf_material.is_null())
    if (const nlohmann::json g = gltf::gltf_material_for(m, c.group + "/" + c.name); !g.is_null())
      proto.gltf_material = OJson::parse(g.dump());
  const BsdfOptions opt = vector_options(proto);
  const uint32_t mask = active_components(m);
  proto.components = component_names(mask);
  const MaterialBsdf ref(m, LutSet::builtin(), opt, mask);
  auto pairs = c.extreme ? extreme_pairs(c) : usual_pairs(c, opt, s.directions, rng);
  if (!c.extreme)
    for (const auto& p : transmitted_pairs(c, ref, rng)) pairs.push_back(p);
  std::vector<MaterialBsdf> perturbed;
  for (const LutSet& t : perturbed_tables()) perturbed.emplace_back(m, t, opt, mask);
  const MaterialBsdf ref_float(float_rounded(m), LutSet::builtin(), opt, mask);
  const bool thin_film = (mask & kThinFilm) != 0;
  const double rel = kFloatRelative + (thin_film ? kThinFilmRelative : 0.0);

  std::vector<Vector> out;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    Vector x = proto;
    char num[24];
    std::snprintf(num, sizeof num, "%02zu", k);
    x.id = c.group + "/" + c.name + "/" + num;
    x.v = pairs[k].first;
    x.l = pairs[k].second;
    x.f_cos = ref.eval(x.v, x.l) * std::abs(x.l.z);
    x.pdf = ref.pdf(x.v, x.l);
    // The tables' part (perturbed_tables): the larger of the tables moved together and apart.
    std::array<double, kPerturbedSets> df_set{}, dp_set{};
    for (std::size_t i = 0; i < kPerturbedSets; ++i) {
      df_set[i] = max_channel_difference(perturbed[i].eval(x.v, x.l) * std::abs(x.l.z), x.f_cos);
      dp_set[i] = std::abs(perturbed[i].pdf(x.v, x.l) - x.pdf);
    }
    auto table_part = [](const std::array<double, kPerturbedSets>& d) {
      const double together = *std::max_element(d.begin(), d.begin() + kTogetherSets);
      double apart = 0;
      for (std::size_t t = 0; t < kPerturbedTables; ++t)
        apart += std::max(d[kTogetherSets + 2 * t], d[kTogetherSets + 2 * t + 1]);
      return std::max(together, apart);
    };
    double df = table_part(df_set), dp = table_part(dp_set);
    // Inputs in float: the change of f cos and pdf when the material and the directions are
    // rounded to single precision (large only where the configuration is ill-conditioned, e.g. a
    // transmission at grazing through an IOR near 1).
    const Vec3 vf = float_rounded(x.v), lf = float_rounded(x.l);
    df += max_channel_difference(ref_float.eval(vf, lf) * std::abs(lf.z), x.f_cos);
    dp += std::abs(ref_float.pdf(vf, lf) - x.pdf);
    x.tolerance = {kFloatAbsolute + 2 * df, rel};
    x.pdf_tolerance = {kFloatAbsolute + 2 * dp, rel};
    if (mask & kEmission) {
      x.emission = ref.emission(x.v);
      x.emission_tolerance = {kFloatAbsolute, kFloatRelative};
    }
    try {
      x.delta = delta_lobes(ref, x.v, ref.delta_probability(x.v));
    } catch (const std::logic_error& e) {
      throw std::logic_error(x.id + ": " + e.what());
    }
    x.delta_tolerance = {kFloatAbsolute, rel};
    if (k == 0 && s.albedo) {
      // Product Gauss-Legendre quadrature at two resolutions; kept where they agree within
      // kAlbedoAgreement, judged within twice their difference plus the tables' error.
      const Rgb coarse = albedo_quadrature(ref, x.v, 16, 64), fine = fine_albedo_quadrature(ref, x.v);
      const double err = max_channel_difference(coarse, fine);
      if (err <= kAlbedoAgreement) {
        x.albedo = albedo_with_delta_lobes(fine, x.delta);
        x.albedo_tolerance = {kTableError + 2 * err + kFloatAbsolute, kFloatRelative};
      }
    }
    out.push_back(std::move(x));
  }
  return out;
}

Material with(Material m, const std::function<void(Material&)>& f) {
  f(m);
  return m;
}

// The built-in materials: each component alone (over the base it needs), the plain sets, the
// combinations and the extremes.
std::vector<Case> builtin_cases() {
  std::vector<Case> c;
  auto add = [&](const std::string& group, const std::string& name, const std::function<void(Material&)>& f,
                 OJson options = nullptr) {
    c.push_back({group, name, with(Material{}, f), std::move(options), nullptr, false});
  };
  const Rgb gold{1.0, 0.78, 0.34}, red{0.8, 0.1, 0.05};
  // A first check: a plain isotropic metal and a plain plastic.
  for (double r : {0.1, 0.3, 0.6, 1.0}) {
    const std::string rs = std::to_string(int(std::lround(r * 100)));
    add("plain_metal", "gold-r" + rs, [&](Material& m) { m.metallic = 1, m.albedo = gold, m.roughness = r; });
    add("plain_plastic", "red-r" + rs, [&](Material& m) { m.albedo = red, m.roughness = r; });
  }
  // The core: metal and dielectric, specular colour and f90 (specular weight), anisotropy with rotation.
  add("metallic", "metal-mirror", [&](Material& m) { m.metallic = 1, m.albedo = gold, m.roughness = 0; });
  add("metallic", "metal-specular-tint", [&](Material& m) {
    m.metallic = 1, m.albedo = gold, m.roughness = 0.4, m.specular = 0.6, m.specularTint = {0.5, 0.9, 1.0};
  });
  add("metallic", "metal-anisotropic-rotated", [&](Material& m) {
    m.metallic = 1, m.albedo = gold, m.roughness = 0.4, m.anisotropy = 0.8, m.anisotropyRotation = 0.15;
  });
  add("metallic", "metal-dielectric-mix", [&](Material& m) { m.metallic = 0.4, m.albedo = gold, m.roughness = 0.3; });
  add("opaque_dielectric", "dielectric-specular-colour", [&](Material& m) {
    m.albedo = {0.2, 0.5, 0.8}, m.roughness = 0.35, m.specular = 0.5, m.specularTint = {1.0, 0.6, 0.3}, m.ior = 1.7;
  });
  add("opaque_dielectric", "dielectric-anisotropic-rotated", [&](Material& m) {
    m.albedo = {0.2, 0.5, 0.8}, m.roughness = 0.5, m.anisotropy = 0.6, m.anisotropyRotation = 0.7;
  });
  add("opaque_dielectric", "dielectric-smooth", [&](Material& m) { m.albedo = {0.2, 0.5, 0.8}, m.roughness = 0; });
  // Layers.
  add("clearcoat", "clearcoat-over-dielectric", [&](Material& m) {
    m.albedo = red, m.roughness = 0.5, m.clearcoat = 1, m.clearcoatRoughness = 0.1;
  });
  add("clearcoat", "clearcoat-over-metal", [&](Material& m) {
    m.metallic = 1, m.albedo = gold, m.roughness = 0.6, m.clearcoat = 0.7, m.clearcoatRoughness = 0.3;
  });
  add("sheen", "sheen-main", [&](Material& m) {
    m.albedo = {0.1, 0.1, 0.4}, m.roughness = 0.6, m.sheenColor = {0.9, 0.7, 0.8}, m.sheenRoughness = 0.4;
  });
  add("sheen", "sheen-ash", [&](Material& m) {
    m.albedo = {0.1, 0.1, 0.4}, m.roughness = 0.6, m.sheenColor = {0.9, 0.7, 0.8}, m.sheenRoughness = 0.4;
  }, OJson{{"sheen", "ash"}});
  add("sheen", "sheen-main-over-metal", [&](Material& m) {
    m.metallic = 1, m.albedo = gold, m.roughness = 0.3, m.sheenColor = {1, 1, 1}, m.sheenRoughness = 0.8;
  });
  const OJson flake_point{{"position", {0.0123, 0.0456, 0.0}}, {"object_normal", {0.0, 0.0, 1.0}}};
  add("flakes", "flakes-rough", [&](Material& m) {
    m.albedo = red, m.roughness = 0.4, m.flakeCoverage = 1, m.flakeSize = 0.5, m.flakeRoughness = 0.3,
    m.flakeColor = {0.9, 0.9, 0.95};
  }, flake_point);
  add("flakes", "flakes-flip-flop", [&](Material& m) {
    m.albedo = red, m.roughness = 0.4, m.flakeCoverage = 0.6, m.flakeSize = 0.2, m.flakeRoughness = 0.5,
    m.flipFlop = 1, m.flipFlopColor = {0.2, 0.9, 0.4};
  }, flake_point);
  add("thin_film", "film-over-dielectric", [&](Material& m) {
    m.albedo = {0.05, 0.05, 0.05}, m.roughness = 0.2, m.thinFilm = 1, m.thinFilmThickness = 0.5, m.thinFilmIor = 1.4;
  });
  add("thin_film", "film-over-metal", [&](Material& m) {
    m.metallic = 1, m.albedo = {0.6, 0.6, 0.6}, m.roughness = 0.3, m.thinFilm = 0.8, m.thinFilmThickness = 0.3;
  });
  add("translucency", "translucent", [&](Material& m) {
    m.albedo = {0.8, 0.8, 0.6}, m.roughness = 0.4, m.translucency = 0.6, m.translucencyColor = {0.9, 0.3, 0.2};
  });
  add("thin_transparent", "thin-glass-rough", [&](Material& m) {
    m.transparency = 1, m.roughness = 0.3, m.albedo = {0.9, 0.95, 1.0};
  });
  add("thin_transparent", "thin-glass-smooth", [&](Material& m) { m.transparency = 1, m.roughness = 0; });
  add("volumetric_transparent", "glass-rough", [&](Material& m) {
    m.transparency = 1, m.thinWalled = false, m.roughness = 0.3, m.albedo = {0.9, 0.95, 1.0};
  });
  add("volumetric_transparent", "glass-smooth", [&](Material& m) {
    m.transparency = 1, m.thinWalled = false, m.roughness = 0, m.ior = 1.5;
  });
  add("volumetric_transparent", "glass-dense-rough", [&](Material& m) {
    m.transparency = 0.8, m.thinWalled = false, m.roughness = 0.6, m.ior = 2.2, m.albedo = {0.7, 0.9, 0.8};
  });
  add("cut_out", "cut-out-plastic", [&](Material& m) { m.albedo = red, m.roughness = 0.5, m.cutoutOpacity = 0.4; });
  add("emission", "emissive-plastic", [&](Material& m) {
    m.albedo = red, m.roughness = 0.5, m.emissionValue = 250, m.emissionColor = {1.0, 0.8, 0.6};
  });
  add("emission", "emissive-under-clearcoat", [&](Material& m) {
    m.albedo = red, m.roughness = 0.5, m.emissionValue = 100, m.clearcoat = 1, m.clearcoatRoughness = 0.2;
  });
  // Combined.
  add("combined", "carpaint", [&](Material& m) {
    m.albedo = {0.5, 0.02, 0.02}, m.roughness = 0.4, m.flakeCoverage = 0.5, m.flakeSize = 0.3, m.flakeRoughness = 0.2,
    m.clearcoat = 1, m.clearcoatRoughness = 0.05, m.thinFilm = 0.3;
  }, flake_point);
  add("combined", "velvet-metal-translucent", [&](Material& m) {
    m.metallic = 0.3, m.albedo = {0.6, 0.4, 0.8}, m.roughness = 0.5, m.translucency = 0.4, m.sheenColor = {0.5, 0.5, 0.5},
    m.sheenRoughness = 0.3, m.anisotropy = 0.5, m.anisotropyRotation = 0.3;
  });
  add("combined", "coated-film-glass", [&](Material& m) {
    m.transparency = 1, m.thinWalled = false, m.roughness = 0.25, m.thinFilm = 1, m.clearcoat = 0.5,
    m.clearcoatRoughness = 0.1, m.cutoutOpacity = 0.8, m.ior = 1.33;
  });
  add("combined", "everything", [&](Material& m) {
    m.metallic = 0.2, m.albedo = {0.7, 0.5, 0.3}, m.roughness = 0.45, m.anisotropy = 0.3, m.anisotropyRotation = 0.2,
    m.translucency = 0.3, m.transparency = 0.3, m.specular = 0.8, m.specularTint = {1.0, 0.9, 0.8}, m.thinFilm = 0.5,
    m.sheenColor = {0.3, 0.3, 0.3}, m.flakeCoverage = 0.3, m.flakeSize = 0.2, m.flakeRoughness = 0.4,
    m.clearcoat = 0.6, m.clearcoatRoughness = 0.2, m.emissionValue = 10, m.cutoutOpacity = 0.9;
  }, flake_point);
  // The extremes: roughness 0 and 1, ior near 1, black and white albedo, at grazing directions.
  auto extreme = [&](const std::string& name, const std::function<void(Material&)>& f) {
    c.push_back({"extremes", name, with(Material{}, f), nullptr, nullptr, true});
  };
  extreme("metal-r0", [](Material& m) { m.metallic = 1, m.roughness = 0; });
  extreme("metal-r1-white", [](Material& m) { m.metallic = 1, m.roughness = 1, m.albedo = {1, 1, 1}; });
  extreme("plastic-r0-black", [](Material& m) { m.roughness = 0, m.albedo = {0, 0, 0}; });
  extreme("plastic-r1-white", [](Material& m) { m.roughness = 1, m.albedo = {1, 1, 1}; });
  extreme("plastic-r1-black", [](Material& m) { m.roughness = 1, m.albedo = {0, 0, 0}; });
  extreme("dielectric-ior-1.01", [](Material& m) { m.roughness = 0.3, m.ior = 1.01; });
  extreme("glass-ior-1.01", [](Material& m) { m.transparency = 1, m.thinWalled = false, m.roughness = 0.3, m.ior = 1.01; });
  extreme("glass-r1", [](Material& m) { m.transparency = 1, m.thinWalled = false, m.roughness = 1; });
  extreme("thin-glass-r1", [](Material& m) { m.transparency = 1, m.roughness = 1; });
  extreme("sheen-r0", [](Material& m) { m.sheenColor = {1, 1, 1}, m.sheenRoughness = 0, m.roughness = 0.5; });
  return c;
}

// An emission a float implementation cannot represent (the eighth fresh tester's pass: the vectors
// expected it and the shader library, in float, gave 0 or the largest float): a colour channel that
// is not 0 but below the smallest normal float (1.2e-38), or an emitted luminance beyond the
// largest float. "" when representable.
std::string emission_float_problem(const Material& m) {
  if (!(m.emissionValue > 0)) return "";
  const double smallest = double(std::numeric_limits<float>::min()), largest = double(std::numeric_limits<float>::max());
  for (double c : {m.emissionColor.r, m.emissionColor.g, m.emissionColor.b})
    if (c > 0 && c < smallest)
      return fmt::format("emissionColor has a channel of {:.3g}", c) +
             ", below the smallest normal float (1.2e-38): a float implementation reads 0 or loses its precision";
  const Rgb rho_e = emission_rho_e(m, 1.0);
  if (rho_e.max_component() > largest)
    return fmt::format("its emitted luminance {:.3g} cd/m^2 is beyond the largest float (3.4e38)", rho_e.max_component());
  return "";
}

// The materials of the .gltf files of `dir` (sorted by file name), mapped by docs/gltf_mapping.md.
std::vector<Case> scene_cases(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (gltf::lower_extension(it->path().string()) == ".gltf") files.push_back(it->path());
  if (ec) throw std::runtime_error(dir + ": cannot list the scene folder: " + ec.message());
  std::sort(files.begin(), files.end());
  std::vector<Case> out;
  // A case name is the file's stem, "-<material index>" added when the file has several: x.gltf's
  // material 1 and x-1.gltf would share the vector ids scenes/x-1/NN; such a set is refused.
  std::map<std::string, std::string> named_by;  // case name -> the file (and material) it came from
  for (const fs::path& f : files) {
    // The stem becomes vector ids, which the CSV files hold one per line: a control character (a
    // newline) would break the line (the sixth fresh tester's pass: the results reader then refused
    // its own quoted row).
    const std::string stem = f.stem().string();
    if (std::any_of(stem.begin(), stem.end(), [](char ch) { return static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f; }))
      throw std::runtime_error(quote_input(f.string()) +
                               ": the file name has a control character, which no vector id may hold: rename the file");
    const gltf::GltfFile file = gltf::read_gltf(f.string());
    const std::vector<gltf::GltfMaterial> mats = gltf::map_materials(file);
    for (const gltf::GltfMaterial& gm : mats) {
      Case c{"scenes", f.stem().string(), gm.material, nullptr, file.json["materials"][std::size_t(gm.index)], false};
      if (mats.size() > 1) c.name += "-" + std::to_string(gm.index);
      std::string source = f.string() + (mats.size() > 1 ? " (material " + std::to_string(gm.index) + ")" : "");
      const auto [it, fresh] = named_by.emplace(c.name, source);
      if (!fresh)
        throw std::runtime_error(it->second + " and " + source + " both give the vector ids scenes/" + c.name +
                                 "/NN: rename one of the files");
      // A factor outside the model's range, or beyond a float's (the vectors' materials are rounded
      // to float, as the implementations judged read them): the file and material.
      std::string problem;
      try {
        validate_material(c.m);
      } catch (const std::exception& e) {
        problem = e.what();
      }
      if (problem.empty()) try {
          validate_material(float_rounded(c.m));
        } catch (const std::exception& e) {
          problem = std::string("beyond the range of a float (the vectors' materials are rounded to float): ") + e.what();
        }
      if (problem.empty()) problem = emission_float_problem(c.m);
      if (!problem.empty()) {
        const OJson name = c.gltf.is_object() && c.gltf.contains("name") ? c.gltf["name"] : OJson();
        throw std::runtime_error(f.string() + ": materials[" + std::to_string(gm.index) + "]" +
                                 (name.is_string() ? " '" + quote_input(name.get<std::string>()) + "'" : std::string()) + ": " +
                                 problem);
      }
      out.push_back(std::move(c));
    }
    if (out.size() > limits::kSceneMaterials)  // the folder's, as one scene analyze run's (limits.h)
      throw std::runtime_error(f.string() + ": the scene folder holds more than " +
                               std::to_string(limits::kSceneMaterials) + " materials, the limit (docs/limits.md)");
  }
  return out;
}

}  // namespace

Material vector_material(const Vector& v) {
  return material_from_instance(ParamDefs::builtin(), nlohmann::json(v.material));
}

BsdfOptions vector_options(const Vector& v) {
  BsdfOptions o;
  if (v.options.is_null()) return o;
  if (!v.options.is_object()) throw std::runtime_error("options must be an object");
  for (auto it = v.options.begin(); it != v.options.end(); ++it) {
    const std::string& key = it.key();
    const nlohmann::ordered_json& value = it.value();
    auto vec = [&key, &value]() {
      if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
          !value[2].is_number())
        throw std::runtime_error("options." + key + " must be 3 numbers");
      return Vec3{value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
    };
    if (key == "sheen") {
      if (value == "main") o.sheen_model = SheenModel::Main;
      else if (value == "ash") o.sheen_model = SheenModel::Ash;
      else throw std::runtime_error("options.sheen must be \"main\" or \"ash\"");
    } else if (key == "position") {
      o.position = vec();
    } else if (key == "object_normal") {
      const Vec3 n = vec();
      const double len = length(n);
      if (!(len > 0) || !std::isfinite(len)) throw std::runtime_error("options.object_normal must be a non-zero finite vector");
      o.object_normal = normalize(n);
    } else {
      throw std::runtime_error("unknown option \"" + key + "\" (known: sheen, position, object_normal)");
    }
  }
  return o;
}

Evaluation evaluate(const Vector& v, const LutSet& luts) {
  const Material m = vector_material(v);
  const MaterialBsdf b(m, luts, vector_options(v), active_components(m));
  return {b.eval(v.v, v.l) * std::abs(v.l.z), b.pdf(v.v, v.l)};
}

MaterialBsdf represented_bsdf(const Vector& v, Material m, const Representation& r, Deviation deviation) {
  const uint32_t mask = active_components(m);  // of the material as given (a clamp adds no component)
  m.roughness = std::max(m.roughness, r.min_roughness);
  m.clearcoatRoughness = std::max(m.clearcoatRoughness, r.min_roughness);
  BsdfOptions o = vector_options(v);
  o.deviation = deviation;
  return MaterialBsdf(m, r.tables != nullptr ? *r.tables : LutSet::builtin(), o, mask);
}

void expect_with(std::vector<Vector>& vectors, const Representation& r) {
  // Each vector's material is built once per vector (as evaluate does): independent, so parallel.
  tbb::parallel_for(std::size_t(0), vectors.size(), [&](std::size_t i) {
    Vector& v = vectors[i];
    try {
      const MaterialBsdf b = represented_bsdf(v, vector_material(v), r);
      v.f_cos = b.eval(v.v, v.l) * std::abs(v.l.z);
      v.pdf = b.pdf(v.v, v.l);
      v.delta = delta_lobes(b, v.v, b.delta_probability(v.v));
      if (v.albedo && r.min_roughness == 0) v.albedo = albedo_with_delta_lobes(fine_albedo_quadrature(b, v.v), v.delta);
    } catch (const std::exception& e) {
      throw std::runtime_error("vector '" + v.id + "': " + e.what());
    }
  });
}

Result implementation_result(const Vector& x, const Bsdf& b) {
  Result r;
  r.id = x.id;
  r.f_cos = b.eval(x.v, x.l) * std::abs(x.l.z);
  r.pdf = b.pdf(x.v, x.l);
  // The sweep only where b says it has a Dirac lobe (8192 samples a vector).
  r.delta = (b.flags() & kLobeDelta) ? delta_lobes(b, x.v, std::numeric_limits<double>::infinity())
                                     : std::vector<DeltaExpectation>{};
  if (x.albedo) r.albedo = albedo_with_delta_lobes(fine_albedo_quadrature(b, x.v), *r.delta);
  return r;
}

std::vector<Vector> generate_vectors(const GenerateSettings& s) {
  std::vector<Case> cases = builtin_cases();
  if (!s.scenes_dir.empty()) {
    std::vector<Case> scenes = scene_cases(s.scenes_dir);
    cases.insert(cases.end(), std::make_move_iterator(scenes.begin()), std::make_move_iterator(scenes.end()));
  }
  std::vector<std::vector<Vector>> per_case(cases.size());
  // Each material's vectors depend on its index and the seed alone: any thread count, same set.
  tbb::parallel_for(std::size_t(0), cases.size(), [&](std::size_t i) { per_case[i] = case_vectors(cases[i], i, s); });
  std::vector<Vector> out;
  for (auto& vs : per_case)
    for (Vector& v : vs) out.push_back(std::move(v));
  return out;
}

}  // namespace dspbr::conformance
