#!/usr/bin/env bash
# Cross-compiles Penumbra for Windows x64 with mingw-w64 into ./build-mingw:
# the engine, both backends (Vulkan and D3D12/DXR), penumbra.exe and
# penumbra-viewer.exe (GLFW and Dear ImGui from the source packages
# scripts/setup.sh unpacks, see cmake/CrossDependencies.cmake). The
# D3D12 backend always builds with warnings as errors, so CI (scripts/build.sh
# runs this after the native build) keeps it compiling and linking.
#
# Needs the native build first: shader reflection runs at build time through
# build/tools/shader_layout/penumbra_shader_layout, which a cross build cannot
# build for itself. The settings are CMakePresets.json's "mingw" ("mingw-ci"
# under CI: warnings as errors); the native build's directory is the first
# argument (default build).
set -euo pipefail
cd "$(dirname "$0")/.."
host_tools="$PWD/${1:-build}/tools/shader_layout"
if [ ! -x "$host_tools/penumbra_shader_layout" ]; then
  echo "build-windows-cross.sh: $host_tools/penumbra_shader_layout is missing; run scripts/build.sh first" >&2
  exit 1
fi
preset=mingw
if [ "${CI:-}" = "true" ]; then preset=mingw-ci; fi
cmake --preset "$preset" -DPENUMBRA_HOST_TOOLS_DIR="$host_tools"
cmake --build --preset "$preset" --parallel "$(nproc)"

# The results must be 64-bit Windows executables that need nothing but
# system DLLs (d3d12.dll, dxgi.dll and vulkan-1.dll are opened at run time).
# The viewer's GLFW adds gdi32.dll (and shell32.dll, for drag and drop).
for exe in build-mingw/apps/render/penumbra.exe build-mingw/apps/viewer/penumbra-viewer.exe; do
  x86_64-w64-mingw32-objdump -f "$exe" | grep -q "file format pei-x86-64" ||
    { echo "build-windows-cross.sh: $exe is not a PE32+ x86-64 executable" >&2; exit 1; }
  imports=$(x86_64-w64-mingw32-objdump -p "$exe" | awk '/DLL Name:/ {print $3}' | sort -u | tr '\n' ' ')
  for dll in $imports; do
    case "${dll,,}" in
      kernel32.dll|msvcrt.dll|user32.dll|gdi32.dll|advapi32.dll|shell32.dll|ole32.dll|ws2_32.dll) ;;
      *) echo "build-windows-cross.sh: $exe imports $dll, which Windows does not ship" >&2; exit 1 ;;
    esac
  done
  echo "build-windows-cross.sh: built $exe (imports: $imports)"
done
