#!/usr/bin/env bash
# Configures and builds Penumbra into ./build (Release). Under CI (CI=true)
# warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
werror=OFF
if [ "${CI:-}" = "true" ]; then werror=ON; fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPENUMBRA_WARNINGS_AS_ERRORS=$werror
cmake --build build --parallel "$(nproc)"
