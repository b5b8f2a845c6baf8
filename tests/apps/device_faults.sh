#!/usr/bin/env bash
# Device failures, injected (rhi/fault_injection.h): the CLI and the viewer
# end a render whose device runs out of memory or is lost with one clear
# line and a non-zero exit -- no crash, no core, no output file left behind.
#   device_faults.sh PENUMBRA PENUMBRA_VIEWER
set -u
penumbra="$1" viewer="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
fail() { echo "device faults: $*" >&2; status=1; }

# expect_failure NAME PATTERN FILE COMMAND...: exit 1 (not a signal's 128+),
# exactly one line on stderr matching PATTERN, FILE not written.
expect_failure() {
  local name="$1" pattern="$2" file="$3"
  shift 3
  "$@" >"$work/out" 2>"$work/err"
  local code=$?
  [ "$code" -eq 1 ] || fail "$name: exit status $code, expected 1 ($(head -c 300 "$work/err"))"
  [ "$(wc -l <"$work/err")" -eq 1 ] || fail "$name: stderr has $(wc -l <"$work/err") lines: $(cat "$work/err")"
  grep -qE "$pattern" "$work/err" || fail "$name: stderr does not say '$pattern': $(cat "$work/err")"
  [ ! -e "$file" ] || fail "$name: $file was written"
}

render=("$penumbra" render --size 32x24 --spp 2 --validation)
# The first submit uploads the scene; the third records a frame.
PENUMBRA_INJECT_FAULT=submit:3 expect_failure "render, device lost" \
  "^error: vulkan: the device .* was lost submitting command list '.*' \(VK_ERROR_DEVICE_LOST\)" \
  "$work/lost.png" "${render[@]}" --out "$work/lost.png"
PENUMBRA_INJECT_FAULT=allocation:4 expect_failure "render, out of memory" \
  "^error: vulkan: out of device memory allocating [0-9.]+ MiB for (buffer|texture) '.+' on .*VK_ERROR_OUT_OF_DEVICE_MEMORY" \
  "$work/oom.exr" "${render[@]}" --out "$work/oom.exr"
PENUMBRA_INJECT_FAULT=everything expect_failure "a misspelt fault" \
  "PENUMBRA_INJECT_FAULT='everything': expected allocation:N or submit:N" \
  "$work/bogus.png" "${render[@]}" --out "$work/bogus.png"
# Without a fault the same command works (the faults above were the cause).
"${render[@]}" --out "$work/fine.png" >/dev/null 2>&1 || fail "the render without a fault failed"
[ -s "$work/fine.png" ] || fail "the render without a fault wrote nothing"

# The viewer, offscreen: the device is lost a few frames in.
cat > "$work/lost.script" <<SCRIPT
wait-frames 2
inject-fault submit 2
wait-frames 3
capture $work/viewer-lost.png
quit
SCRIPT
expect_failure "viewer, device lost" "was lost submitting command list 'viewer frame [0-9]'" \
  "$work/viewer-lost.png" "$viewer" --offscreen --size 64x48 --validation --config "$work/v.json" \
  --script "$work/lost.script"
# A scene the device has no memory for: the script stops there, naming its line.
cat > "$work/oom.script" <<SCRIPT
wait-frames 1
inject-fault allocation 1
scene material-test
capture $work/viewer-oom.png
quit
SCRIPT
expect_failure "viewer, scene too large" "oom.script:3: vulkan: out of device memory allocating" \
  "$work/viewer-oom.png" "$viewer" --offscreen --size 64x48 --validation --config "$work/v.json" \
  --script "$work/oom.script"
[ "$status" -eq 0 ] && echo "device faults: every injected failure ended in one clear line"
exit "$status"
