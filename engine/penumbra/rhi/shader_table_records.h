#pragma once
// What both backends' shader tables share: which export each record names
// and what local data it carries, whether that changed since the last
// upload, the upload buffer and writing the records into it at the places
// computeShaderTableLayout gives, and where each region then lies on the
// GPU. A backend derives from it and adds only what its API needs (the
// identifier lookup, its buffer type, the regions in its own struct). The argument rules (known
// export of the right kind, local data no larger than the shaders read) are the validation layer's.
#include <functional>
#include <vector>

#include "penumbra/rhi/shader_table_layout.h"

namespace penumbra::rhi {

// Where a region of an uploaded table lies: all zero when it holds no record.
// D3D12: a D3D12_GPU_VIRTUAL_ADDRESS_RANGE_AND_STRIDE. Vulkan: a
// VkStridedDeviceAddressRegionKHR.
struct ShaderTableRange {
  uint64_t address = 0;
  uint64_t stride = 0;
  uint64_t size = 0;
};

struct ShaderTableRanges {
  ShaderTableRange rayGeneration, miss, hitGroup;
};

class ShaderTableRecords : public IShaderTable {
 public:
  void setRayGenerationShader(const std::string& exportName, const void* localData,
                              size_t localBytes) override;
  uint32_t addMissShader(const std::string& exportName, const void* localData,
                         size_t localBytes) override;
  uint32_t addHitGroup(const std::string& exportName, const void* localData,
                       size_t localBytes) override;
  void clearMissShaders() override;
  void clearHitGroups() override;

 protected:
  // When a record changed since the last call: lays the records out for
  // `alignment`, creates a fresh upload buffer with `createBuffer` (the
  // backend's own, with its base alignment; a command list still in flight
  // keeps the old one alive), writes each record's identifier (handleSize
  // bytes from identifier(exportName)) and local data into it. Returns where
  // each region lies, the same ranges again when nothing changed.
  const ShaderTableRanges& upload(
      const ShaderTableAlignment& alignment, const std::string& debugName,
      const std::function<BufferHandle(const BufferDesc&)>& createBuffer,
      const std::function<const void*(const std::string&)>& identifier);
  // The buffer the last upload wrote (null before the first).
  const BufferHandle& uploadBuffer() const { return buffer_; }

 private:
  ShaderTableLayout recordLayout(const ShaderTableAlignment& alignment) const;
  // Zeroes layout.totalBytes at `base`, then writes the records.
  void writeRecords(uint8_t* base, const ShaderTableLayout& layout, uint32_t handleSize,
                    const std::function<const void*(const std::string&)>& identifier);
  struct Record {
    std::string exportName;
    std::vector<uint8_t> localData;
  };
  static Record makeRecord(const std::string& exportName, const void* data, size_t bytes);
  Record rayGeneration_;
  std::vector<Record> miss_, hitGroups_;
  bool changed_ = true;  // from any change until the next upload
  BufferHandle buffer_;
  ShaderTableRanges ranges_;
};

}  // namespace penumbra::rhi
