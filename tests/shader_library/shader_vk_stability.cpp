// The validation's stability scan (src/dspbr/validate/stability.h) of the shader library on a
// Vulkan device (Mesa's lavapipe without a GPU): every eval, pdf and sample the scan makes is
// computed by the kernel (conformance.comp or .hlsl with DSPBR_TEST_STABILITY: modes 4 and 5 of
// kernel_common.glsl), and the scan's own code counts NaN, Inf, negative values and sampled
// directions that are not unit. The materials are those `dspbr validate` scans the library's C++
// compile on ("shader library: stability", apps/dspbr/validate_shader_library.cpp): every corner of
// the validation's catalog and one random material in four, with the same 300 random directions.
// On top, per material, views and lights that are NaN, +-Inf, zero or not unit: f and pdf must be
// finite and non-negative and a sample invalid or finite.
//   shader_vk_stability KERNEL.spv LUT_DIR LABEL [K/N]
// (K/N: the materials whose index is K modulo N; all by default.)
// The scan runs twice: the first records its queries (answering 0 and no sample), the device
// answers them all in two dispatches per material, and the second is the verdict.
// Exit 0: no failure; 1: a failure (each material's counts printed); 2: bad arguments or a Vulkan
// error; 77: no Vulkan device.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "dspbr/bsdf/material_bsdf.h"
#include "dspbr/shader/material_mapping.h"
#include "dspbr/validate/catalog.h"
#include "dspbr/validate/stability.h"
#include "dspbr/validate/suite.h"
#include "shader_material.h"
#include "vk_queries.h"

namespace {

using dspbr::Vec3;
using shader_test::exact_key;
using Key = shader_test::ExactKey<6>;
using KeyHash = shader_test::ExactKeyHash;

struct Query {
  Vec3 v, w;
};

// The device's answers by their inputs. Until stop_recording() it records the queries it has no
// answer for and answers 0 and no sample (the scan's first round, whose counts are not the
// verdict); after it, such a query counts as unanswered.
class DeviceBsdf : public dspbr::Bsdf {
 public:
  dspbr::Rgb eval(const Vec3& v, const Vec3& l) const override { return value(v, l).f; }
  double pdf(const Vec3& v, const Vec3& l) const override { return value(v, l).pdf; }
  dspbr::BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    const auto it = samples_.find(exact_key(v, u));
    if (it != samples_.end()) return it->second;
    if (!recording_) ++unanswered_;
    else if (pending_sample_keys_.insert(exact_key(v, u)).second) pending_samples_.push_back({v, u});
    return dspbr::BsdfSample{};
  }
  uint32_t flags() const override { return 0; }

  std::vector<Query> take_evals() { return std::move(pending_evals_); }
  std::vector<Query> take_samples() { return std::move(pending_samples_); }
  void answer_eval(const Query& q, const dspbr::Rgb& f, double pdf) { evals_[exact_key(q.v, q.w)] = {f, pdf}; }
  void answer_sample(const Query& q, const dspbr::BsdfSample& s) { samples_[exact_key(q.v, q.w)] = s; }
  // After the answers: a query not answered is an error of this harness, not of the library.
  void stop_recording() { recording_ = false; }
  std::size_t unanswered() const { return unanswered_; }

 private:
  struct Value {
    dspbr::Rgb f;
    double pdf = 0;
  };
  Value value(const Vec3& v, const Vec3& l) const {
    const auto it = evals_.find(exact_key(v, l));
    if (it != evals_.end()) return it->second;
    if (recording_) {
      if (pending_eval_keys_.insert(exact_key(v, l)).second) pending_evals_.push_back({v, l});
    } else {
      ++unanswered_;
    }
    return {};
  }
  bool recording_ = true;
  mutable std::size_t unanswered_ = 0;
  std::unordered_map<Key, Value, KeyHash> evals_;
  std::unordered_map<Key, dspbr::BsdfSample, KeyHash> samples_;
  mutable std::unordered_set<Key, KeyHash> pending_eval_keys_, pending_sample_keys_;
  mutable std::vector<Query> pending_evals_, pending_samples_;
};

