// What the device tests of the shader library share (shader_vk_conformance, shader_vk_chi2,
// shader_vk_stability): the device with the test kernel (conformance.comp / .hlsl,
// kernel_common.glsl) and the tables, a dispatch of it over queries that follow a material's record,
// and a sample as modes 3 and 5 write it.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "dspbr/bsdf/bsdf.h"
#include "dspbr/vulkan/vk_compute.h"
#include "shader_material.h"

namespace shader_test {

// The first Vulkan device with a test kernel and the tables it reads.
struct DeviceKernel {
  explicit DeviceKernel(const char* application) : device(application) {}
  // False without a Vulkan device, after printing "no Vulkan device: skipped" (the caller exits 77);
  // else prints "LABEL on DEVICE" and reads the kernel (SPIR-V) and the tables of LUT_DIR/renderer.
  bool open(const char* spv, const char* lut_dir, const char* label) {
    if (!device.has_device()) {
      std::printf("no Vulkan device: skipped\n");
      return false;
    }
    std::printf("%s on %s\n", label, device.device_name().c_str());
    spirv = vk_compute::read_spirv(spv);
    textures = vk_compute::read_lookup_textures(lut_dir, false);
    return true;
  }
  // One invocation per item over `input`, floats_per_item output floats each; the tables are bound
  // from binding 2 (after the two buffers), as the kernels expect.
  std::vector<float> run(const std::vector<float>& input, std::size_t items, std::size_t floats_per_item, const void* push,
                         uint32_t push_bytes) {
    return device.run(vk_compute::item_job(spirv, input.data(), input.size() * sizeof(float), items, floats_per_item, textures, 2,
                                           push, push_bytes));
  }
  vk_compute::Device device;
  std::vector<uint32_t> spirv;
  std::vector<vk_compute::TableImage> textures;
};

// Runs `mode` once per query: the input is `record` (kRecordFloats floats, pack_record's) followed
// by the queries' floats (query_floats each); the output holds out_floats floats per query.
inline std::vector<float> run_queries(DeviceKernel& kernel, const float* record, const std::vector<float>& queries,
                                      std::size_t query_floats, uint32_t mode, std::size_t out_floats) {
  std::vector<float> input(record, record + kRecordFloats);
  input.insert(input.end(), queries.begin(), queries.end());
  const std::size_t count = queries.size() / query_floats;
  const uint32_t push[2] = {uint32_t(count), mode};
  return kernel.run(input, count, out_floats, push, sizeof push);
}

// The exact bits of a query's vectors (a direction, random numbers): the key under which a device
// test keeps the device's answer, found again when the scan asks the same query.
template <std::size_t N>
using ExactKey = std::array<uint64_t, N>;
struct ExactKeyHash {
  template <std::size_t N>
  std::size_t operator()(const ExactKey<N>& k) const {
    std::size_t h = 0;
    for (uint64_t x : k) h = h * 0x9E3779B97F4A7C15ull ^ (x + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2));
    return h;
  }
};
inline ExactKey<3> exact_key(const dspbr::Vec3& a) {
  ExactKey<3> k;
  const double d[3] = {a.x, a.y, a.z};
  std::memcpy(k.data(), d, sizeof d);
  return k;
}
inline ExactKey<6> exact_key(const dspbr::Vec3& a, const dspbr::Vec3& b) {
  ExactKey<6> k;
  const double d[6] = {a.x, a.y, a.z, b.x, b.y, b.z};
  std::memcpy(k.data(), d, sizeof d);
  return k;
}

// A sample from the 9 floats modes 3 and 5 write: valid, l, weight, pdf, flags.
inline dspbr::BsdfSample sample_from_floats(const float* o) {
  dspbr::BsdfSample s;
  s.valid = o[0] > 0.5f;
  s.l = {o[1], o[2], o[3]};
  s.weight = dspbr::Rgb(o[4], o[5], o[6]);
  s.pdf = o[7];
  s.flags = uint32_t(o[8]);
  return s;
}

// The optional K/N argument of the device tests: only the items whose index is K modulo N.
// False (a usage error) unless argc is 4, or 5 with argv[4] = K/N, K < N.
inline bool parse_part(int argc, char** argv, unsigned& part, unsigned& parts) {
  part = 0, parts = 1;
  char end = 0;
  if (argc == 4) return true;
  return argc == 5 && std::sscanf(argv[4], "%u/%u%c", &part, &parts, &end) == 2 && parts >= 1 && part < parts;
}

}  // namespace shader_test
