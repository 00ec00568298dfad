// The chi-square test of sample against pdf (src/dspbr/validate/chi2.h) with the samples drawn by
// the shader library on a Vulkan device (Mesa's lavapipe without a GPU): the cases of
// shader_test::chi2_cases(), the same as the C++ compile's GoogleTest
// ShaderLibrary.SamplingMatchesPdfByChiSquare, every sample (direction, weight, pdf, flags)
// computed by the kernel (conformance.comp, mode 3 compiled alone: shader_chi2_glsl.spv, _hlsl.spv).
// The density the test integrates for the expected counts, and the pdf and f of its per-sample
// consistency checks, are the C++ compile's
// (the conformance runs show it equal to the device's within the kit's tolerance), so each sample's
// pdf and weight from the device are also checked against them, within 1e-3 (the C++ test's 1e-4
// is one compile against itself; the driver's exp, pow and sqrt may be a few ulp off, and the
// device's weights were measured up to 5.8e-4 from the C++ compile's f |cos| / pdf at cos 0.2).
//   shader_vk_chi2 KERNEL.spv LUT_DIR LABEL [K/N]
// (K/N: run only the cases whose index is K modulo N; all by default. CTest runs each case once on
// the device: shader_hlsl_chi2 0/3, shader_glsl_chi2_1 1/3 and shader_glsl_chi2_2 2/3, the HLSL
// entry being the same body as the GLSL one through another front end.)
// The test draws its own random numbers: a first round records them (the C++ compile standing in),
// the device samples them all in one dispatch, and the second round is the verdict.
// Exit 0: every case passes; 1: a failure; 2: bad arguments or a Vulkan error; 77: no Vulkan device.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "shader_material.h"
#include "vk_queries.h"

namespace {

using shader_test::exact_key;
using Key = shader_test::ExactKey<3>;
using KeyHash = shader_test::ExactKeyHash;

// The device's samples by their random numbers u, with the C++ compile standing in for those not
// drawn yet (recorded for the dispatch); pdf and f are the C++ compile's. The first round only
// records the random numbers: until the first take_pending() there is no sample, pdf or f (0), so
// that its chi-square, which is not the verdict, costs no quadrature of the pdf (half the time).
class DeviceBsdf : public dspbr::Bsdf {
 public:
  explicit DeviceBsdf(const shader_test::ShaderBsdf& cpp) : cpp_(cpp) {}

  dspbr::Rgb eval(const dspbr::Vec3& v, const dspbr::Vec3& l) const override {
    return recording_ ? dspbr::Rgb(0.0) : cpp_.eval(v, l);
  }
  double pdf(const dspbr::Vec3& v, const dspbr::Vec3& l) const override { return recording_ ? 0.0 : cpp_.pdf(v, l); }
  dspbr::BsdfSample sample(const dspbr::Vec3& v, const dspbr::Vec3& u) const override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto it = samples_.find(exact_key(u));
      if (it != samples_.end()) return it->second;
      if (pending_keys_.insert(exact_key(u)).second) pending_.push_back(u);
    }
    return recording_ ? dspbr::BsdfSample{} : cpp_.sample(v, u);
  }
  uint32_t flags() const override { return cpp_.flags(); }

  std::vector<dspbr::Vec3> take_pending() {
    recording_ = false;
    pending_keys_.clear();
    return std::move(pending_);
  }
  void answer(const dspbr::Vec3& u, const dspbr::BsdfSample& s) { samples_[exact_key(u)] = s; }

 private:
  const shader_test::ShaderBsdf& cpp_;
  bool recording_ = true;
  mutable std::mutex mutex_;
  std::unordered_map<Key, dspbr::BsdfSample, KeyHash> samples_;
  mutable std::unordered_set<Key, KeyHash> pending_keys_;
  mutable std::vector<dspbr::Vec3> pending_;
};

}  // namespace

int main(int argc, char** argv) {
  unsigned part = 0, parts = 1;
  if (!shader_test::parse_part(argc, argv, part, parts)) {
    std::fprintf(stderr, "usage: shader_vk_chi2 KERNEL.spv LUT_DIR LABEL [K/N] (K < N: the cases K modulo N)\n");
    return 2;
  }
  try {
    shader_test::DeviceKernel kernel("dspbr shader chi-square");
    if (!kernel.open(argv[1], argv[2], argv[3])) return 77;
    // One dispatch of `mode` over the queries w (3 floats each after vector x's record).
    auto dispatch = [&](const dspbr::conformance::Vector& x, const std::vector<dspbr::Vec3>& w, uint32_t mode,
                        std::size_t floats) {
      float record[shader_test::kRecordFloats];
      shader_test::pack_record(x, record);
      std::vector<float> q;
      for (const dspbr::Vec3& u : w) q.insert(q.end(), {float(u.x), float(u.y), float(u.z)});
      return shader_test::run_queries(kernel, record, q, 3, mode, floats);
    };
    std::vector<shader_test::Chi2Case> cases;
    const std::vector<shader_test::Chi2Case> all = shader_test::chi2_cases();
    for (std::size_t k = part; k < all.size(); k += parts) cases.push_back(all[k]);
    int failed = 0;
    std::size_t queries = 0;
    for (const shader_test::Chi2Case& c : cases) {
      dspbr::conformance::Vector x = c.vector;
      x.v = c.v;  // the record's v (its l is not read in modes 3 and 4)
      const shader_test::ShaderBsdf cpp(dspbr::conformance::vector_material(x), dspbr::conformance::vector_options(x));
      DeviceBsdf dev(cpp);
      dspbr::validate::Chi2Settings settings = c.settings;
      settings.consistency_tol = 1e-3;  // device against the C++ compile (the header says why)
      dspbr::validate::Chi2Result r;
      bool answered = false;
      int rounds = 0;
      std::size_t case_queries = 0;
      for (; rounds < 3 && !answered; ++rounds) {
        r = dspbr::validate::chi2_test(dev, c.v, settings);
        const std::vector<dspbr::Vec3> us = dev.take_pending();
        answered = us.empty();
        case_queries += us.size();
        if (answered) break;
        const std::vector<float> out = dispatch(x, us, 3, 9);
        for (std::size_t k = 0; k < us.size(); ++k) dev.answer(us[k], shader_test::sample_from_floats(&out[9 * k]));
      }
      queries += case_queries;
      if (!answered || !r.passed()) {
        ++failed;
        std::printf("%s FAIL %s at cos %.2f: %s\n", argv[3], x.id.c_str(), c.v.z,
                    answered ? shader_test::chi2_summary(r).c_str() : "samples the device did not draw");
      }
    }
    std::printf("%s: chi-square of the device's samples, %zu of %zu cases pass (%zu samples drawn on the device)\n", argv[3],
                cases.size() - std::size_t(failed), cases.size(), queries);
    return failed == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shader_vk_chi2: %s\n", e.what());
    return 2;
  }
}
