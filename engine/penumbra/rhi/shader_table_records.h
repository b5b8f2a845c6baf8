#pragma once
// The bookkeeping both backends' shader tables share: which export each
// record names and what local data it carries, whether that changed since
// the last upload, and writing the records into mapped memory at the places
// computeShaderTableLayout gives. A backend derives from it and adds only
// what its API needs (the identifier lookup, the buffer, the dispatch
// regions). The argument rules (known export of the right kind, local data
// no larger than the shaders read) are the validation layer's.
#include <functional>
#include <vector>

#include "penumbra/rhi/shader_table_layout.h"

namespace penumbra::rhi {

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
  // True from any change until writeRecords.
  bool changed() const { return changed_; }
  ShaderTableLayout recordLayout(const ShaderTableAlignment& alignment) const;
  // Zeroes layout.totalBytes at `base`, then writes each record's identifier
  // (handleSize bytes from identifier(exportName)) and its local data.
  void writeRecords(uint8_t* base, const ShaderTableLayout& layout, uint32_t handleSize,
                    const std::function<const void*(const std::string&)>& identifier);

 private:
  struct Record {
    std::string exportName;
    std::vector<uint8_t> localData;
  };
  static Record makeRecord(const std::string& exportName, const void* data, size_t bytes);
  Record rayGeneration_;
  std::vector<Record> miss_, hitGroups_;
  bool changed_ = true;
};

}  // namespace penumbra::rhi
