#!/usr/bin/env bash
# The device test cases (tests/CMakeLists.txt, PENUMBRA_DEVICE_TEST_SOURCES)
# on D3D12: the Windows build's penumbra_tests.exe under Wine with
# vkd3d-proton on lavapipe (scripts/wine-d3d12.sh), its test device made on
# D3D12 (PENUMBRA_TEST_BACKEND=d3d12) with the RHI validation layer and
# without the D3D12 debug layer, which vkd3d-proton does not have
# (PENUMBRA_TEST_API_VALIDATION=0). Each case is reported by name with its
# backend. Cases tagged [spirv-only] run shaders the tests build to SPIR-V
# alone (GLSL test shaders and compute harnesses): they are listed as not
# run on D3D12, by name.
#   d3d12_device_cases.sh PENUMBRA_TESTS_EXE SOURCE_DIR [SHARD/COUNT]
# SHARD/COUNT (e.g. 2/2) runs every COUNT-th case from the SHARD-th on, so
# ctest runs the shards side by side: one Wine process took 1557 s of a
# fresh clone's CI, the longest path of the suite. Round robin, not Catch2's
# --shard-index, whose contiguous blocks put the slow files together.
# Shard 1 lists the [spirv-only] cases.
# Without wine, vkd3d-proton or the executable: says why, exits 77 (Not Run).
set -u
exe="$1" source="$2" shard_spec="${3:-1/1}"
shard=${shard_spec%/*} shards=${shard_spec#*/}
case "$shard/$shards" in
  [1-9]/[1-9]) [ "$shard" -le "$shards" ] || { echo "FAIL: shard $shard_spec: the shard is past the count"; exit 1; } ;;
  *) echo "FAIL: shard '$shard_spec' is not SHARD/COUNT (1-9)"; exit 1 ;;
esac
work=$(mktemp -d)
xvfb_pid=""
cleanup() {
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
  [ -n "${KEEP:-}" ] || rm -rf "$work"
}
trap cleanup EXIT
not_run() { echo "NOT RUN (D3D12 device cases): $*"; exit 77; }
command -v wine >/dev/null 2>&1 || not_run "wine is not installed (scripts/setup.sh installs it)"
[ -f "$exe" ] || not_run "no Windows test executable at $exe (scripts/build.sh builds it)"

source "$(dirname "$0")/xvfb_display.sh"
export PENUMBRA_TEST_BACKEND=d3d12 PENUMBRA_TEST_API_VALIDATION=0
export PENUMBRA_TEST_DATA="$source/tests/data"
# A D3D12 device under Wine and vkd3d-proton takes lavapipe about 2 s to
# create: the device-lifetime case makes 50 here (the native run makes 200;
# the driver that once failed did so after about 30).
export PENUMBRA_TEST_LIFETIMES=50

wine_tests() { bash "$source/scripts/wine-d3d12.sh" "$exe" "$@"; }
wine_tests "~[spirv-only]" --list-tests --verbosity quiet >"$work/all.txt" 2>"$work/list.log"
grep -q "no vkd3d-proton" "$work/list.log" && not_run "$(grep -m1 'no vkd3d-proton' "$work/list.log")"
# This shard's names, one a line, with the characters Catch2's test specs
# treat as syntax escaped (commas, brackets, wildcards, quotes, backslashes).
tr -d '\r' <"$work/all.txt" | awk -v k="$shards" -v i="$shard" 'NF && (n++ % k) == i - 1' >"$work/names.txt"
[ -s "$work/names.txt" ] || { echo "FAIL: shard $shard_spec has no cases (listing: $(head -c 300 "$work/list.log"))"; exit 1; }
sed -e 's/\\/\\\\/g' -e 's/[],[*"]/\\&/g' "$work/names.txt" >"$work/spec.txt"
# Z: (Wine's drive for /): on Windows, Catch2 reads an argument that starts
# with / as an option.
wine_tests --input-file "Z:$work/spec.txt" --reporter "JUnit::out=$work/cases.xml" \
  --reporter "compact::out=$work/compact.log" >"$work/run.log" 2>&1
status=$?
# The engine's own shaders lack DXIL only in a build without DXC.
grep -q "has no DXIL for shader 'path_trace" "$work/compact.log" 2>/dev/null &&
  not_run "$exe was built without DXC (no DXIL)"
: >"$work/spirv.txt"
[ "$shard" = 1 ] && wine_tests "[spirv-only]" --list-tests --verbosity quiet 2>/dev/null | tr -d '\r' >"$work/spirv.txt"

python3 - "$work/cases.xml" "$work/spirv.txt" "$work/names.txt" "$shard_spec" <<'PY'
import sys, xml.etree.ElementTree as ET
cases = list(ET.parse(sys.argv[1]).getroot().iter("testcase"))
passed = failed = 0
# Every case of the shard ran once: a name Catch2 did not match is a failure.
wanted = [line.strip() for line in open(sys.argv[3]) if line.strip()]
ran = [case.get("name") for case in cases]
missing = sorted(set(wanted) - set(ran))
for name in missing:
    print(f"d3d12: {name}: FAILED (in shard {sys.argv[4]}, but not run)")
failed += len(missing)
for case in cases:
    name = case.get("name")
    bad = case.find("failure") if case.find("failure") is not None else case.find("error")
    print(f"d3d12: {name}: {'FAILED' if bad is not None else 'passed'} ({float(case.get('time', 0)):.1f} s)")
    if bad is not None:
        failed += 1
        print("   " + (bad.text or bad.get("message") or "").strip().replace("\n", "\n   "))
    else:
        passed += 1
skipped = [line.strip() for line in open(sys.argv[2]) if line.strip()]
for name in skipped:
    print(f"d3d12: {name}: NOT RUN (its shaders are SPIR-V only: GLSL test shaders or compute harness)")
# This test is the longest of the suite: where its time goes.
slowest = sorted(cases, key=lambda c: -float(c.get("time", 0)))[:10]
print("slowest: " + "; ".join(f"{float(c.get('time', 0)):.0f} s {c.get('name')}" for c in slowest))
print(f"D3D12 device cases, shard {sys.argv[4]}: {passed} passed, {failed} failed"
      + (f", {len(skipped)} not run on D3D12 ([spirv-only])" if skipped else ""))
sys.exit(1 if failed else 0)
PY
report=$?
if [ $status -ne 0 ] || [ $report -ne 0 ]; then
  tail -40 "$work/compact.log"
  echo "FAIL: penumbra_tests.exe on D3D12, shard $shard_spec: exit status $status, $report from the report"
  exit 1
fi
