#!/usr/bin/env bash
# The real-time figures docs/results.md reports, side by side in one run on
# one device: the rtsmoke probe (../shared/tools/rtsmoke, the bare tracer's
# ray rate) and each given penumbra build on the showcase scenes at the
# real-time settings (default MIS, max depth 8, 16 spp in one frame), then
# the denoiser's cost and the combined frame. GPU timestamps throughout.
#   scripts/realtime_bench.sh RTSMOKE SIZE PENUMBRA [PENUMBRA...]
# e.g. on the GPU machine: scripts/realtime_bench.sh .carry/rtsmoke-static-ish 1920x1080 .carry/penumbra
set -euo pipefail
rtsmoke="$1" size="$2"
shift 2
probe() {
  "$rtsmoke" --scene cornell --size "$size" --spp 16 --depth 8 --frames 6 --out '' | grep '^RESULT'
}
probe
for penumbra in "$@"; do
  echo "== $penumbra"
  for scene in cornell-box material-test implicit-surfaces performance; do
    "$penumbra" render --scene "$scene" --size "$size" --spp 32 --spp-per-frame 16 --seed 1 --out /tmp/realtime.exr |
      sed -nE "s/^GPU time: ([0-9.]+) ms total, ([0-9.]+) ms per sample.*/$scene: \2 ms per spp/p; s/^rays: ([0-9]+) \(([0-9.]+) Mrays\/s\)/$scene: \1 rays, \2 Mrays\/s/p"
  done
  "$penumbra" bench --scene cornell-box --size "$size" --frames 8 --spp-per-frame 16 --denoise svgf |
    grep -E "^(specialized|denoiser|path tracing|frame-to-frame)"
done
probe
