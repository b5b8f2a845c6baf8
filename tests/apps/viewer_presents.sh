#!/usr/bin/env bash
# What the viewer shows on screen is the tone-mapped image: with the menus
# hidden and the accumulation stopped at 16 samples, the X server's copy of
# the window (xwd) must equal the PNG screenshot of the same image. This
# covers the display pass, the copy (a channel-swapping blit into the BGRA
# back buffer on X11) and presentation.
#
# Tolerance: 45 dB PSNR per channel, i.e. an RMS difference under 1.5 of 255.
# The display pass (unorm store) and the PNG path (x * 255 + 0.5) may round a
# value one step apart; measured on lavapipe: identical (PSNR inf). A broken
# pass (black, red/blue swapped, wrong scale) measures below 20 dB.
set -eu
viewer="$1"
for tool in xvfb-run xwd xwdtopnm pngtopnm pnmpsnr; do
  command -v "$tool" >/dev/null 2>&1 || { echo "viewer test: $tool not found (scripts/setup.sh installs it)" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/show.script" <<SCRIPT
set ui off
set max-samples 16
set spp-per-frame 4
wait-samples 16
wait-frames 4          # the last frames display the finished image
screenshot $work/shot.png
wait-frames 100000000  # the test ends the viewer once it has the window
SCRIPT
cat > "$work/session.sh" <<SESSION
set -eu
"$viewer" --scene cornell-box --size 96x64 --render-scale 1 --config "$work/viewer.json" \
  --script "$work/show.script" > "$work/log" 2>&1 &
pid=\$!
for i in \$(seq 1 600); do [ -s "$work/shot.json" ] && break; sleep 0.2; done
sleep 1
xwd -silent -name "Penumbra viewer" > "$work/window.xwd"
kill \$pid
SESSION
xvfb-run -a -s "-screen 0 640x480x24" bash "$work/session.sh"
cat "$work/log"
[ -s "$work/shot.png" ] || { echo "viewer test: no screenshot" >&2; exit 1; }
xwdtopnm "$work/window.xwd" > "$work/window.ppm" 2>/dev/null
pngtopnm "$work/shot.png" > "$work/shot.ppm"
psnr=$(pnmpsnr -rgb -machine "$work/window.ppm" "$work/shot.ppm")
echo "window vs screenshot PSNR (R G B, dB): $psnr"
for value in $psnr; do
  [ "$value" = "inf" ] && continue
  awk -v v="$value" 'BEGIN { exit !(v >= 45) }' || { echo "viewer test: the window does not show the image" >&2; exit 1; }
done
echo "viewer presents ok"
