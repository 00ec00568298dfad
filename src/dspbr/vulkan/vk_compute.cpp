#include "dspbr/vulkan/vk_compute.h"

#include <cstring>
#include <fstream>

namespace vk_compute {

namespace {

void check(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw VkError(std::string(what) + " failed (VkResult " + std::to_string(int(r)) + ")");
}

}  // namespace

Job item_job(const std::vector<uint32_t>& spirv, const void* input, size_t input_bytes, size_t items,
             size_t floats_per_item, const std::vector<TableImage>& textures, uint32_t texture_binding,
             const void* push, uint32_t push_bytes) {
  Job job;
  job.spirv = &spirv;
  job.input = input;
  job.input_bytes = input_bytes;
  job.output_floats = items * floats_per_item;
  job.textures = &textures;
  job.texture_binding = texture_binding;
  job.push = push;
  job.push_bytes = push_bytes;
  job.groups[0] = uint32_t((items + 63) / 64);
  return job;
}

std::vector<uint32_t> read_spirv(const std::string& path) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) throw std::invalid_argument("cannot read '" + path + "'");
  const std::streamsize n = f.tellg();
  if (n <= 0 || n % 4 != 0) throw std::invalid_argument("'" + path + "' is not SPIR-V");
  std::vector<uint32_t> words(size_t(n) / 4);
  f.seekg(0);
  f.read(reinterpret_cast<char*>(words.data()), n);
  // The header: the magic number and four more words (SPIR-V specification, 2.3 "Physical Layout").
  if (!f || words.size() < 5 || words[0] != 0x07230203u) throw std::invalid_argument("'" + path + "' is not SPIR-V");
  return words;
}

Device::Device(const char* application) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = application;
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

