#!/usr/bin/env bash
# The sanitizer build: every target of the suite under AddressSanitizer and
# UndefinedBehaviorSanitizer (clang, any report fatal, leaks included) into
# ./build-sanitize (CMakePresets.json "sanitize"), then its ctest: the
# host-side test cases, the GPU cases on lavapipe in one process, and each
# libFuzzer target for a fixed number of executions (at most
# PENUMBRA_FUZZ_SECONDS, 300) from its committed corpus (tests/fuzz).
# README's test command runs it after the main suite; docs/security.md says
# what it covers and costs.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset sanitize -DPENUMBRA_FUZZ_SECONDS="${PENUMBRA_FUZZ_SECONDS:-300}"
cmake --build --preset sanitize --parallel "$(nproc)" --target penumbra_tests fuzz_gltf fuzz_scene \
  fuzz_settings fuzz_image
echo "sanitize.sh: build-sanitize/ in $SECONDS s"
# Third-party libraries loaded at run time keep allocations LeakSanitizer
# would report (tests/fuzz/lsan.supp says which and why).
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp"
ctest --test-dir build-sanitize -L sanitize --output-on-failure -j"$(nproc)"
