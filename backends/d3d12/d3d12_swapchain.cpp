#include "d3d12_swapchain.h"

#include <fmt/format.h>

#include <algorithm>

#include "penumbra/util/error.h"

namespace penumbra::d3d12 {

D3D12Swapchain::D3D12Swapchain(D3D12Device& device, const rhi::SwapchainDesc& desc)
    : device_(device), desc_(desc) {
  if (desc_.window.system != rhi::WindowSystem::Win32 || !desc_.window.window)
    throw Error(fmt::format("d3d12: a swapchain needs a Win32 window (got a {} window)",
                            rhi::windowSystemName(desc_.window.system)));
  window_ = static_cast<HWND>(desc_.window.window);

  ComPtr<IDXGIFactory5> factory5;
  if (SUCCEEDED(device_.factory()->QueryInterface(IID_PPV_ARGS(&factory5)))) {
    BOOL allowTearing = FALSE;
    tearing_ = SUCCEEDED(factory5->CheckFeatureSupport(DXGI_FEATURE_PRESENT_ALLOW_TEARING,
                                                       &allowTearing, sizeof(allowTearing))) &&
               allowTearing;
  }

  DXGI_SWAP_CHAIN_DESC1 sd{};
  sd.Width = desc_.width;
  sd.Height = desc_.height;
  sd.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
  sd.SampleDesc.Count = 1;
  sd.BufferUsage = DXGI_USAGE_RENDER_TARGET_OUTPUT;
  // One buffer more than the frames in flight, as on Vulkan.
  sd.BufferCount = std::max(2u, desc_.framesInFlight + 1);
  sd.Scaling = DXGI_SCALING_STRETCH;
  sd.SwapEffect = DXGI_SWAP_EFFECT_FLIP_DISCARD;
  sd.AlphaMode = DXGI_ALPHA_MODE_IGNORE;
  sd.Flags = tearing_ ? DXGI_SWAP_CHAIN_FLAG_ALLOW_TEARING : 0;
  ComPtr<IDXGISwapChain1> swapchain1;
  // Flip-model swapchains present through the queue they were created on.
  check(device_.factory()->CreateSwapChainForHwnd(device_.queue(), window_, &sd, nullptr, nullptr,
                                                  &swapchain1),
        "IDXGIFactory4::CreateSwapChainForHwnd");
  check(swapchain1.As(&swapchain_), "IDXGISwapChain1 -> IDXGISwapChain3");
  // The viewer handles its own full-screen toggling (if any), not DXGI's Alt+Enter.
  device_.factory()->MakeWindowAssociation(window_, DXGI_MWA_NO_ALT_ENTER);
  slotFence_.assign(desc_.framesInFlight, 0);
  getBuffers();
}

D3D12Swapchain::~D3D12Swapchain() {
  try {
    device_.waitForIdle();
  } catch (const std::exception&) {
    // Destruction goes on: the device reports its own removal.
  }
}

void D3D12Swapchain::getBuffers() {
  DXGI_SWAP_CHAIN_DESC1 sd{};
  check(swapchain_->GetDesc1(&sd), "IDXGISwapChain1::GetDesc1");
  desc_.width = sd.Width;
  desc_.height = sd.Height;
  buffers_.clear();
  for (UINT i = 0; i < sd.BufferCount; ++i) {
    ComPtr<ID3D12Resource> resource;
    check(swapchain_->GetBuffer(i, IID_PPV_ARGS(&resource)), "IDXGISwapChain::GetBuffer");
    rhi::TextureDesc texture;
    texture.width = sd.Width;
    texture.height = sd.Height;
    texture.format = rhi::Format::RGBA8_UNORM;
    texture.usage = rhi::TextureUsage::CopyDest | rhi::TextureUsage::RenderTarget;
    texture.debugName = fmt::format("{} buffer {}", desc_.debugName, i);
    auto buffer = std::make_unique<D3D12Texture>(texture, resource);
    buffer->state = rhi::ResourceState::Present;  // back buffers start in PRESENT (= COMMON)
    buffers_.push_back(std::move(buffer));
  }
}

rhi::ITexture* D3D12Swapchain::acquireNextImage() {
  if (acquired_) throw Error("d3d12: acquireNextImage twice without present");
  RECT client{};
  // A minimised window has no client area to present to.
  if (GetClientRect(window_, &client) && (client.right == 0 || client.bottom == 0)) return nullptr;
  if (uint32_t(client.right) != desc_.width || uint32_t(client.bottom) != desc_.height)
    return nullptr;
  device_.waitForFence(slotFence_[slot_]);
  imageIndex_ = swapchain_->GetCurrentBackBufferIndex();
  acquired_ = true;
  return buffers_[imageIndex_].get();
}

bool D3D12Swapchain::present(rhi::ICommandList* commandList) {
  if (!acquired_) throw Error("d3d12: present without acquireNextImage");
  acquired_ = false;
  if (buffers_[imageIndex_]->state != rhi::ResourceState::Present)
    throw Error(
        "d3d12: present: the command list must leave the back buffer in ResourceState::Present");
  device_.submit(commandList);
  const UINT sync = desc_.vsync ? 1 : 0;
  const UINT flags = !desc_.vsync && tearing_ ? DXGI_PRESENT_ALLOW_TEARING : 0;
  const HRESULT hr = swapchain_->Present(sync, flags);
  slotFence_[slot_] = device_.signalQueue();
  slot_ = (slot_ + 1) % desc_.framesInFlight;
  if (hr == DXGI_STATUS_OCCLUDED) return true;  // hidden: nothing shown, nothing wrong
  device_.checkDevice(hr, "IDXGISwapChain::Present");
  return true;
}

void D3D12Swapchain::resize(uint32_t width, uint32_t height) {
  if (acquired_) throw Error("d3d12: resize between acquireNextImage and present");
  device_.waitForIdle();
  buffers_.clear();  // ResizeBuffers fails while any reference to a buffer remains
  check(swapchain_->ResizeBuffers(0, width, height, DXGI_FORMAT_UNKNOWN,
                                  tearing_ ? DXGI_SWAP_CHAIN_FLAG_ALLOW_TEARING : 0),
        "IDXGISwapChain::ResizeBuffers");
  getBuffers();
}

}  // namespace penumbra::d3d12
