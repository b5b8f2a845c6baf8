#include "penumbra/rhi/shader_table_records.h"

#include <algorithm>
#include <cstring>

namespace penumbra::rhi {

ShaderTableRecords::Record ShaderTableRecords::makeRecord(const std::string& exportName,
                                                          const void* data, size_t bytes) {
  Record record{exportName, {}};
  if (bytes > 0) {
    const auto* p = static_cast<const uint8_t*>(data);
    record.localData.assign(p, p + bytes);
  }
  return record;
}

void ShaderTableRecords::setRayGenerationShader(const std::string& exportName,
                                                const void* localData, size_t localBytes) {
  rayGeneration_ = makeRecord(exportName, localData, localBytes);
  changed_ = true;
}

uint32_t ShaderTableRecords::addMissShader(const std::string& exportName, const void* localData,
                                           size_t localBytes) {
  miss_.push_back(makeRecord(exportName, localData, localBytes));
  changed_ = true;
  return uint32_t(miss_.size() - 1);
}

uint32_t ShaderTableRecords::addHitGroup(const std::string& exportName, const void* localData,
                                         size_t localBytes) {
  hitGroups_.push_back(makeRecord(exportName, localData, localBytes));
  changed_ = true;
  return uint32_t(hitGroups_.size() - 1);
}

void ShaderTableRecords::clearMissShaders() {
  miss_.clear();
  changed_ = true;
}

void ShaderTableRecords::clearHitGroups() {
  hitGroups_.clear();
  changed_ = true;
}

ShaderTableLayout ShaderTableRecords::recordLayout(const ShaderTableAlignment& alignment) const {
  auto largestLocalData = [](const std::vector<Record>& records) {
    size_t bytes = 0;
    for (const auto& r : records) bytes = std::max(bytes, r.localData.size());
    return uint32_t(bytes);
  };
  return computeShaderTableLayout(alignment, uint32_t(rayGeneration_.localData.size()),
                                  uint32_t(miss_.size()), largestLocalData(miss_),
                                  uint32_t(hitGroups_.size()), largestLocalData(hitGroups_));
}

void ShaderTableRecords::writeRecords(
    uint8_t* base, const ShaderTableLayout& layout, uint32_t handleSize,
    const std::function<const void*(const std::string&)>& identifier) {
  std::memset(base, 0, layout.totalBytes);
  auto write = [&](const ShaderTableRegion& region, size_t i, const Record& r) {
    uint8_t* dst = base + region.offset + region.stride * i;
    std::memcpy(dst, identifier(r.exportName), handleSize);
    if (!r.localData.empty()) std::memcpy(dst + handleSize, r.localData.data(), r.localData.size());
  };
  write(layout.rayGeneration, 0, rayGeneration_);
  for (size_t i = 0; i < miss_.size(); ++i) write(layout.miss, i, miss_[i]);
  for (size_t i = 0; i < hitGroups_.size(); ++i) write(layout.hitGroup, i, hitGroups_[i]);
  changed_ = false;
}

const ShaderTableRanges& ShaderTableRecords::upload(
    const ShaderTableAlignment& alignment, const std::string& debugName,
    const std::function<BufferHandle(const BufferDesc&)>& createBuffer,
    const std::function<const void*(const std::string&)>& identifier) {
  if (!changed_) return ranges_;
  const ShaderTableLayout layout = recordLayout(alignment);
  BufferDesc desc;
  desc.byteSize = layout.totalBytes;
  desc.usage = BufferUsage::ShaderTable;
  desc.memory = MemoryLocation::Upload;
  desc.debugName = debugName;
  buffer_ = createBuffer(desc);
  writeRecords(static_cast<uint8_t*>(buffer_->mappedData()), layout, alignment.handleSize,
               identifier);
  const uint64_t address = buffer_->deviceAddress();
  auto range = [&](const ShaderTableRegion& r) {
    ShaderTableRange v;
    if (r.count == 0) return v;
    v.address = address + r.offset;
    v.stride = r.stride;
    v.size = r.size;
    return v;
  };
  ranges_ = {range(layout.rayGeneration), range(layout.miss), range(layout.hitGroup)};
  return ranges_;
}

}  // namespace penumbra::rhi
