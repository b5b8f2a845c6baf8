#!/usr/bin/env bash
# Configures and builds Penumbra into ./build (Release), then cross-compiles
# the Windows build (both backends, D3D12 included) into ./build-mingw with
# scripts/build-windows-cross.sh, so CI keeps the D3D12 backend compiling.
# Under CI (CI=true) warnings are errors; backends/d3d12 always treats them so.
# PENUMBRA_SKIP_WINDOWS=1 skips the cross build (local iteration only).
# `build.sh --render` builds only the renderer, `build/apps/render/penumbra`
# (README's first command: no viewer, tests or cross build; what
# `setup.sh --render` installs is enough for it).
# The settings are CMakePresets.json's: "release", or "ci" under CI (the same
# build/ with warnings as errors).
set -euo pipefail
cd "$(dirname "$0")/.."
preset=release
if [ "${CI:-}" = "true" ]; then preset=ci; fi
case "${1:-}" in
  --render)
    cmake --preset "$preset" -DPENUMBRA_BUILD_TESTS=OFF -DPENUMBRA_BUILD_VIEWER=OFF
    cmake --build --preset "$preset" --parallel "$(nproc)" --target penumbra
    exit 0 ;;
  "") ;;
  *) echo "build.sh: unknown option '$1' (--render: only the renderer)" >&2; exit 2 ;;
esac
cmake --preset "$preset" -DPENUMBRA_BUILD_TESTS=ON -DPENUMBRA_BUILD_VIEWER=ON
cmake --build --preset "$preset" --parallel "$(nproc)"
echo "build.sh: build/ in $SECONDS s"
if [ "${PENUMBRA_SKIP_WINDOWS:-}" != "1" ]; then
  begun=$SECONDS
  bash scripts/build-windows-cross.sh build
  echo "build.sh: build-mingw/ in $((SECONDS - begun)) s"
fi
