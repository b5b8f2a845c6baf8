// Pipeline layouts (from reflection), compute and ray-tracing pipelines,
// binding sets and shader tables.
#include <fmt/format.h>

#include <cstring>

#include "penumbra/rhi/binding_layout.h"
#include "penumbra/rhi/shader_table_layout.h"
#include "penumbra/util/error.h"
#include "vulkan_backend.h"

namespace penumbra::vk {
namespace {

VkDescriptorType toDescriptorType(rhi::ResourceType type) {
  switch (type) {
    case rhi::ResourceType::AccelStruct:
      return VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
    case rhi::ResourceType::StorageBuffer:
      return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case rhi::ResourceType::ConstantBuffer:
      return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case rhi::ResourceType::StorageTexture:
      return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    case rhi::ResourceType::SampledTexture:
      return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case rhi::ResourceType::Sampler:
      return VK_DESCRIPTOR_TYPE_SAMPLER;
  }
  return VK_DESCRIPTOR_TYPE_MAX_ENUM;
}

VkShaderStageFlagBits toVkStage(rhi::ShaderStage stage) {
  switch (stage) {
    case rhi::ShaderStage::Compute:
      return VK_SHADER_STAGE_COMPUTE_BIT;
    case rhi::ShaderStage::RayGeneration:
      return VK_SHADER_STAGE_RAYGEN_BIT_KHR;
    case rhi::ShaderStage::Miss:
      return VK_SHADER_STAGE_MISS_BIT_KHR;
    case rhi::ShaderStage::ClosestHit:
      return VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR;
    case rhi::ShaderStage::AnyHit:
      return VK_SHADER_STAGE_ANY_HIT_BIT_KHR;
    case rhi::ShaderStage::Intersection:
      return VK_SHADER_STAGE_INTERSECTION_BIT_KHR;
    case rhi::ShaderStage::Vertex:
      return VK_SHADER_STAGE_VERTEX_BIT;
    case rhi::ShaderStage::Pixel:
      return VK_SHADER_STAGE_FRAGMENT_BIT;
  }
  return VK_SHADER_STAGE_ALL;
}

std::span<const uint32_t> spirvOf(const rhi::ShaderDesc& shader) {
  if (shader.spirv.empty())
    throw Error(fmt::format("vulkan: shader '{}' has no SPIR-V", shader.exportName));
  return shader.spirv;
}

VkShaderModule createModule(VulkanDevice& device, const rhi::ShaderDesc& shader) {
  auto words = spirvOf(shader);
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = words.size_bytes();
  info.pCode = words.data();
  VkShaderModule module = VK_NULL_HANDLE;
  check(vkCreateShaderModule(device.handle(), &info, nullptr, &module), "vkCreateShaderModule");
  device.setName(VK_OBJECT_TYPE_SHADER_MODULE, uint64_t(module), shader.exportName);
  return module;
}

}  // namespace

VulkanPipelineLayout::VulkanPipelineLayout(VulkanDevice& device, rhi::PipelineBindingLayout layout,
                                           VkShaderStageFlags stages)
    : device_(device), layout_(std::move(layout)), stages_(stages) {
  for (const auto& space : layout_.spaces) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    // An unbounded array becomes a fixed-size binding (Vulkan has no
    // unbounded ones) that binding sets fill only in part: PARTIALLY_BOUND
    // makes the unwritten elements legal as long as shaders do not read them.
    std::vector<VkDescriptorBindingFlags> flags;
    bool anyPartial = false;
    for (const auto& item : space.items) {
      VkDescriptorSetLayoutBinding b{};
      b.binding = item.slot;
      b.descriptorType = toDescriptorType(item.type);
      b.descriptorCount = item.arraySize > 0 ? item.arraySize : device_.bindlessCapacity(item.type);
      b.stageFlags = stages_;
      bindings.push_back(b);
      flags.push_back(item.arraySize == 0 ? VK_DESCRIPTOR_BINDING_PARTIALLY_BOUND_BIT : 0);
      anyPartial = anyPartial || item.arraySize == 0;
    }
    VkDescriptorSetLayoutBindingFlagsCreateInfo flagsInfo{
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO};
    flagsInfo.bindingCount = uint32_t(flags.size());
    flagsInfo.pBindingFlags = flags.data();
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.pNext = anyPartial ? &flagsInfo : nullptr;
    info.bindingCount = uint32_t(bindings.size());
    info.pBindings = bindings.data();
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    check(vkCreateDescriptorSetLayout(device_.handle(), &info, nullptr, &setLayout),
          "vkCreateDescriptorSetLayout");
    setLayouts_.push_back(setLayout);
    setBindings_.push_back(std::move(bindings));
  }
  VkPushConstantRange range{stages_, 0, layout_.pushConstantBytes};
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = uint32_t(setLayouts_.size());
  info.pSetLayouts = setLayouts_.data();
  info.pushConstantRangeCount = layout_.pushConstantBytes > 0 ? 1 : 0;
  info.pPushConstantRanges = &range;
  check(vkCreatePipelineLayout(device_.handle(), &info, nullptr, &pipelineLayout_),
        "vkCreatePipelineLayout");
}

