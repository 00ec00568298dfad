// The generated GLSL lookups and fits on a real Vulkan driver (CTest vulkan_lookup_textures;
// docs/luts.md, "Using the tables in your renderer"): runs
// tests/shaders/vulkan_lookup.comp, compiled to SPIR-V by glslangValidator, on the first Vulkan
// device (Mesa's lavapipe on a machine without a GPU) at kPoints points of the whole domain, and
// compares every output with the C header (luts/dspbr_lookup.h, dspbr_glass_lookup.h) and the
// C++ fits (fits/dspbr_fits.hpp) evaluated here.
//   vulkan_lookup SHADER.spv arrays
//   vulkan_lookup SHADER.spv textures LUT_DIR   (LUT_DIR/renderer/NAME.exr uploaded as R32F
//                                                textures, bound as the header says)
// Exit 0: every value within tolerance; 1: a difference (the worst listed); 2: bad arguments or
// a Vulkan error; 77: no Vulkan device (CTest reports the test skipped, never passed).
#include <vulkan/vulkan.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dspbr_fits.hpp"
// The glass header uses the main one's helpers.
#include "dspbr_lookup.h"
#include "dspbr_glass_lookup.h"

namespace {

constexpr uint32_t kOutputs = 26;  // the shader's kOutputs, in its order
constexpr uint32_t kPoints = 4096;
constexpr int kSkip = 77;

const char* const kOutputNames[kOutputs] = {
    "ggx_E", "ggx_E_avg", "ggx_E_avg_missing", "fresnel_ms", "base_E", "base_E_avg", "sheen_E", "sheen_ash_E",
    "ms_lobe", "diffuse_bc", "sheen_layer_scale", "sheen_ash_layer_scale", "glass_E(out)", "glass_E(in)",
    "glass_E_avg(out)", "glass_E_avg(in)", "glass_compensation", "thin_glass_compensation", "fit_ggx_E",
    "fit_ggx_E_avg", "fit_base_E", "fit_base_E_avg", "fit_sheen_E", "fit_sheen_ash_E", "fit_sheen_lambda",
    "fit_flake_lobe"};

// The same outputs from the C header and the C++ fits, and per output its amplification of an
// ulp of difference: the compensation lobes are products and quotients of differences of nearly
// equal floats (1 - E near E = 1, the missing energy 1 - E_avg), each computed from the driver's
// exp / pow on one side and glibc's on the other, so that an ulp(1) of difference in E is a
// relative difference of ulp(1) / (1 - E) in the lobe. The sum of those 1 / (1 - x); 0 elsewhere.
void reference(const float q[4], float o[kOutputs], double amplification[kOutputs]) {
  const float cv = q[0], cl = q[1], r = q[2], s = q[3], ior = 1.0f + 2.0f * s;
  auto inv = [](double d) { return 1.0 / std::max(d, 1e-9); };
  for (uint32_t k = 0; k < kOutputs; ++k) amplification[k] = 0;
  amplification[8] = inv(dspbr_ggx_E_avg_missing(r)) + inv(1.0 - dspbr_ggx_E(cv, r)) + inv(1.0 - dspbr_ggx_E(cl, r));
  amplification[9] = inv(1.0 - dspbr_base_E_avg(r, s)) + inv(1.0 - dspbr_base_E(cv, r, s)) +
                     inv(1.0 - dspbr_base_E(cl, r, s));
  amplification[16] = inv(1.0 - dspbr_glass_core_E_avg(r, ior, 0)) + inv(1.0 - dspbr_glass_core_E(cv, r, ior, 1)) +
                      inv(1.0 - dspbr_glass_core_E(cl, r, ior, 0));
  amplification[17] = amplification[8];
  o[0] = dspbr_ggx_E(cv, r);
  o[1] = dspbr_ggx_E_avg(r);
  o[2] = dspbr_ggx_E_avg_missing(r);
  o[3] = dspbr_fresnel_ms(s, 1.0f, cv);
  o[4] = dspbr_base_E(cv, r, s);
  o[5] = dspbr_base_E_avg(r, s);
  o[6] = dspbr_sheen_E(cv, s);
  o[7] = dspbr_sheen_ash_E(cv, s);
  o[8] = dspbr_ms_lobe(cv, cl, r);
  o[9] = dspbr_diffuse_bc(cv, cl, r, s);
  o[10] = dspbr_sheen_layer_scale(cv, cl, r, s);
  o[11] = dspbr_sheen_ash_layer_scale(cv, cl, r, s);
  o[12] = dspbr_glass_E(cv, r, ior, 0);
  o[13] = dspbr_glass_E(cv, r, ior, 1);
  o[14] = dspbr_glass_E_avg(r, ior, 0);
  o[15] = dspbr_glass_E_avg(r, ior, 1);
  o[16] = dspbr_glass_compensation(cv, cl, r, ior, 1, 1);
  o[17] = dspbr_thin_glass_compensation(cv, cl, r, ior, 0);
  o[18] = dspbr_fit_ggx_E(cv, r);
  o[19] = dspbr_fit_ggx_E_avg(r);
  o[20] = dspbr_fit_base_E(cv, r, s);
  o[21] = dspbr_fit_base_E_avg(r, s);
  o[22] = dspbr_fit_sheen_E(cv, s);
  o[23] = dspbr_fit_sheen_ash_E(cv, s);
  o[24] = dspbr_fit_sheen_lambda(cv, s);
  o[25] = dspbr_fit_flake_lobe(std::sqrt(1.0f - cv * cv), 0.0f, cv, -std::sqrt(1.0f - cl * cl), 0.0f, cl,
                               0.05f + 0.9f * s);
}

// Points over the whole domain: cosines down to 1e-3 (a quarter log-uniform towards it),
// roughness 0 and 1 included, s uniform; a fixed 64-bit LCG (the same points everywhere).
std::vector<float> make_points() {
  uint64_t state = 0x9E3779B97F4A7C15ull;
  auto u = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return float(double(state >> 40) / double(1ull << 24));
  };
  auto cosine = [&](uint32_t i) {
    const float x = u();
    return i % 4 == 0 ? std::pow(10.0f, -3.0f * x) : std::max(x, 1e-3f);
  };
  std::vector<float> p;
  for (uint32_t i = 0; i < kPoints; ++i) {
    const float r = i % 16 == 0 ? 0.0f : (i % 16 == 1 ? 1.0f : u());
    p.insert(p.end(), {cosine(i), cosine(i + 1), r, u()});
  }
  return p;
}

