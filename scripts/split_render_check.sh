#!/usr/bin/env bash
# Split renders on one device, at 1080p: for the Cornell box and the
# material test, a plain `render --spp 256`, the same 256 samples as one
# piece and as five uneven pieces merged in reverse order; prints the GPU and
# wall times, whether the merged file equals the one-piece render byte for
# byte, and how the plain running-mean render compares with it.
# Usage: bash scripts/split_render_check.sh [path/to/penumbra]
set -euo pipefail
penumbra=$(realpath "${1:-build/apps/render/penumbra}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for scene in cornell-box material-test; do
  common=(--scene "$scene" --size 1920x1080 --seed 7)
  /usr/bin/time -f "plain render --spp 256: %e s wall" "$penumbra" render "${common[@]}" \
    --spp 256 --out plain.exr 2>&1 | grep -E "^device:|GPU time|wall"
  /usr/bin/time -f "one piece 0:256: %e s wall" "$penumbra" render "${common[@]}" \
    --total-spp 256 --samples 0:256 --out whole.exr 2>&1 | grep -E "GPU time|wall"
  "$penumbra" merge whole.exr --out single.exr >/dev/null
  for range in 0:48 48:112 112:160 160:176 176:256; do
    "$penumbra" render "${common[@]}" --total-spp 256 --samples "$range" \
      --out "piece-${range/:/-}.exr" >/dev/null 2>&1
  done
  mapfile -t pieces < <(ls piece-*.exr | sort -r)
  /usr/bin/time -f "merge of 5 pieces: %e s wall" "$penumbra" merge "${pieces[@]}" \
    --out merged.exr 2>&1 | grep -E "wall"
  if cmp -s merged.exr single.exr; then
    echo "$scene: 5 pieces merged = the one-piece render, byte for byte"
  else
    echo "$scene: 5 pieces merged DIFFER from the one-piece render"
  fi
  "$penumbra" compare plain.exr single.exr --tolerance 1e-5 |
    grep -E "max absolute|PSNR|relative MSE|within"
done