VulkanPipelineLayout::~VulkanPipelineLayout() {
  vkDestroyPipelineLayout(device_.handle(), pipelineLayout_, nullptr);
  for (auto l : setLayouts_) vkDestroyDescriptorSetLayout(device_.handle(), l, nullptr);
}

VulkanComputePipeline::VulkanComputePipeline(VulkanDevice& device,
                                             const rhi::ComputePipelineDesc& desc)
    : device_(device) {
  rhi::PipelineBindingLayout reflected;
  rhi::mergeBindingLayout(reflected, desc.shader.bindingLayout, desc.shader.exportName);
  layout_ = std::make_unique<VulkanPipelineLayout>(device_, std::move(reflected),
                                                   VK_SHADER_STAGE_COMPUTE_BIT);
  VkShaderModule module = createModule(device_, desc.shader);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = desc.shader.entryPoint.c_str();
  info.layout = layout_->handle();
  VkResult r =
      vkCreateComputePipelines(device_.handle(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_);
  vkDestroyShaderModule(device_.handle(), module, nullptr);
  check(r, "vkCreateComputePipelines");
  device_.setName(VK_OBJECT_TYPE_PIPELINE, uint64_t(pipeline_), desc.debugName);
}

VulkanComputePipeline::~VulkanComputePipeline() {
  vkDestroyPipeline(device_.handle(), pipeline_, nullptr);
}

VulkanGraphicsPipeline::VulkanGraphicsPipeline(VulkanDevice& device,
                                               const rhi::GraphicsPipelineDesc& desc)
    : device_(device), desc_(desc) {
  rhi::PipelineBindingLayout reflected;
  rhi::mergeBindingLayout(reflected, desc.vertexShader.bindingLayout, desc.vertexShader.exportName);
  rhi::mergeBindingLayout(reflected, desc.pixelShader.bindingLayout, desc.pixelShader.exportName);
  layout_ = std::make_unique<VulkanPipelineLayout>(
      device_, std::move(reflected), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);

  std::vector<VkVertexInputAttributeDescription> attributes;
  for (const auto& a : desc.vertexLayout.attributes)
    attributes.push_back({a.location, 0, toVkFormat(a.format), a.offset});
  VkVertexInputBindingDescription binding{0, desc.vertexLayout.stride, VK_VERTEX_INPUT_RATE_VERTEX};
  VkPipelineVertexInputStateCreateInfo vertexInput{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &binding;
  vertexInput.vertexAttributeDescriptionCount = uint32_t(attributes.size());
  vertexInput.pVertexAttributeDescriptions = attributes.data();
  VkPipelineInputAssemblyStateCreateInfo inputAssembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  inputAssembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineColorBlendAttachmentState blend{};
  blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                         VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  if (desc.blend == rhi::BlendMode::AlphaBlend) {
    blend.blendEnable = VK_TRUE;
    blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.colorBlendOp = VK_BLEND_OP_ADD;
    blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  VkPipelineColorBlendStateCreateInfo colorBlend{
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  colorBlend.attachmentCount = 1;
  colorBlend.pAttachments = &blend;
  // No depth attachment, so no depth-stencil state.
  const VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamicStates;
  const VkFormat colorFormat = toVkFormat(desc.renderTargetFormat);
  VkPipelineRenderingCreateInfoKHR rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO_KHR};
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachmentFormats = &colorFormat;

  VkShaderModule vertexModule = createModule(device_, desc.vertexShader);
  VkShaderModule pixelModule = VK_NULL_HANDLE;
  try {
    pixelModule = createModule(device_, desc.pixelShader);
  } catch (...) {
    vkDestroyShaderModule(device_.handle(), vertexModule, nullptr);
    throw;
  }
  VkPipelineShaderStageCreateInfo stages[2] = {
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
      {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertexModule;
  stages[0].pName = desc.vertexShader.entryPoint.c_str();
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = pixelModule;
  stages[1].pName = desc.pixelShader.entryPoint.c_str();

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.pNext = &rendering;
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &inputAssembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pColorBlendState = &colorBlend;
  info.pDynamicState = &dynamic;
  info.layout = layout_->handle();
  VkResult r =
      vkCreateGraphicsPipelines(device_.handle(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_);
  vkDestroyShaderModule(device_.handle(), vertexModule, nullptr);
  vkDestroyShaderModule(device_.handle(), pixelModule, nullptr);
  check(r, "vkCreateGraphicsPipelines");
  device_.setName(VK_OBJECT_TYPE_PIPELINE, uint64_t(pipeline_), desc.debugName);
}

VulkanGraphicsPipeline::~VulkanGraphicsPipeline() {
  vkDestroyPipeline(device_.handle(), pipeline_, nullptr);
}

VulkanRayTracingPipeline::VulkanRayTracingPipeline(VulkanDevice& device,
                                                   const rhi::RayTracingPipelineDesc& desc)
    : device_(device), desc_(desc) {
  const auto& adapter = device_.adapter();

  rhi::PipelineBindingLayout reflected;
  std::map<std::string, uint32_t> stageIndex;
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  std::vector<VkShaderModule> modules;
  VkShaderStageFlags usedStages = 0;
  for (const auto& shader : desc.shaders) {
    stageIndex.emplace(shader.exportName, uint32_t(stages.size()));
    rhi::mergeBindingLayout(reflected, shader.bindingLayout, shader.exportName);
    modules.push_back(createModule(device_, shader));
    VkPipelineShaderStageCreateInfo s{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    s.stage = toVkStage(shader.stage);
    s.module = modules.back();
    s.pName = shader.entryPoint.c_str();
    stages.push_back(s);
    usedStages |= s.stage;
  }

  std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups;
  auto newGroup = [](VkRayTracingShaderGroupTypeKHR type) {
    VkRayTracingShaderGroupCreateInfoKHR g{
        VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
    g.type = type;
    g.generalShader = g.closestHitShader = g.anyHitShader = g.intersectionShader =
        VK_SHADER_UNUSED_KHR;
    return g;
  };
  for (const auto& shader : desc.shaders) {
    if (shader.stage == rhi::ShaderStage::RayGeneration || shader.stage == rhi::ShaderStage::Miss) {
      auto g = newGroup(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR);
      g.generalShader = stageIndex.at(shader.exportName);
      groupIndex_[shader.exportName] = uint32_t(groups.size());
      groups.push_back(g);
    }
  }
  // The validation layer checked that every name is a shader of the right stage.
  auto lookup = [&](const std::string& name) {
    return name.empty() ? VK_SHADER_UNUSED_KHR : stageIndex.at(name);
  };
  for (const auto& hg : desc.hitGroups) {
    auto g = newGroup(hg.isProcedural ? VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR
                                      : VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR);
    g.closestHitShader = lookup(hg.closestHit);
    g.anyHitShader = lookup(hg.anyHit);
    g.intersectionShader = lookup(hg.intersection);
    groupIndex_.emplace(hg.exportName, uint32_t(groups.size()));
    groups.push_back(g);
  }

  layout_ = std::make_unique<VulkanPipelineLayout>(device_, std::move(reflected), usedStages);
  VkRayTracingPipelineCreateInfoKHR info{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  info.stageCount = uint32_t(stages.size());
  info.pStages = stages.data();
  info.groupCount = uint32_t(groups.size());
  info.pGroups = groups.data();
  info.maxPipelineRayRecursionDepth = desc.maxRecursionDepth;
  info.layout = layout_->handle();
  VkResult r = vkCreateRayTracingPipelinesKHR(device_.handle(), VK_NULL_HANDLE, VK_NULL_HANDLE, 1,
                                              &info, nullptr, &pipeline_);
  for (auto m : modules) vkDestroyShaderModule(device_.handle(), m, nullptr);
  check(r, "vkCreateRayTracingPipelinesKHR");
  device_.setName(VK_OBJECT_TYPE_PIPELINE, uint64_t(pipeline_), desc.debugName);

  const uint32_t handleSize = adapter.shaderTable.handleSize;
  groupHandles_.resize(size_t(handleSize) * groups.size());
  check(
      vkGetRayTracingShaderGroupHandlesKHR(device_.handle(), pipeline_, 0, uint32_t(groups.size()),
                                           groupHandles_.size(), groupHandles_.data()),
      "vkGetRayTracingShaderGroupHandlesKHR");
}

VulkanRayTracingPipeline::~VulkanRayTracingPipeline() {
  vkDestroyPipeline(device_.handle(), pipeline_, nullptr);
}

const uint8_t* VulkanRayTracingPipeline::groupHandle(const std::string& exportName) const {
  auto it = groupIndex_.find(exportName);
  if (it == groupIndex_.end())
    throw Error(fmt::format("vulkan: pipeline '{}' has no raygen/miss shader or hit group '{}'",
                            desc_.debugName, exportName));
  return groupHandles_.data() + size_t(it->second) * device_.adapter().shaderTable.handleSize;
}

rhi::ShaderTableHandle VulkanRayTracingPipeline::createShaderTable(const std::string& debugName) {
  return std::make_shared<VulkanShaderTable>(device_, shared_from_this(), debugName);
}

VulkanBindingSet::VulkanBindingSet(VulkanDevice& device, const rhi::BindingSetDesc& desc,
                                   const VulkanPipelineLayout& layout)
    : device_(device), desc_(desc) {
  if (desc.space < layout.bindingLayout().spaces.size())
    layoutItems_ = layout.bindingLayout().spaces[desc.space].items;

  // The pool must hold every descriptor of the set layout, arrays (and the
  // full capacity of unbounded ones) included, whatever the set writes.
  std::vector<VkDescriptorPoolSize> sizes;
  if (desc.space < layout.bindingLayout().spaces.size())
    for (const auto& b : layout.setBindings(desc.space))
      sizes.push_back({b.descriptorType, b.descriptorCount});
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = uint32_t(sizes.size());
  poolInfo.pPoolSizes = sizes.data();
  VkDescriptorPoolSize dummy{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
  if (sizes.empty()) {
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &dummy;
  }
  check(vkCreateDescriptorPool(device_.handle(), &poolInfo, nullptr, &pool_),
        "vkCreateDescriptorPool");
  VkDescriptorSetLayout setLayout = layout.setLayout(desc.space);
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &setLayout;
  check(vkAllocateDescriptorSets(device_.handle(), &alloc, &set_), "vkAllocateDescriptorSets");
  device_.setName(VK_OBJECT_TYPE_DESCRIPTOR_SET, uint64_t(set_), desc.debugName);

  // Reserve so the pointers the writes keep stay valid.
  std::vector<VkDescriptorBufferInfo> bufferInfos;
  std::vector<VkDescriptorImageInfo> imageInfos;
  std::vector<VkWriteDescriptorSetAccelerationStructureKHR> asInfos;
  std::vector<VkAccelerationStructureKHR> asHandles;
  size_t imageCount = 0;
  for (const auto& item : desc.items) imageCount += item.elementCount();
  bufferInfos.reserve(desc.items.size());
  imageInfos.reserve(imageCount);
  asInfos.reserve(desc.items.size());
  asHandles.reserve(desc.items.size());
  std::vector<VkWriteDescriptorSet> writes;
  for (const auto& item : desc.items) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set_;
    w.dstBinding = item.slot;
    w.descriptorCount = 1;
    w.descriptorType = toDescriptorType(item.type);
    switch (item.type) {
      case rhi::ResourceType::AccelStruct: {
        asHandles.push_back(static_cast<VulkanAccelStruct*>(item.accelStruct.get())->handle());
        VkWriteDescriptorSetAccelerationStructureKHR a{
            VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
        a.accelerationStructureCount = 1;
        a.pAccelerationStructures = &asHandles.back();
        asInfos.push_back(a);
        w.pNext = &asInfos.back();
        break;
      }
      case rhi::ResourceType::StorageBuffer:
      case rhi::ResourceType::ConstantBuffer: {
        auto* b = static_cast<VulkanBuffer*>(item.buffer.get());
        bufferInfos.push_back({b->handle(), 0, VK_WHOLE_SIZE});
        w.pBufferInfo = &bufferInfos.back();
        break;
      }
      case rhi::ResourceType::StorageTexture: {
        auto* t = static_cast<VulkanTexture*>(item.texture.get());
        imageInfos.push_back({VK_NULL_HANDLE, t->view(), VK_IMAGE_LAYOUT_GENERAL});
        w.pImageInfo = &imageInfos.back();
        break;
      }
      // Arrays: elements 0..n-1 in one write; elements of an unbounded array
      // past n stay unwritten (PARTIALLY_BOUND). Sampled textures are read in
      // GENERAL, the layout the command lists give ResourceState::ShaderResource.
      case rhi::ResourceType::SampledTexture: {
        w.descriptorCount = uint32_t(item.textures.size());
        w.pImageInfo = imageInfos.data() + imageInfos.size();
        for (const auto& texture : item.textures)
          imageInfos.push_back({VK_NULL_HANDLE, static_cast<VulkanTexture*>(texture.get())->view(),
                                VK_IMAGE_LAYOUT_GENERAL});
        break;
      }
      case rhi::ResourceType::Sampler: {
        w.descriptorCount = uint32_t(item.samplerHandles.size());
        w.pImageInfo = imageInfos.data() + imageInfos.size();
        for (const auto& sampler : item.samplerHandles)
          imageInfos.push_back({static_cast<VulkanSampler*>(sampler.get())->handle(),
                                VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED});
        break;
      }
    }
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device_.handle(), uint32_t(writes.size()), writes.data(), 0, nullptr);
}

VulkanBindingSet::~VulkanBindingSet() {
  vkDestroyDescriptorPool(device_.handle(), pool_, nullptr);
}

bool VulkanBindingSet::isWritable(uint32_t slot) const {
  for (const auto& item : layoutItems_)
    if (item.slot == slot) return item.writable;
  return false;
}

VulkanShaderTable::VulkanShaderTable(VulkanDevice& device,
                                     std::shared_ptr<VulkanRayTracingPipeline> pipeline,
                                     std::string debugName)
    : device_(device), pipeline_(std::move(pipeline)), debugName_(std::move(debugName)) {}

VulkanShaderTable::Regions VulkanShaderTable::prepare() {
  const auto& align = device_.adapter().shaderTable;
  // The buffer starts shaderGroupBaseAlignment aligned, so every region does.
  const rhi::ShaderTableRanges& ranges = upload(
      align, debugName_,
      [&](const rhi::BufferDesc& desc) {
        return std::make_shared<VulkanBuffer>(device_, desc, align.tableAlignment);
      },
      [&](const std::string& name) { return pipeline_->groupHandle(name); });
  auto region = [](const rhi::ShaderTableRange& r) {
    return VkStridedDeviceAddressRegionKHR{r.address, r.stride, r.size};
  };
  return {region(ranges.rayGeneration), region(ranges.miss), region(ranges.hitGroup), {}};
}

std::shared_ptr<VulkanBuffer> VulkanShaderTable::buffer() const {
  return std::static_pointer_cast<VulkanBuffer>(uploadBuffer());
}

}  // namespace penumbra::vk
