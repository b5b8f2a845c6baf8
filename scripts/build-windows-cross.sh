#!/usr/bin/env bash
# Cross-compiles Penumbra for Windows x64 with mingw-w64 into ./build-mingw:
# the engine, both backends (Vulkan and D3D12/DXR) and penumbra.exe. The
# D3D12 backend always builds with warnings as errors, so CI (scripts/build.sh
# runs this after the native build) keeps it compiling and linking.
#
# Needs the native build first: shader reflection runs at build time through
# build/tools/shader_layout/penumbra_shader_layout, which a cross build cannot
# build for itself.
set -euo pipefail
cd "$(dirname "$0")/.."
host_tools="$PWD/${1:-build}/tools/shader_layout"
if [ ! -x "$host_tools/penumbra_shader_layout" ]; then
  echo "build-windows-cross.sh: $host_tools/penumbra_shader_layout is missing; run scripts/build.sh first" >&2
  exit 1
fi
werror=OFF
if [ "${CI:-}" = "true" ]; then werror=ON; fi
cmake -S . -B build-mingw -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/mingw-w64-x86_64.cmake \
  -DPENUMBRA_HOST_TOOLS_DIR="$host_tools" -DPENUMBRA_BUILD_TESTS=OFF \
  -DPENUMBRA_WARNINGS_AS_ERRORS=$werror
cmake --build build-mingw --parallel "$(nproc)"
echo "build-windows-cross.sh: built build-mingw/apps/render/penumbra.exe"