bool finite_non_negative(double x) { return std::isfinite(x) && x >= 0; }

std::string case_name(const dspbr::validate::StabilityCase& c) { return c.component + " / " + c.corner; }

}  // namespace

int main(int argc, char** argv) {
  unsigned part = 0, parts = 1;
  if (!shader_test::parse_part(argc, argv, part, parts)) {
    std::fprintf(stderr, "usage: shader_vk_stability KERNEL.spv LUT_DIR LABEL [K/N] (K < N: the materials K modulo N)\n");
    return 2;
  }
  const char* label = argv[3];
  try {
    shader_test::DeviceKernel kernel("dspbr shader stability");
    if (!kernel.open(argv[1], argv[2], label)) return 77;
    // The materials of the validation's "shader library: stability", with its settings (the full
    // run's: its seed and 300 random pairs; stream = the case's index, as run_stability numbers them).
    const std::vector<dspbr::validate::StabilityCase> cases =
        dspbr::validate::whole_material_stability(dspbr::validate::dspbr_catalog({}));
    const dspbr::validate::SuiteSettings suite = dspbr::validate::SuiteSettings::defaults(false);
    dspbr::validate::StabilitySettings settings = suite.stability;
    settings.seed = suite.seed;
    // Inputs no direction should be: NaN, +-Inf, zero, not unit (each against a plain direction).
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const Vec3 plain{0.3, 0.2, 0.9};
    const std::vector<Vec3> bad = {{nan, 0, 1}, {0, 0, nan}, {inf, 0, 1}, {0, 0, -inf}, {0, 0, 0}, {0, 0, 1e-30}, {3, 4, 12}};
    std::vector<Query> bad_pairs;
    for (const Vec3& b : bad) bad_pairs.push_back({b, plain}), bad_pairs.push_back({plain, b});
    // One dispatch of `mode` over the queries (v, w) after the material's record.
    auto dispatch = [&](const dspbr::validate::StabilityCase& c, const std::vector<Query>& qs, uint32_t mode,
                        std::size_t floats) {
      float record[shader_test::kRecordFloats] = {};
      dspbr::shader::pack_shader_inputs(*c.material, c.options, Vec3{0, 0, 1}, Vec3{0, 0, 1}, record);
      std::vector<float> q;
      for (const Query& x : qs) q.insert(q.end(), {float(x.v.x), float(x.v.y), float(x.v.z), float(x.w.x), float(x.w.y), float(x.w.z)});
      return shader_test::run_queries(kernel, record, q, 6, mode, floats);
    };
    dspbr::validate::StabilityCounts total;
    std::size_t failed = 0, bad_failed = 0, checked = 0;
    std::size_t worst = cases.size();  // the material of the largest sample weight, and its sample
    dspbr::BsdfSample worst_sample;
    for (std::size_t i = part; i < cases.size(); i += parts) {
      const dspbr::validate::StabilityCase& c = cases[i];
      const std::string name = case_name(c);
      DeviceBsdf dev;
      settings.stream = i;
      dspbr::validate::stability_scan(dev, settings);  // records
      std::vector<Query> evals = dev.take_evals();
      evals.insert(evals.end(), bad_pairs.begin(), bad_pairs.end());
      std::vector<Query> samples = dev.take_samples();
      samples.insert(samples.end(), bad_pairs.begin(), bad_pairs.end());  // (bad v, u) and (v, bad u)
      const std::vector<float> e = dispatch(c, evals, 4, 4);
      for (std::size_t k = 0; k < evals.size(); ++k)
        dev.answer_eval(evals[k], dspbr::Rgb(e[4 * k], e[4 * k + 1], e[4 * k + 2]), e[4 * k + 3]);
      const std::vector<float> s = dispatch(c, samples, 5, 9);
      for (std::size_t k = 0; k < samples.size(); ++k) dev.answer_sample(samples[k], shader_test::sample_from_floats(&s[9 * k]));
      dev.stop_recording();
      const dspbr::validate::StabilityCounts st = dspbr::validate::stability_scan(dev, settings);  // the verdict
      if (st.max_weight > total.max_weight) {
        worst = i;
        worst_sample = dev.sample(st.max_weight_v, st.max_weight_u);
      }
      total += st;
      ++checked;
      // The inputs no direction should be: no value may be NaN, Inf or negative, a sample not valid
      // unless finite.
      std::size_t bad_here = 0;
      for (const Query& q : bad_pairs) {
        const dspbr::Rgb f = dev.eval(q.v, q.w);
        for (int k = 0; k < 3; ++k) bad_here += !finite_non_negative(f[k]);
        bad_here += !finite_non_negative(dev.pdf(q.v, q.w));
        const dspbr::BsdfSample x = dev.sample(q.v, q.w);
        if (x.valid)
          bad_here += !finite_non_negative(x.pdf) || !std::isfinite(x.l.x + x.l.y + x.l.z) ||
                      !finite_non_negative(x.weight[0]) || !finite_non_negative(x.weight[1]) ||
                      !finite_non_negative(x.weight[2]);
      }
      if (dev.unanswered() > 0) throw std::runtime_error(name + ": queries the device did not answer");
      if (st.total_failures() > 0 || bad_here > 0) {
        ++failed;
        bad_failed += bad_here;
        std::printf("%s FAIL %s: %zu NaN, %zu Inf, %zu negative, %zu directions not unit; %zu bad values for "
                    "non-finite or non-unit inputs\n",
                    label, name.c_str(), st.nan, st.inf, st.negative, st.bad_direction, bad_here);
      }
    }
    std::printf("%s: stability scan on the device, %zu of %zu materials clean (%zu evaluations: %zu NaN, %zu Inf, "
                "%zu negative, %zu directions not unit; %zu bad values for non-finite or non-unit inputs)\n",
                label, checked - failed, checked, total.evaluations, total.nan, total.inf, total.negative,
                total.bad_direction, bad_failed);
    if (worst < cases.size()) {
      // The largest weight (a firefly, not a failure: docs/validation.md) beside the reference's
      // (double): its own sample for the same view and random numbers, and its f |cos| / pdf at
      // the device's sampled direction.
      const Vec3 &v = total.max_weight_v, &u = total.max_weight_u;
      const dspbr::validate::StabilityCase& c = cases[worst];
      const dspbr::MaterialBsdf reference(*c.material, dspbr::LutSet::builtin(), c.options);
      const dspbr::BsdfSample own = reference.sample(v, u);
      const Vec3& l = worst_sample.l;
      const double ref_pdf = reference.pdf(v, l);
      const double ref_ratio = reference.eval(v, l)[0] * std::abs(l.z) / ref_pdf;
      std::printf("%s: largest sample weight %.3g: %s at v (%.9g, %.9g, %.9g), u (%.9g, %.9g, %.9g): l (%.9g, %.9g, "
                  "%.9g), pdf %.3g\n",
                  label, total.max_weight, case_name(c).c_str(), v.x, v.y, v.z, u.x, u.y, u.z, l.x, l.y, l.z,
                  worst_sample.pdf);
      std::printf("%s: the reference there: at that l pdf %.3g and f |cos| / pdf %.3g; its own sample l (%.9g, %.9g, "
                  "%.9g), pdf %.3g, weight %.3g\n",
                  label, ref_pdf, ref_ratio, own.l.x, own.l.y, own.l.z, own.pdf, own.valid ? own.weight[0] : 0.0);
    }
    return failed == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shader_vk_stability: %s\n", e.what());
    return 2;
  }
}