struct VkError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void check(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw VkError(std::string(what) + " failed (VkResult " + std::to_string(int(r)) + ")");
}

std::vector<uint32_t> read_spirv(const std::string& path) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) throw std::invalid_argument("cannot read '" + path + "'");
  const std::streamsize n = f.tellg();
  if (n <= 0 || n % 4 != 0) throw std::invalid_argument("'" + path + "' is not SPIR-V");
  std::vector<uint32_t> words(size_t(n) / 4);
  f.seekg(0);
  f.read(reinterpret_cast<char*>(words.data()), n);
  return words;
}

// One R32F table image read from an EXR written by `dspbr lut` (channel Y).
struct TableImage {
  int width = 0, height = 0;
  std::vector<float> pixels;
};

TableImage read_exr(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::invalid_argument("cannot read '" + path + "'");
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != 1) throw std::invalid_argument("'" + path + "' has more than one channel");
  TableImage t{spec.width, spec.height, std::vector<float>(size_t(spec.width) * size_t(spec.height))};
  if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, t.pixels.data()))
    throw std::invalid_argument("cannot read the pixels of '" + path + "'");
  return t;
}

// The tables in binding order (dspbr_lookup.glsl 0-5, dspbr_glass_lookup.glsl 6-9).
const char* const kTextures[] = {"GGX_E",   "GGX_beta",    "GGX_E_avg",   "GGX_B_avg",       "Sheen_E",
                                 "Sheen_ash_E", "Glass_E", "Glass_inv_E", "Glass_E_avg", "Glass_inv_E_avg"};
constexpr uint32_t kTextureBinding = 2;  // the shader's DSPBR_LOOKUP_BINDING_BASE in texture mode

