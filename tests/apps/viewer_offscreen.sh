#!/usr/bin/env bash
# The viewer's offscreen mode (no window, no display) on lavapipe with the
# validation layer:
# 1. a script's screenshot equals `penumbra render --settings` of its record
#    (the same frames, so bit-identical: compare allows 1e-6 relative, which
#    only float reassociation could need);
# 2. with the menus off, its capture (what the window would show) equals the
#    capture of the same script in a real window under Xvfb, byte for byte
#    (the same display texture read back either way), and equals the
#    screenshot's tone-mapped PNG to 45 dB PSNR (one 8-bit rounding step apart
#    at most; measured identical);
# 3. with the menus on, the capture shows them: more than 5 % of its pixels
#    differ from the menu-less capture (the "Penumbra" and stats windows cover
#    about a third of 320x240; a UI pass that draws nothing changes none);
# 4. the denoiser runs offscreen (its GPU time is reported), --record writes
#    one PNG per frame, and the run ends with every pass's GPU time;
# 5. bad use fails with one line: --offscreen without --script, a capture
#    that is not a PNG.
set -eu
viewer="$1"
penumbra="$2"
for tool in xvfb-run pngtopnm pnmpsnr; do
  command -v "$tool" >/dev/null 2>&1 || { echo "viewer test: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "viewer offscreen test: $*" >&2; exit 1; }

# The part both runs share: menus off, a fixed render scale, 16 samples.
cat > "$work/common.script" <<SCRIPT
set ui off
set spp-per-frame 4
set seed 5
set max-samples 16
move 0.03 0 0.05
wait-frames 2
wait-samples 16
wait-frames 2
SCRIPT
{ cat "$work/common.script"; cat <<SCRIPT
screenshot $work/off/shot.exr
screenshot $work/off/shot.png
capture $work/off/shown.png
set ui on
wait-frames 3
capture $work/off/menus.png
set max-samples 0
set denoise svgf
move 0.02 0 0
wait-frames 4
capture $work/off/denoised.png
quit
SCRIPT
} > "$work/offscreen.script"
{ cat "$work/common.script"; echo "capture $work/win/shown.png"; echo quit; } > "$work/window.script"
mkdir -p "$work/off" "$work/win"

env -u DISPLAY -u WAYLAND_DISPLAY "$viewer" --offscreen --scene cornell-box --size 320x240 \
  --render-scale 1 --validation --config "$work/viewer.json" --script "$work/offscreen.script" \
  --record "$work/frames" | tee "$work/off.log"
grep -q "^device: .* offscreen 320x240$" "$work/off.log" || fail "no offscreen device line"
grep -q "^screenshot: $work/off/shot.exr (320x240, 16 spp)" "$work/off.log" || fail "no screenshot"
for f in shown menus denoised; do
  grep -q "^capture: $work/off/$f.png (320x240)$" "$work/off.log" || fail "no capture $f"
done
# Every pass timed on the GPU: path tracing, the denoiser (on in the last
# frames), the display pass, the UI (on from the menus capture on).
n='[1-9][0-9]*'
grep -Eq "^timings: [0-9]+ frames; path tracing [0-9.]+ ms/frame \(median of $n\); denoiser [0-9.]+ ms/frame \(median of $n\); display [0-9.]+ ms/frame \(median of $n\); UI [0-9.]+ ms/frame \(median of $n\)$" \
  "$work/off.log" || fail "no per-pass timings"
frames=$(sed -nE 's/^timings: ([0-9]+) frames.*/\1/p' "$work/off.log")
recorded=$(ls "$work/frames" | grep -c '^frame-[0-9]\{6\}\.png$')
[ "$recorded" -eq "$frames" ] || fail "--record wrote $recorded frames of $frames"

xvfb-run -a -s "-screen 0 640x480x24" "$viewer" --scene cornell-box --size 320x240 \
  --render-scale 1 --config "$work/viewer.json" --script "$work/window.script" | tee "$work/win.log"
grep -q "^device: .* X11 window$" "$work/win.log" || fail "no window device line"
cmp "$work/off/shown.png" "$work/win/shown.png" || fail "the offscreen capture differs from the window's"

"$penumbra" render --settings "$work/off/shot.json" --out "$work/render.exr" > /dev/null
"$penumbra" compare "$work/off/shot.exr" "$work/render.exr" --tolerance 1e-6 ||
  fail "the offscreen screenshot differs from penumbra render --settings"

pngtopnm "$work/off/shown.png" > "$work/shown.ppm"
pngtopnm "$work/off/shot.png" > "$work/shot.ppm"
pngtopnm "$work/off/menus.png" > "$work/menus.ppm"
psnr=$(pnmpsnr -rgb -machine "$work/shown.ppm" "$work/shot.ppm")
echo "capture vs screenshot PSNR (R G B, dB): $psnr"
for value in $psnr; do
  [ "$value" = "inf" ] && continue
  awk -v v="$value" 'BEGIN { exit !(v >= 45) }' || fail "the capture does not show the image"
done
changed=$(python3 "$(dirname "$0")/changed_pixels.py" "$work/shown.ppm" "$work/menus.ppm")
echo "pixels the menus change: $changed"
awk -v v="$changed" 'BEGIN { exit !(v > 0.05) }' || fail "the capture does not show the menus"

# Bad use: one line each, non-zero exit, nothing written.
set +e
env -u DISPLAY "$viewer" --offscreen --scene cornell-box 2> "$work/err1"
status=$?
set -e
[ "$status" -ne 0 ] && [ "$(wc -l < "$work/err1")" -eq 1 ] &&
  grep -q "^error: --offscreen needs --script" "$work/err1" || fail "--offscreen without --script"
printf 'capture %s\nquit\n' "$work/bad.exr" > "$work/bad.script"
set +e
env -u DISPLAY "$viewer" --offscreen --size 64x48 --scene cornell-box --script "$work/bad.script" \
  > /dev/null 2> "$work/err2"
status=$?
set -e
cat "$work/err2"
[ "$status" -ne 0 ] && [ "$(wc -l < "$work/err2")" -eq 1 ] &&
  grep -q "capture $work/bad.exr: a capture is a .png" "$work/err2" || fail "a capture to .exr"
[ ! -e "$work/bad.exr" ] || fail "a refused capture left a file"
echo "viewer offscreen ok"
