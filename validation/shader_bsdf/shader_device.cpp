#include "shader_device.h"

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "gpu_backend/device_info.h"
#include "gpu_backend/gpu_error.h"
#include "gpu_backend/vk_device.h"
#include "gpu_backend/vk_instance.h"

namespace tr::shader_bsdf {

namespace {

constexpr uint32_t kWorkgroup = 64;     // local_size_x of the wrapper
constexpr uint32_t kMaxGroups = 65535;  // per dispatch (maxComputeWorkGroupCount minimum)
constexpr std::size_t kMaxBatch = std::size_t(1) << 20;
constexpr int kMaxRuns = 64;  // runs of one check before giving up (see ShaderBsdf)

static_assert(sizeof(ShaderDevice::Query) == 48 && sizeof(ShaderDevice::Result) == 32,
              "std430 layout of the wrapper's Query and Result");

}  // namespace

// ---- Device ------------------------------------------------------------------------------

struct ShaderDevice::Impl {
  std::unique_ptr<VulkanInstance> instance;
  std::unique_ptr<VulkanDevice> device;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkShaderModule module = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  Buffer queries, results, params;
  std::size_t capacity = 0;
};

namespace {

struct PushConstants {
  uint32_t first;
  uint32_t count;
};

Buffer host_buffer(VulkanDevice& device, std::size_t bytes) {
  return Buffer(device, std::max<std::size_t>(bytes, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
}

}  // namespace

ShaderDevice::ShaderDevice(const std::vector<uint32_t>& spirv, const std::string& selector)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.instance = std::make_unique<VulkanInstance>();
  std::vector<DeviceInfo> devices = query_devices(m.instance->handle());
  m.device = std::make_unique<VulkanDevice>(*m.instance, select_device(devices, selector));
  VkDevice d = m.device->handle();
  VkDescriptorSetLayoutBinding entries[3]{};
  for (uint32_t b = 0; b < 3; ++b) {
    entries[b].binding = b;
    entries[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    entries[b].descriptorCount = 1;
    entries[b].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo set_info{};
  set_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  set_info.bindingCount = 3;
  set_info.pBindings = entries;
  vk_check(vkCreateDescriptorSetLayout(d, &set_info, nullptr, &m.set_layout),
           "vkCreateDescriptorSetLayout");
  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PushConstants)};
  VkPipelineLayoutCreateInfo layout_info{};
  layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &m.set_layout;
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  vk_check(vkCreatePipelineLayout(d, &layout_info, nullptr, &m.layout), "vkCreatePipelineLayout");
  VkShaderModuleCreateInfo module{};
  module.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  module.codeSize = spirv.size() * 4;
  module.pCode = spirv.data();
  vk_check(vkCreateShaderModule(d, &module, nullptr, &m.module), "vkCreateShaderModule");
  VkComputePipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = m.module;
  info.stage.pName = "main";
  info.layout = m.layout;
  vk_check(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &info, nullptr, &m.pipeline),
           "vkCreateComputePipelines (check-bsdf wrapper)");
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3};
  VkDescriptorPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  vk_check(vkCreateDescriptorPool(d, &pool_info, nullptr, &m.pool), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo alloc{};
  alloc.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  alloc.descriptorPool = m.pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &m.set_layout;
  vk_check(vkAllocateDescriptorSets(d, &alloc, &m.set), "vkAllocateDescriptorSets");
}

ShaderDevice::~ShaderDevice() {
  Impl& m = *impl_;
  if (!m.device) return;
  VkDevice d = m.device->handle();
  vkDeviceWaitIdle(d);
  m.queries = Buffer();
  m.results = Buffer();
  m.params = Buffer();
  if (m.pool) vkDestroyDescriptorPool(d, m.pool, nullptr);
  if (m.pipeline) vkDestroyPipeline(d, m.pipeline, nullptr);
  if (m.module) vkDestroyShaderModule(d, m.module, nullptr);
  if (m.layout) vkDestroyPipelineLayout(d, m.layout, nullptr);
  if (m.set_layout) vkDestroyDescriptorSetLayout(d, m.set_layout, nullptr);
  m.device.reset();
}

const std::string& ShaderDevice::name() const { return impl_->device->name(); }

void ShaderDevice::evaluate(const std::vector<Query>& queries, const std::vector<float>& parameters,
                            std::vector<Result>& results) {
  Impl& m = *impl_;
  VulkanDevice& device = *m.device;
  results.resize(queries.size());
  const std::size_t capacity = std::min(queries.size(), kMaxBatch);
  if (capacity > m.capacity || !m.params.handle()) {
    m.capacity = std::max(capacity, m.capacity);
    m.queries = host_buffer(device, m.capacity * sizeof(Query));
    m.results = host_buffer(device, m.capacity * sizeof(Result));
    m.params = host_buffer(device, 4 * std::max<std::size_t>(parameters.size(), 1) + 16);
    VkDescriptorBufferInfo infos[3] = {{m.queries.handle(), 0, VK_WHOLE_SIZE},
                                       {m.results.handle(), 0, VK_WHOLE_SIZE},
                                       {m.params.handle(), 0, VK_WHOLE_SIZE}};
    VkWriteDescriptorSet writes[3]{};
    for (uint32_t b = 0; b < 3; ++b) {
      writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      writes[b].dstSet = m.set;
      writes[b].dstBinding = b;
      writes[b].descriptorCount = 1;
      writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      writes[b].pBufferInfo = &infos[b];
    }
    vkUpdateDescriptorSets(device.handle(), 3, writes, 0, nullptr);
  }
  std::memset(m.params.mapped(), 0, m.params.size());
  std::memcpy(m.params.mapped(), parameters.data(), parameters.size() * sizeof(float));
  for (std::size_t first = 0; first < queries.size(); first += kMaxBatch) {
    const uint32_t count = uint32_t(std::min(queries.size() - first, kMaxBatch));
    std::memcpy(m.queries.mapped(), queries.data() + first, count * sizeof(Query));
    device.submit_and_wait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m.pipeline);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m.layout, 0, 1, &m.set, 0,
                              nullptr);
      for (uint32_t at = 0; at < count; at += kWorkgroup * kMaxGroups) {
        PushConstants push{at, count};
        vkCmdPushConstants(cmd, m.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
        vkCmdDispatch(cmd, std::min(kMaxGroups, (count - at + kWorkgroup - 1) / kWorkgroup), 1, 1);
      }
      VkMemoryBarrier barrier{};
      barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
      barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                           1, &barrier, 0, nullptr, 0, nullptr);
    });
    std::memcpy(results.data() + first, m.results.mapped(), count * sizeof(Result));
  }
  device.check_validation();
}

