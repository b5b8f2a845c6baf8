#!/usr/bin/env bash
# The viewer end to end under a virtual X server (Xvfb) on lavapipe, with the
# validation layer: a scripted session moves the camera, changes settings,
# waits for 16 samples and saves a screenshot with its settings record, then
# edits two materials as the Material menu does and saves another;
# `penumbra render --settings` must reproduce that screenshot, edits included.
#
# Tolerance: both run the same frames (4 spp each, same sample indices, same
# seed) on the same device, so the images are expected bit-identical; measured
# on lavapipe: max |difference| 0. The compare allows 1e-6 relative per
# channel and no pixel beyond it, which only floating-point reassociation
# could need.
set -eu
viewer="$1"
penumbra="$2"
if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "viewer test: xvfb-run not found; scripts/setup.sh installs xvfb" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/session.script" <<SCRIPT
set spp-per-frame 4
set seed 3
set max-depth 6
move 0.05 0.02 0.1      # right, up, forward (metres)
turn 4 -2               # degrees right, up
wait-frames 2
wait-samples 16
screenshot $work/unedited.exr
material white baseColor 0.9 0.5 0.2
material green metallic 0.6
wait-frames 2
wait-samples 16
screenshot $work/shot.exr
set tonemap aces
screenshot $work/shot.png
set render-scale 0.5
window-size 120 80
wait-frames 3
wait-samples 4
screenshot $work/resized.exr
set denoise svgf        # the temporal denoiser while the camera moves
move 0.02 0 0
wait-frames 3
set view normal         # the guide buffers, and the denoiser's motion vectors
wait-frames 1
set view depth
wait-frames 1
set view motion
wait-frames 1
set view image
set denoise atrous      # the single-frame filter on the accumulation
wait-frames 2
set denoise off
environment map default # the Environment menu's edits, recorded with the screenshot
environment rotation 40
environment intensity 0.5
environment background hidden
wait-frames 2
wait-samples 16
screenshot $work/env.exr
quit
SCRIPT
xvfb-run -a -s "-screen 0 640x480x24" "$viewer" --scene cornell-box --size 96x64 --render-scale 1 \
  --validation --config "$work/viewer.json" --script "$work/session.script" | tee "$work/log"
grep -q "^device: .* X11 window$" "$work/log"
grep -q "^screenshot: $work/shot.exr (96x64, 16 spp)" "$work/log"
[ -s "$work/shot.exr" ] && [ -s "$work/shot.png" ]
# Half the render scale of a 120x80 window (swapchain and image resized).
grep -q "^screenshot: $work/resized.exr (60x40, [0-9]* spp)" "$work/log"
grep -q '"spp": 16' "$work/shot.json"
grep -q '"sppPerFrame": 4' "$work/shot.json"
grep -q '"maxDepth": 6' "$work/shot.json"
grep -q '"toneMapping": "aces"' "$work/shot.json"
# The edits are in the record, and only in the edited one.
grep -q '"materials"' "$work/shot.json"
grep -q '"name": "white"' "$work/shot.json"
grep -q '"name": "green"' "$work/shot.json"
grep -q '"metallic": 0.6' "$work/shot.json"
if grep -q '"materials"' "$work/unedited.json"; then
  echo "viewer test: a record without material edits lists materials" >&2
  exit 1
fi

"$penumbra" render --settings "$work/shot.json" --validation --out "$work/headless.exr" | tee "$work/render.log"
grep -q "96x64, 16 spp, seed 3" "$work/render.log"
"$penumbra" compare "$work/shot.exr" "$work/headless.exr" --tolerance 1e-6 | tee "$work/compare"
grep -q "^within tolerance$" "$work/compare"
# The camera moved: the screenshot is not the scene camera's view.
"$penumbra" render --scene cornell-box --size 96x64 --spp 16 --spp-per-frame 4 --seed 3 --max-depth 6 \
  --out "$work/unmoved.exr" >/dev/null
if "$penumbra" compare "$work/shot.exr" "$work/unmoved.exr" --tolerance 1e-6 >/dev/null; then
  echo "viewer test: the scripted camera move did not change the image" >&2
  exit 1
fi
# The edits changed the image: reproducing shot.exr needs them applied.
if "$penumbra" compare "$work/shot.exr" "$work/unedited.exr" --tolerance 1e-6 >/dev/null; then
  echo "viewer test: the scripted material edits did not change the image" >&2
  exit 1
fi
# The environment edits: recorded, reproduced, and visible in the image.
grep -q '"map": "default"' "$work/env.json"
grep -q '"rotation": 40' "$work/env.json"
grep -q '"intensity": 0.5' "$work/env.json"
grep -q '"background": false' "$work/env.json"
"$penumbra" render --settings "$work/env.json" --validation --out "$work/env-headless.exr" >/dev/null
"$penumbra" compare "$work/env.exr" "$work/env-headless.exr" --tolerance 1e-6 | tee "$work/compare"
grep -q "^within tolerance$" "$work/compare"
"$penumbra" render --settings "$work/env.json" --env none --out "$work/env-none.exr" >/dev/null
if "$penumbra" compare "$work/env.exr" "$work/env-none.exr" --tolerance 1e-6 >/dev/null; then
  echo "viewer test: the environment did not change the image" >&2
  exit 1
fi
echo "viewer screenshot ok"
