// HRESULT checks, UTF-8/UTF-16 conversion, debug names, and the run-time
// loading of d3d12.dll and dxgi.dll.
#include "d3d12_common.h"

#include <fmt/format.h>

#include <mutex>

#include "d3d12_backend.h"
#include "penumbra/util/error.h"

namespace penumbra::d3d12 {

std::string hresultName(HRESULT hr) {
  switch (hr) {
    case E_OUTOFMEMORY: return "E_OUTOFMEMORY";
    case E_INVALIDARG: return "E_INVALIDARG";
    case E_NOINTERFACE: return "E_NOINTERFACE";
    case E_NOTIMPL: return "E_NOTIMPL";
    case E_FAIL: return "E_FAIL";
    case DXGI_ERROR_NOT_FOUND: return "DXGI_ERROR_NOT_FOUND";
    case DXGI_ERROR_UNSUPPORTED: return "DXGI_ERROR_UNSUPPORTED";
    case DXGI_ERROR_DEVICE_REMOVED: return "DXGI_ERROR_DEVICE_REMOVED";
    case DXGI_ERROR_DEVICE_HUNG: return "DXGI_ERROR_DEVICE_HUNG";
    case DXGI_ERROR_DEVICE_RESET: return "DXGI_ERROR_DEVICE_RESET";
    case DXGI_ERROR_DRIVER_INTERNAL_ERROR: return "DXGI_ERROR_DRIVER_INTERNAL_ERROR";
    case DXGI_ERROR_INVALID_CALL: return "DXGI_ERROR_INVALID_CALL";
    case DXGI_ERROR_SDK_COMPONENT_MISSING: return "DXGI_ERROR_SDK_COMPONENT_MISSING";
    default: return fmt::format("HRESULT 0x{:08x}", static_cast<uint32_t>(hr));
  }
}

void check(HRESULT hr, const char* what) {
  if (FAILED(hr)) throw Error(fmt::format("d3d12: {} failed: {}", what, hresultName(hr)));
}

std::wstring toWide(const std::string& utf8) {
  if (utf8.empty()) return {};
  const int n = MultiByteToWideChar(CP_UTF8, 0, utf8.data(), int(utf8.size()), nullptr, 0);
  std::wstring out(size_t(n), L'\0');
  MultiByteToWideChar(CP_UTF8, 0, utf8.data(), int(utf8.size()), out.data(), n);
  return out;
}

std::string fromWide(const wchar_t* utf16) {
  if (!utf16 || !*utf16) return {};
  const int n = WideCharToMultiByte(CP_UTF8, 0, utf16, -1, nullptr, 0, nullptr, nullptr);
  std::string out(size_t(n), '\0');
  WideCharToMultiByte(CP_UTF8, 0, utf16, -1, out.data(), n, nullptr, nullptr);
  out.resize(size_t(n > 0 ? n - 1 : 0));  // drop the terminator WideCharToMultiByte counted
  return out;
}

void setName(ID3D12Object* object, const std::string& name) {
  if (object && !name.empty()) object->SetName(toWide(name).c_str());
}

namespace {
template <class T>
T symbol(HMODULE module, const char* name) {
  // GetProcAddress returns a generic FARPROC; the cast to the documented
  // signature goes through void* to keep -Wcast-function-type quiet.
  return reinterpret_cast<T>(reinterpret_cast<void*>(GetProcAddress(module, name)));
}
}  // namespace

const Library& library() {
  static std::once_flag once;
  static Library lib;
  static std::string failure;
  std::call_once(once, [] {
    HMODULE d3d12 = LoadLibraryA("d3d12.dll");
    HMODULE dxgi = LoadLibraryA("dxgi.dll");
    if (!d3d12 || !dxgi) {
      failure = "d3d12: d3d12.dll or dxgi.dll not found (D3D12 needs Windows 10 or later)";
      return;
    }
    lib.createDevice = symbol<PFN_D3D12_CREATE_DEVICE>(d3d12, "D3D12CreateDevice");
    lib.getDebugInterface = symbol<PFN_D3D12_GET_DEBUG_INTERFACE>(d3d12, "D3D12GetDebugInterface");
    lib.serializeVersionedRootSignature = symbol<PFN_D3D12_SERIALIZE_VERSIONED_ROOT_SIGNATURE>(
        d3d12, "D3D12SerializeVersionedRootSignature");
    lib.createDxgiFactory2 = symbol<decltype(lib.createDxgiFactory2)>(dxgi, "CreateDXGIFactory2");
    if (!lib.createDevice || !lib.serializeVersionedRootSignature || !lib.createDxgiFactory2)
      failure = "d3d12: this Windows lacks D3D12CreateDevice, D3D12SerializeVersionedRootSignature "
                "or CreateDXGIFactory2 (DXR needs Windows 10 1809 or later)";
  });
  if (!failure.empty()) throw Error(failure);
  return lib;
}

}  // namespace penumbra::d3d12