// ---- Memoizing evaluator ----------------------------------------------------------------

namespace {

ShaderDevice::Query make_query(uint32_t op, const glm::vec3& wi, const glm::vec3& arg) {
  ShaderDevice::Query q;
  std::memset(&q, 0, sizeof(q));
  q.op = op;
  q.wi[0] = wi.x;
  q.wi[1] = wi.y;
  q.wi[2] = wi.z;
  q.arg[0] = arg.x;
  q.arg[1] = arg.y;
  q.arg[2] = arg.z;
  return q;
}

}  // namespace

// Every query asked so far, its device result (zeros while pending) and an open-addressing table
// of their positions. A check calls in much the same order on every run, so the positions the
// previous run visited (its tape) are tried in order first, without hashing (as
// tests/bsdf_gpu/gpu_core_calls.cpp does).
struct ShaderBsdf::Impl {
  static constexpr uint32_t kEmpty = 0xffffffffu;
  std::vector<ShaderDevice::Query> queries;
  std::vector<ShaderDevice::Result> results;
  std::size_t evaluated = 0;  // queries[0, evaluated) hold device results
  std::vector<uint32_t> table;
  std::vector<uint32_t> tape, previous_tape;
  std::vector<uint32_t> tape_index;  // position -> its first call in previous_tape
  std::size_t cursor = 0;