class Runner {
 public:
  Runner() {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "dspbr vulkan_lookup";
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ici.pApplicationInfo = &app;
    if (vkCreateInstance(&ici, nullptr, &instance_) != VK_SUCCESS) {
      instance_ = VK_NULL_HANDLE;
      return;  // no driver: no device
    }
    uint32_t n = 0;
    vkEnumeratePhysicalDevices(instance_, &n, nullptr);
    std::vector<VkPhysicalDevice> devices(n);
    if (n) vkEnumeratePhysicalDevices(instance_, &n, devices.data());
    for (VkPhysicalDevice d : devices) {
      uint32_t qn = 0;
      vkGetPhysicalDeviceQueueFamilyProperties(d, &qn, nullptr);
      std::vector<VkQueueFamilyProperties> qs(qn);
      vkGetPhysicalDeviceQueueFamilyProperties(d, &qn, qs.data());
      for (uint32_t q = 0; q < qn; ++q)
        if (qs[q].queueFlags & VK_QUEUE_COMPUTE_BIT) {
          physical_ = d;
          family_ = q;
          break;
        }
      if (physical_ != VK_NULL_HANDLE) break;
    }
    if (physical_ == VK_NULL_HANDLE) return;
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(physical_, &props);
    device_name_ = props.deviceName;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = family_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    check(vkCreateDevice(physical_, &dci, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, family_, 0, &queue_);
    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.queueFamilyIndex = family_;
    check(vkCreateCommandPool(device_, &pci, nullptr, &pool_), "vkCreateCommandPool");
  }
  ~Runner() {
    if (device_ != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device_);
      for (auto& b : buffers_) {
        vkDestroyBuffer(device_, b.buffer, nullptr);
        vkFreeMemory(device_, b.memory, nullptr);
      }
      for (auto& i : images_) {
        vkDestroyImageView(device_, i.view, nullptr);
        vkDestroyImage(device_, i.image, nullptr);
        vkFreeMemory(device_, i.memory, nullptr);
      }
      if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
      vkDestroyCommandPool(device_, pool_, nullptr);
      vkDestroyDevice(device_, nullptr);
    }
    if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
  }
  bool has_device() const { return device_ != VK_NULL_HANDLE; }
  const std::string& device_name() const { return device_name_; }

