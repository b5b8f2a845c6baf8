#!/usr/bin/env bash
# Runs the libFuzzer targets for longer than CI does, after scripts/sanitize.sh
# built them:  scripts/fuzz.sh [SECONDS per target, default 600] [TARGET...]
# (targets: gltf scene settings image). A finding is left in a scratch folder
# that run_fuzzer.sh names; minimise it (fuzz_X -minimize_crash=1 FILE), fix
# the cause, and commit it under tests/fuzz/corpus/X/finding-* with a
# regression test in the normal suite.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(gltf scene settings image)
for t in "${targets[@]}"; do
  echo "== fuzz_$t, $seconds s"
  bash tests/fuzz/run_fuzzer.sh "build-sanitize/tests/fuzz/fuzz_$t" "tests/fuzz/corpus/$t" \
    tests/fuzz/json.dict "$seconds"
done
