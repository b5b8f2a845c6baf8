#!/usr/bin/env bash
# Every built-in scene through the real viewer loop, offscreen (no display
# needed: a GPU server), with the validation layer: the temporal denoiser
# while the camera moves, then the a-trous filter on the accumulation once
# still, the menus on. For each scene it writes two captures (what the window
# would show) and a screenshot, renders the screenshot's record again with
# `penumbra render --settings`, and compares the two (same device, same
# frames: bit-identical expected). The viewer's timings line gives the median
# GPU times of path tracing and of the denoiser per frame.
#   scripts/viewer_offscreen_check.sh VIEWER PENUMBRA SIZE OUTDIR [SPP_PER_FRAME]
# e.g. on the GPU machine:
#   scripts/viewer_offscreen_check.sh .carry/penumbra-viewer .carry/penumbra 1920x1080 /tmp/viewer 4
set -euo pipefail
viewer="$1" penumbra="$2" size="$3" out="$4" spp="${5:-4}"
mkdir -p "$out"
status=0
for scene in cornell-box material-test implicit-surfaces performance cornell-box-whitted; do
  cat > "$out/$scene.script" <<SCRIPT
set spp-per-frame $spp
set seed 2
set denoise svgf
move 0.02 0 0.02
wait-frames 4
move 0.02 0 0.02
wait-frames 4
capture $out/$scene-moving.png
set denoise atrous
wait-samples $((spp * 8))
wait-frames 2
screenshot $out/$scene.exr
capture $out/$scene-still.png
quit
SCRIPT
  echo "== $scene"
  if ! "$viewer" --offscreen --size "$size" --render-scale 1 --validation --scene "$scene" \
    --config "$out/viewer.json" --script "$out/$scene.script"; then
    echo "$scene: the viewer failed"
    status=1
    continue
  fi
  "$penumbra" render --settings "$out/$scene.json" --out "$out/$scene-render.exr" > /dev/null
  if ! "$penumbra" compare "$out/$scene.exr" "$out/$scene-render.exr" --tolerance 1e-6 |
    grep -E "^(max absolute difference|pixels beyond|within|relative MSE)"; then
    echo "$scene: the screenshot differs from penumbra render --settings"
    status=1
  fi
done
exit $status