  static uint64_t hash(const ShaderDevice::Query& q) {
    uint32_t words[12];
    std::memcpy(words, &q, sizeof(q));
    uint64_t h = 1469598103934665603ull;  // FNV-1a, then the splitmix64 finalizer
    for (uint32_t w : words) h = (h ^ w) * 1099511628211ull;
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebull;
    return h ^ (h >> 31);
  }
  static bool same(const ShaderDevice::Query& a, const ShaderDevice::Query& b) {
    return std::memcmp(&a, &b, sizeof(a)) == 0;
  }
  void insert(uint32_t position) {
    const std::size_t mask = table.size() - 1;
    for (std::size_t slot = hash(queries[position]) & mask;; slot = (slot + 1) & mask) {
      if (table[slot] == kEmpty) {
        table[slot] = position;
        return;
      }
    }
  }
  void grow() {
    table.assign(std::max<std::size_t>(1024, table.size() * 2), kEmpty);
    for (uint32_t p = 0; p < queries.size(); ++p) insert(p);
  }
  uint32_t find(const ShaderDevice::Query& q) const {
    if (table.empty()) return kEmpty;
    const std::size_t mask = table.size() - 1;
    for (std::size_t slot = hash(q) & mask;; slot = (slot + 1) & mask) {
      uint32_t p = table[slot];
      if (p == kEmpty || same(queries[p], q)) return p;
    }
  }
  const ShaderDevice::Result& lookup(const ShaderDevice::Query& q) {
    if (cursor < previous_tape.size()) {
      uint32_t p = previous_tape[cursor];
      if (same(queries[p], q)) {
        ++cursor;
        tape.push_back(p);
        return results[p];
      }
    }
    uint32_t p = find(q);
    if (p != kEmpty && p < tape_index.size() && tape_index[p] != kEmpty) {
      // Calls were added or dropped since the previous run: continue its tape after this call.
      cursor = tape_index[p] + 1;
    } else if (p == kEmpty) {
      if (2 * (queries.size() + 1) > table.size()) grow();
      p = uint32_t(queries.size());
      queries.push_back(q);
      results.push_back(ShaderDevice::Result{});
      insert(p);
    }
    tape.push_back(p);
    return results[p];
  }
};

ShaderBsdf::ShaderBsdf(ShaderDevice& device, std::vector<float> parameters)
    : impl_(std::make_unique<Impl>()), device_(device), parameters_(std::move(parameters)) {}

ShaderBsdf::~ShaderBsdf() = default;

validation::BsdfUnderTest ShaderBsdf::under_test(const std::string& name, bool reciprocal) {
  Impl* m = impl_.get();
  validation::BsdfUnderTest b;
  b.name = name;
  b.eval_includes_cosine = true;
  b.reciprocal = reciprocal;
  b.sample = [m](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    const ShaderDevice::Result& r = m->lookup(make_query(0, wi, glm::vec3(u1, u2.x, u2.y)));
    validation::BsdfSample s;
    s.wo = glm::vec3(r.wo_pdf[0], r.wo_pdf[1], r.wo_pdf[2]);
    s.pdf = r.wo_pdf[3];
    s.weight = glm::vec3(r.value[0], r.value[1], r.value[2]);
    return s;
  };
  b.pdf = [m](const glm::vec3& wi, const glm::vec3& wo) {
    return m->lookup(make_query(1, wi, wo)).wo_pdf[3];
  };
  b.eval = [m](const glm::vec3& wi, const glm::vec3& wo) {
    const ShaderDevice::Result& r = m->lookup(make_query(2, wi, wo));
    return glm::vec3(r.value[0], r.value[1], r.value[2]);
  };
  return b;
}

void ShaderBsdf::run_check(const std::function<void()>& check) {
  Impl& m = *impl_;
  // The checks share few arguments: each starts with an empty cache, which bounds the memory.
  m.queries.clear();
  m.results.clear();
  m.evaluated = 0;
  m.table.clear();
  m.tape.clear();
  for (int run = 0;; ++run) {
    m.previous_tape.swap(m.tape);
    m.tape.clear();
    m.cursor = 0;
    m.tape_index.assign(m.queries.size(), Impl::kEmpty);
    for (std::size_t i = m.previous_tape.size(); i-- > 0;)
      m.tape_index[m.previous_tape[i]] = uint32_t(i);
    check();
    if (m.queries.size() == m.evaluated) return;
    if (run + 1 >= kMaxRuns)
      throw std::runtime_error("check-bsdf: a check still asked for new values after " +
                               std::to_string(kMaxRuns) + " runs");
    std::vector<ShaderDevice::Query> pending(m.queries.begin() + m.evaluated, m.queries.end());
    std::vector<ShaderDevice::Result> results;
    device_.evaluate(pending, parameters_, results);
    std::copy(results.begin(), results.end(), m.results.begin() + m.evaluated);
    evaluations_ += pending.size();
    ++batches_;
    m.evaluated = m.queries.size();
  }
}

}  // namespace tr::shader_bsdf
