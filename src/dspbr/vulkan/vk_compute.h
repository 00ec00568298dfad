// Running one compute shader on the first Vulkan device (Mesa's lavapipe on a machine without a
// GPU), as the Vulkan programs of the project use it (examples/vulkan/sphere.cpp, CTest
// vulkan_sphere_example; tests/vulkan/vulkan_lookup.cpp, CTest vulkan_lookup_textures): set 0
// holds an input storage buffer at binding 0, an output storage buffer at binding 1 and the
// lookup tables as combined image samplers from a given binding on (docs/luts.md, "Using the
// tables in your renderer"); a push-constant block; one dispatch; the output read back.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "dspbr/vulkan/lookup_textures.h"

namespace vk_compute {

// A Vulkan call that failed (its name and VkResult in the message).
struct VkError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The words of a SPIR-V file (glslangValidator -V); std::invalid_argument when unreadable or without
// a SPIR-V header (magic number 0x07230203 and four more words).
std::vector<uint32_t> read_spirv(const std::string& path);

// One dispatch: what the shader reads and writes.
struct Job {
  const std::vector<uint32_t>* spirv = nullptr;
  const void* input = nullptr;  // binding 0, std430 storage buffer (read)
  size_t input_bytes = 0;
  size_t output_floats = 0;     // binding 1, std430 storage buffer of floats (NaN until written)
  const std::vector<TableImage>* textures = nullptr;  // R32F combined image samplers
  uint32_t texture_binding = 0;                       // the first table's binding
  const void* push = nullptr;   // push constants (compute stage, offset 0)
  uint32_t push_bytes = 0;
  uint32_t groups[3] = {1, 1, 1};  // vkCmdDispatch's workgroup counts
};

// A job of one invocation per item in workgroups of 64 (the local_size_x of the project's item
// kernels: tests/shaders/vulkan_lookup.comp, the shader-library test kernels and the conformance
// kit's runner): `input` at binding 0, floats_per_item output floats per item at binding 1, the tables
// from texture_binding on. The job points into its arguments: they must outlive Device::run.
Job item_job(const std::vector<uint32_t>& spirv, const void* input, size_t input_bytes, size_t items,
             size_t floats_per_item, const std::vector<TableImage>& textures, uint32_t texture_binding,
             const void* push, uint32_t push_bytes);

class Device {
 public:
  // The first physical device with a compute queue; none: has_device() is false (no exception).
  explicit Device(const char* application);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
  bool has_device() const { return device_ != VK_NULL_HANDLE; }
  const std::string& device_name() const { return device_name_; }

  // Runs the job and returns the output buffer; VkError when a Vulkan call fails. The pipeline
  // and the uploaded tables are kept for later jobs with the same SPIR-V, tables, binding and
  // push-constant size (a driver that compiles at pipeline creation, lavapipe, takes seconds per
  // pipeline of the shader library); the job's buffers are released when it returns.
  std::vector<float> run(const Job& job);

 private:
  struct Buffer {
    VkBuffer buffer;
    VkDeviceMemory memory;
    void* mapped;
  };
  struct Image {
    VkImage image;
    VkDeviceMemory memory;
    VkImageView view;
  };
  // A pipeline and its tables, by what built them (run's cache).
  struct Pipeline {
    VkDescriptorSetLayout set_layout;
    VkPipelineLayout layout;
    VkShaderModule module;
    VkPipeline pipeline;
    std::vector<VkImageView> views;  // the tables, in binding order
  };
  Pipeline& pipeline_for(const Job& job);
  void release(const Buffer& b);
  uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags want) const;
  VkDeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags want);
  Buffer make_buffer(size_t bytes, VkBufferUsageFlags usage);  // host-visible, mapped; release() it
  VkCommandBuffer begin();
  void submit(VkCommandBuffer cmd);
  void upload_textures(const std::vector<TableImage>& textures);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  uint32_t family_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
  std::string device_name_;
  std::vector<Image> images_;
  std::map<std::string, Pipeline> pipelines_;  // key: the SPIR-V, the tables, binding, push size
};

}  // namespace vk_compute