  // Runs the shader over `points` (4 floats each) and returns kOutputs floats per point.
  std::vector<float> run(const std::vector<uint32_t>& spirv, const std::vector<float>& points,
                         const std::vector<TableImage>& textures) {
    const uint32_t n = uint32_t(points.size() / 4);
    const size_t in_bytes = points.size() * sizeof(float), out_bytes = size_t(n) * kOutputs * sizeof(float);
    Buffer& in = make_buffer(in_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    Buffer& out = make_buffer(out_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memcpy(in.mapped, points.data(), in_bytes);
    std::memset(out.mapped, 0xFF, out_bytes);  // NaN until written

    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (uint32_t b = 0; b < 2; ++b)
      bindings.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    for (uint32_t t = 0; t < textures.size(); ++t)
      bindings.push_back(
          {kTextureBinding + t, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    if (!textures.empty()) upload_textures(textures);

    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = uint32_t(bindings.size());
    lci.pBindings = bindings.data();
    VkDescriptorSetLayout set_layout;
    check(vkCreateDescriptorSetLayout(device_, &lci, nullptr, &set_layout), "vkCreateDescriptorSetLayout");
    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t)};
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &set_layout;
    plci.pushConstantRangeCount = 1;
    plci.pPushConstantRanges = &push;
    VkPipelineLayout pipeline_layout;
    check(vkCreatePipelineLayout(device_, &plci, nullptr, &pipeline_layout), "vkCreatePipelineLayout");
    VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    smci.codeSize = spirv.size() * sizeof(uint32_t);
    smci.pCode = spirv.data();
    VkShaderModule module;
    check(vkCreateShaderModule(device_, &smci, nullptr, &module), "vkCreateShaderModule");
    VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    cpci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpci.stage.module = module;
    cpci.stage.pName = "main";
    cpci.layout = pipeline_layout;
    VkPipeline pipeline;
    check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline), "vkCreateComputePipelines");

    std::vector<VkDescriptorPoolSize> sizes = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}};
    if (!textures.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(textures.size())});
    VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpci.maxSets = 1;
    dpci.poolSizeCount = uint32_t(sizes.size());
    dpci.pPoolSizes = sizes.data();
    VkDescriptorPool descriptor_pool;
    check(vkCreateDescriptorPool(device_, &dpci, nullptr, &descriptor_pool), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dsai.descriptorPool = descriptor_pool;
    dsai.descriptorSetCount = 1;
    dsai.pSetLayouts = &set_layout;
    VkDescriptorSet set;
    check(vkAllocateDescriptorSets(device_, &dsai, &set), "vkAllocateDescriptorSets");
    VkDescriptorBufferInfo buffer_infos[2] = {{in.buffer, 0, VK_WHOLE_SIZE}, {out.buffer, 0, VK_WHOLE_SIZE}};
    std::vector<VkDescriptorImageInfo> image_infos;
    for (const Image& i : images_) image_infos.push_back({sampler_, i.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
    std::vector<VkWriteDescriptorSet> writes;
    for (uint32_t b = 0; b < 2; ++b) {
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = set;
      w.dstBinding = b;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      w.pBufferInfo = &buffer_infos[b];
      writes.push_back(w);
    }
    for (uint32_t t = 0; t < image_infos.size(); ++t) {
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = set;
      w.dstBinding = kTextureBinding + t;
      w.descriptorCount = 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      w.pImageInfo = &image_infos[t];
      writes.push_back(w);
    }
    vkUpdateDescriptorSets(device_, uint32_t(writes.size()), writes.data(), 0, nullptr);

    VkCommandBuffer cmd = begin();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, pipeline_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t), &n);
    vkCmdDispatch(cmd, (n + 63) / 64, 1, 1);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
    submit(cmd);

    std::vector<float> values(size_t(n) * kOutputs);
    std::memcpy(values.data(), out.mapped, out_bytes);
    vkDestroyDescriptorPool(device_, descriptor_pool, nullptr);
    vkDestroyPipeline(device_, pipeline, nullptr);
    vkDestroyShaderModule(device_, module, nullptr);
    vkDestroyPipelineLayout(device_, pipeline_layout, nullptr);
    vkDestroyDescriptorSetLayout(device_, set_layout, nullptr);
    return values;
  }

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

  uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags want) const {
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(physical_, &mp);
    for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
      if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
    throw VkError("no suitable memory type");
  }

  // Memory of `want` properties for `req`.
  VkDeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags want) {
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = memory_type(req.memoryTypeBits, want);
    VkDeviceMemory memory;
    check(vkAllocateMemory(device_, &mai, nullptr, &memory), "vkAllocateMemory");
    return memory;
  }

  // A host-visible, coherent, mapped buffer.
  Buffer& make_buffer(size_t bytes, VkBufferUsageFlags usage) {
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = bytes;
    bci.usage = usage;
    bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    Buffer b{};
    check(vkCreateBuffer(device_, &bci, nullptr, &b.buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, b.buffer, &req);
    b.memory = allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    check(vkBindBufferMemory(device_, b.buffer, b.memory, 0), "vkBindBufferMemory");
    check(vkMapMemory(device_, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
    buffers_.push_back(b);
    return buffers_.back();
  }

  VkCommandBuffer begin() {
    VkCommandBufferAllocateInfo cbai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cbai.commandPool = pool_;
    cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cbai.commandBufferCount = 1;
    VkCommandBuffer cmd;
    check(vkAllocateCommandBuffers(device_, &cbai, &cmd), "vkAllocateCommandBuffers");
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &bi), "vkBeginCommandBuffer");
    return cmd;
  }

  void submit(VkCommandBuffer cmd) {
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    check(vkQueueSubmit(queue_, 1, &si, VK_NULL_HANDLE), "vkQueueSubmit");
    check(vkQueueWaitIdle(queue_), "vkQueueWaitIdle");
    vkFreeCommandBuffers(device_, pool_, 1, &cmd);
  }

  // Each table as an R32_SFLOAT image (width = fastest axis), filled from a staging buffer, and one
  // nearest-filter sampler (texelFetch ignores its state; the combined image sampler needs one).
  void upload_textures(const std::vector<TableImage>& textures) {
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    check(vkCreateSampler(device_, &sci, nullptr, &sampler_), "vkCreateSampler");
    for (const TableImage& t : textures) {
      const size_t bytes = t.pixels.size() * sizeof(float);
      Buffer& staging = make_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
      std::memcpy(staging.mapped, t.pixels.data(), bytes);
      VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
      ici.imageType = VK_IMAGE_TYPE_2D;
      ici.format = VK_FORMAT_R32_SFLOAT;
      ici.extent = {uint32_t(t.width), uint32_t(t.height), 1};
      ici.mipLevels = ici.arrayLayers = 1;
      ici.samples = VK_SAMPLE_COUNT_1_BIT;
      ici.tiling = VK_IMAGE_TILING_OPTIMAL;
      ici.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
      ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
      Image img{};
      check(vkCreateImage(device_, &ici, nullptr, &img.image), "vkCreateImage");
      VkMemoryRequirements req;
      vkGetImageMemoryRequirements(device_, img.image, &req);
      img.memory = allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      check(vkBindImageMemory(device_, img.image, img.memory, 0), "vkBindImageMemory");
      VkCommandBuffer cmd = begin();
      VkImageMemoryBarrier to_dst{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
      to_dst.srcAccessMask = 0;
      to_dst.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      to_dst.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
      to_dst.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
      to_dst.srcQueueFamilyIndex = to_dst.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      to_dst.image = img.image;
      to_dst.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                           nullptr, 1, &to_dst);
      VkBufferImageCopy copy{};
      copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      copy.imageExtent = ici.extent;
      vkCmdCopyBufferToImage(cmd, staging.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
      VkImageMemoryBarrier to_read = to_dst;
      to_read.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      to_read.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
      to_read.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
      to_read.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0,
                           nullptr, 1, &to_read);
      submit(cmd);
      VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
      vci.image = img.image;
      vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
      vci.format = VK_FORMAT_R32_SFLOAT;
      vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      check(vkCreateImageView(device_, &vci, nullptr, &img.view), "vkCreateImageView");
      images_.push_back(img);
    }
  }

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  uint32_t family_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
  std::string device_name_;
  std::deque<Buffer> buffers_;  // a deque: the references make_buffer returns stay valid
  std::vector<Image> images_;
};

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string usage = "usage: vulkan_lookup SHADER.spv arrays | SHADER.spv textures LUT_DIR";
    if (argc < 3) throw std::invalid_argument(usage);
    const std::string mode = argv[2];
    if (!((mode == "arrays" && argc == 3) || (mode == "textures" && argc == 4))) throw std::invalid_argument(usage);
    const std::vector<uint32_t> spirv = read_spirv(argv[1]);
    std::vector<TableImage> textures;
    if (mode == "textures")
      for (const char* name : kTextures) textures.push_back(read_exr(std::string(argv[3]) + "/renderer/" + name + ".exr"));

    Runner vk;
    if (!vk.has_device()) {
      std::printf("SKIPPED: no Vulkan device with a compute queue (install mesa-vulkan-drivers for lavapipe)\n");
      return kSkip;
    }
    const std::vector<float> points = make_points();
    const std::vector<float> gpu = vk.run(spirv, points, textures);

    // Tolerance: float evaluation on both sides, the driver's pow / exp / log within a few ulp of
    // glibc's (Vulkan allows 3 + 2 |x| ulp for exp): 5e-5 relative + 2e-6 absolute, plus for the
    // compensation lobes 4 ulp(1) times their amplification (above) relative.
    const double rel = 5e-5, abs_tol = 2e-6, ulp1 = 0x1p-23;
    double worst[kOutputs] = {};
    uint32_t worst_at[kOutputs] = {}, failures = 0;
    for (uint32_t i = 0; i < kPoints; ++i) {
      float ref[kOutputs];
      double amplification[kOutputs];
      reference(&points[4 * i], ref, amplification);
      for (uint32_t k = 0; k < kOutputs; ++k) {
        const double g = gpu[size_t(i) * kOutputs + k], c = ref[k];
        const double tol = abs_tol + (rel + 4 * ulp1 * amplification[k]) * std::abs(c);
        const double d = std::isfinite(g) ? std::abs(g - c) / tol : INFINITY;
        if (!(d <= 1.0)) ++failures;
        if (!(d <= worst[k])) {
          worst[k] = d;
          worst_at[k] = i;
        }
      }
    }
    std::printf("device: %s, mode: %s, %u points x %u outputs, tolerance |gpu - c| <= %g + (%g + 4 ulp(1) "
                "amplification) |c|\n", vk.device_name().c_str(), mode.c_str(), kPoints, kOutputs, abs_tol, rel);
    for (uint32_t k = 0; k < kOutputs; ++k) {
      const float* p = &points[4 * worst_at[k]];
      std::printf("  %-24s worst %.3g of the tolerance at (cos_v %.4g, cos_l %.4g, r %.4g, s %.4g)\n", kOutputNames[k],
                  worst[k], p[0], p[1], p[2], p[3]);
    }
    if (failures) {
      std::printf("FAILED: %u values outside the tolerance\n", failures);
      return 1;
    }
    std::printf("PASSED: every value within the tolerance\n");
    return 0;
  } catch (const VkError& e) {
    std::fprintf(stderr, "vulkan_lookup: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vulkan_lookup: %s\n", e.what());
    return 2;
  }
}
