#pragma once
// A DXGI flip-model swapchain behind rhi::ISwapchain.
#include <memory>
#include <vector>

#include "d3d12_backend.h"
#include "penumbra/rhi/presentation.h"

namespace penumbra::d3d12 {

class D3D12Swapchain final : public rhi::ISwapchain {
 public:
  D3D12Swapchain(D3D12Device& device, const rhi::SwapchainDesc& desc);
  ~D3D12Swapchain() override;
  const rhi::SwapchainDesc& desc() const override { return desc_; }
  // R8G8B8A8_UNORM: CopyTextureRegion cannot swizzle, and the tonemapper writes RGBA.
  rhi::Format format() const override { return rhi::Format::RGBA8_UNORM; }
  rhi::ITexture* acquireNextImage() override;
  bool present(rhi::ICommandList* commandList) override;
  void resize(uint32_t width, uint32_t height) override;
  void setVsync(bool vsync) override { desc_.vsync = vsync; }
  uint32_t imageCount() const override { return uint32_t(buffers_.size()); }

  // For the viewer's UI renderer (d3d12_interop.h).
  ID3D12Resource* backBuffer(uint32_t index) const { return buffers_.at(index)->resource(); }
  uint32_t currentImage() const { return imageIndex_; }

 private:
  void getBuffers();
  D3D12Device& device_;
  rhi::SwapchainDesc desc_;
  HWND window_ = nullptr;
  ComPtr<IDXGISwapChain3> swapchain_;
  bool tearing_ = false;  // DXGI_FEATURE_PRESENT_ALLOW_TEARING: vsync off without waiting
  std::vector<std::unique_ptr<D3D12Texture>> buffers_;
  std::vector<uint64_t> slotFence_;  // per frame slot: fence value of its last frame
  uint32_t slot_ = 0;
  uint32_t imageIndex_ = 0;
  bool acquired_ = false;
};

}  // namespace penumbra::d3d12
