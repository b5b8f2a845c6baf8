#pragma once
// Windows and D3D12 headers in the one order that works for MSVC and
// mingw-w64 alike, and the helpers every D3D12 file uses. DirectX-Headers
// (<directx/...>, <dxguids/...>) supply d3d12.h; DXGI comes from the Windows
// SDK / mingw-w64 runtime headers.
#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
#include <wrl/client.h>

#include <directx/d3d12.h>
#include <dxgi1_6.h>
#include <dxguids/dxguids.h>

#include <string>

namespace penumbra::d3d12 {

using Microsoft::WRL::ComPtr;

// Throws penumbra::Error "d3d12: <what> failed: <HRESULT name or hex>".
void check(HRESULT hr, const char* what);
std::string hresultName(HRESULT hr);
std::wstring toWide(const std::string& utf8);
std::string fromWide(const wchar_t* utf16);
// ID3D12Object::SetName, so PIX, Nsight and debug-layer messages show the
// RHI debug name.
void setName(ID3D12Object* object, const std::string& name);

}  // namespace penumbra::d3d12