Device::~Device() {
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    for (auto& [key, p] : pipelines_) {
      vkDestroyPipeline(device_, p.pipeline, nullptr);
      vkDestroyShaderModule(device_, p.module, nullptr);
      vkDestroyPipelineLayout(device_, p.layout, nullptr);
      vkDestroyDescriptorSetLayout(device_, p.set_layout, nullptr);
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

Device::Pipeline& Device::pipeline_for(const Job& job) {
  const std::vector<TableImage> none;
  const std::vector<TableImage>& textures = job.textures ? *job.textures : none;
  // The key: everything the pipeline and its tables are made of, byte for byte.
  std::string key(reinterpret_cast<const char*>(job.spirv->data()), job.spirv->size() * sizeof(uint32_t));
  key += "|" + std::to_string(job.texture_binding) + "|" + std::to_string(job.push_bytes);
  for (const TableImage& t : textures) {
    key += "|" + std::to_string(t.width) + "x" + std::to_string(t.height) + ":";
    key.append(reinterpret_cast<const char*>(t.pixels.data()), t.pixels.size() * sizeof(float));
  }
  const auto found = pipelines_.find(key);
  if (found != pipelines_.end()) return found->second;

  Pipeline p;
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (uint32_t b = 0; b < 2; ++b)
    bindings.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  for (uint32_t t = 0; t < textures.size(); ++t)
    bindings.push_back(
        {job.texture_binding + t, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  const size_t first_image = images_.size();
  if (!textures.empty()) upload_textures(textures);
  for (size_t i = first_image; i < images_.size(); ++i) p.views.push_back(images_[i].view);

  VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  lci.bindingCount = uint32_t(bindings.size());
  lci.pBindings = bindings.data();
  check(vkCreateDescriptorSetLayout(device_, &lci, nullptr, &p.set_layout), "vkCreateDescriptorSetLayout");
  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, job.push_bytes};
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = 1;
  plci.pSetLayouts = &p.set_layout;
  plci.pushConstantRangeCount = job.push_bytes ? 1 : 0;
  plci.pPushConstantRanges = &push;
  check(vkCreatePipelineLayout(device_, &plci, nullptr, &p.layout), "vkCreatePipelineLayout");
  VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  smci.codeSize = job.spirv->size() * sizeof(uint32_t);
  smci.pCode = job.spirv->data();
  check(vkCreateShaderModule(device_, &smci, nullptr, &p.module), "vkCreateShaderModule");
  VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  cpci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  cpci.stage.module = p.module;
  cpci.stage.pName = "main";
  cpci.layout = p.layout;
  check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &cpci, nullptr, &p.pipeline), "vkCreateComputePipelines");
  return pipelines_.emplace(key, p).first->second;
}

std::vector<float> Device::run(const Job& job) {
  const size_t out_bytes = job.output_floats * sizeof(float);
  const Pipeline& p = pipeline_for(job);
  const Buffer in = make_buffer(job.input_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  const Buffer out = make_buffer(out_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  std::memcpy(in.mapped, job.input, job.input_bytes);
  std::memset(out.mapped, 0xFF, out_bytes);  // NaN until written

  std::vector<VkDescriptorPoolSize> sizes = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}};
  if (!p.views.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(p.views.size())});
  VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpci.maxSets = 1;
  dpci.poolSizeCount = uint32_t(sizes.size());
  dpci.pPoolSizes = sizes.data();
  VkDescriptorPool descriptor_pool;
  check(vkCreateDescriptorPool(device_, &dpci, nullptr, &descriptor_pool), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  dsai.descriptorPool = descriptor_pool;
  dsai.descriptorSetCount = 1;
  dsai.pSetLayouts = &p.set_layout;
  VkDescriptorSet set;
  check(vkAllocateDescriptorSets(device_, &dsai, &set), "vkAllocateDescriptorSets");
  VkDescriptorBufferInfo buffer_infos[2] = {{in.buffer, 0, VK_WHOLE_SIZE}, {out.buffer, 0, VK_WHOLE_SIZE}};
  std::vector<VkDescriptorImageInfo> image_infos;
  for (VkImageView view : p.views) image_infos.push_back({sampler_, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
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
    w.dstBinding = job.texture_binding + t;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &image_infos[t];
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device_, uint32_t(writes.size()), writes.data(), 0, nullptr);

  VkCommandBuffer cmd = begin();
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout, 0, 1, &set, 0, nullptr);
  if (job.push_bytes) vkCmdPushConstants(cmd, p.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, job.push_bytes, job.push);
  vkCmdDispatch(cmd, job.groups[0], job.groups[1], job.groups[2]);
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
  submit(cmd);

  std::vector<float> values(job.output_floats);
  std::memcpy(values.data(), out.mapped, out_bytes);
  vkDestroyDescriptorPool(device_, descriptor_pool, nullptr);
  release(in);
  release(out);
  return values;
}

uint32_t Device::memory_type(uint32_t bits, VkMemoryPropertyFlags want) const {
  VkPhysicalDeviceMemoryProperties mp;
  vkGetPhysicalDeviceMemoryProperties(physical_, &mp);
  for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
  throw VkError("no suitable memory type");
}

// Memory of `want` properties for `req`.
VkDeviceMemory Device::allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags want) {
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = memory_type(req.memoryTypeBits, want);
  VkDeviceMemory memory;
  check(vkAllocateMemory(device_, &mai, nullptr, &memory), "vkAllocateMemory");
  return memory;
}

// A host-visible, coherent, mapped buffer.
Device::Buffer Device::make_buffer(size_t bytes, VkBufferUsageFlags usage) {
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
  return b;
}

void Device::release(const Buffer& b) {
  vkDestroyBuffer(device_, b.buffer, nullptr);
  vkFreeMemory(device_, b.memory, nullptr);
}

VkCommandBuffer Device::begin() {
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

void Device::submit(VkCommandBuffer cmd) {
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
void Device::upload_textures(const std::vector<TableImage>& textures) {
  if (sampler_ == VK_NULL_HANDLE) {
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    check(vkCreateSampler(device_, &sci, nullptr, &sampler_), "vkCreateSampler");
  }
  for (const TableImage& t : textures) {
    const size_t bytes = t.pixels.size() * sizeof(float);
    const Buffer staging = make_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
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
    release(staging);
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = img.image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = VK_FORMAT_R32_SFLOAT;
    vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    check(vkCreateImageView(device_, &vci, nullptr, &img.view), "vkCreateImageView");
    images_.push_back(img);
  }
}

}  // namespace vk_compute
