// DXGI adapter enumeration, the DXR tier check, and device selection.
#include <fmt/format.h>

#include "d3d12_backend.h"
#include "penumbra/util/error.h"

namespace penumbra::d3d12 {
namespace {

std::string featureLevelName(D3D_FEATURE_LEVEL level) {
  return fmt::format("D3D12 feature level {}_{}", (unsigned(level) >> 12) & 0xf,
                     (unsigned(level) >> 8) & 0xf);
}

// Fills `info` from a device created on the adapter: DXR tier, feature level,
// UMA (integrated) or not.
void probeDevice(ID3D12Device* device, rhi::AdapterInfo& info) {
  D3D12_FEATURE_DATA_D3D12_OPTIONS5 options5{};
  if (SUCCEEDED(device->CheckFeatureSupport(D3D12_FEATURE_D3D12_OPTIONS5, &options5, sizeof(options5)))) {
    const bool tier10 = options5.RaytracingTier >= D3D12_RAYTRACING_TIER_1_0;
    info.rayTracingPipeline = tier10;
    info.accelerationStructure = tier10;
    info.rayQuery = options5.RaytracingTier >= D3D12_RAYTRACING_TIER_1_1;
  }
  // DXR caps the declarable TraceRay recursion at 31 on every tier.
  info.maxRecursionDepth = info.rayTracingPipeline ? D3D12_RAYTRACING_MAX_DECLARABLE_TRACE_RECURSION_DEPTH : 0;
  info.shaderTable.handleSize = D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES;
  info.shaderTable.recordAlignment = D3D12_RAYTRACING_SHADER_RECORD_BYTE_ALIGNMENT;
  info.shaderTable.tableAlignment = D3D12_RAYTRACING_SHADER_TABLE_BYTE_ALIGNMENT;
  info.shaderTable.maxRecordStride = D3D12_RAYTRACING_MAX_SHADER_RECORD_STRIDE;

  const D3D_FEATURE_LEVEL levels[] = {D3D_FEATURE_LEVEL_12_2, D3D_FEATURE_LEVEL_12_1, D3D_FEATURE_LEVEL_12_0,
                                      D3D_FEATURE_LEVEL_11_1, D3D_FEATURE_LEVEL_11_0};
  D3D12_FEATURE_DATA_FEATURE_LEVELS fl{};
  fl.NumFeatureLevels = UINT(std::size(levels));
  fl.pFeatureLevelsRequested = levels;
  if (SUCCEEDED(device->CheckFeatureSupport(D3D12_FEATURE_FEATURE_LEVELS, &fl, sizeof(fl))))
    info.apiVersion = featureLevelName(fl.MaxSupportedFeatureLevel);
  // D3D12_RAYTRACING_TIER_1_0 is 10, _1_1 is 11.
  const unsigned tier = unsigned(options5.RaytracingTier);
  info.apiVersion += tier >= D3D12_RAYTRACING_TIER_1_0
                         ? fmt::format(", DXR tier {}.{}", tier / 10, tier % 10)
                         : std::string(", no DXR");

  D3D12_FEATURE_DATA_ARCHITECTURE arch{};
  if (info.type != rhi::AdapterType::Cpu &&
      SUCCEEDED(device->CheckFeatureSupport(D3D12_FEATURE_ARCHITECTURE, &arch, sizeof(arch))))
    info.type = arch.UMA ? rhi::AdapterType::Integrated : rhi::AdapterType::Discrete;
}

}  // namespace

ComPtr<IDXGIFactory4> createFactory(bool debug) {
  ComPtr<IDXGIFactory4> factory;
  check(library().createDxgiFactory2(debug ? DXGI_CREATE_FACTORY_DEBUG : 0, IID_PPV_ARGS(&factory)),
        "CreateDXGIFactory2");
  return factory;
}

std::vector<Adapter> enumerateAdapters(IDXGIFactory4* factory) {
  std::vector<Adapter> adapters;
  ComPtr<IDXGIAdapter1> dxgiAdapter;
  for (UINT i = 0; factory->EnumAdapters1(i, &dxgiAdapter) != DXGI_ERROR_NOT_FOUND; ++i) {
    DXGI_ADAPTER_DESC1 desc{};
    dxgiAdapter->GetDesc1(&desc);
    Adapter a;
    a.adapter = dxgiAdapter;
    a.info.index = i;
    a.info.name = fromWide(desc.Description);
    a.info.type = (desc.Flags & DXGI_ADAPTER_FLAG_SOFTWARE) ? rhi::AdapterType::Cpu : rhi::AdapterType::Other;
    LARGE_INTEGER umd{};
    if (SUCCEEDED(dxgiAdapter->CheckInterfaceSupport(__uuidof(IDXGIDevice), &umd)))
      a.info.driver = fmt::format("{}.{}.{}.{}", HIWORD(umd.HighPart), LOWORD(umd.HighPart),
                                  HIWORD(umd.LowPart), LOWORD(umd.LowPart));
    ComPtr<ID3D12Device> probe;
    if (SUCCEEDED(library().createDevice(dxgiAdapter.Get(), D3D_FEATURE_LEVEL_11_0, IID_PPV_ARGS(&probe))))
      probeDevice(probe.Get(), a.info);
    else
      a.info.apiVersion = "no D3D12 device";
    adapters.push_back(std::move(a));
  }
  return adapters;
}

std::vector<rhi::AdapterInfo> listAdapters() {
  auto factory = createFactory(false);
  std::vector<rhi::AdapterInfo> infos;
  for (auto& a : enumerateAdapters(factory.Get())) infos.push_back(a.info);
  return infos;
}

rhi::DeviceHandle createDevice(const rhi::DeviceCreateInfo& info) {
  if (info.validation) {
    // The debug layer must be on before the device exists; GPU-based
    // validation also checks descriptors and resource states on the GPU.
    ComPtr<ID3D12Debug> debug;
    if (!library().getDebugInterface || FAILED(library().getDebugInterface(IID_PPV_ARGS(&debug))))
      throw Error("d3d12: --validation needs the D3D12 debug layer (Windows 'Graphics Tools' optional feature)");
    debug->EnableDebugLayer();
    ComPtr<ID3D12Debug1> debug1;
    if (SUCCEEDED(debug.As(&debug1))) debug1->SetEnableGPUBasedValidation(TRUE);
  }
  auto factory = createFactory(info.validation);
  auto adapters = enumerateAdapters(factory.Get());
  if (adapters.empty()) throw Error("d3d12: no DXGI adapters found");
  if (info.adapterIndex >= 0) {
    if (size_t(info.adapterIndex) >= adapters.size())
      throw Error(fmt::format("d3d12: no adapter {} (found {}; see `penumbra devices --backend d3d12`)",
                              info.adapterIndex, adapters.size()));
    auto& a = adapters[size_t(info.adapterIndex)];
    if (!a.info.supportsRayTracing())
      throw Error(fmt::format("d3d12: adapter {} ({}) has no DXR (needs D3D12_RAYTRACING_TIER_1_0)",
                              info.adapterIndex, a.info.name));
    return std::make_shared<D3D12Device>(factory, std::move(a), info.validation,
                                         info.bindingOffsets);
  }
  // Default: the first GPU with DXR; a software adapter (WARP) only if no GPU has it.
  for (int pass = 0; pass < 2; ++pass)
    for (auto& a : adapters)
      if (a.info.supportsRayTracing() && (pass == 1 || a.info.type != rhi::AdapterType::Cpu))
        return std::make_shared<D3D12Device>(factory, std::move(a), info.validation,
                                             info.bindingOffsets);
  throw Error("d3d12: no adapter supports DXR (D3D12_RAYTRACING_TIER_1_0)");
}

}  // namespace penumbra::d3d12
