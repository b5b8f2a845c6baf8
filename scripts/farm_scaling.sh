#!/usr/bin/env bash
# What splitting a render across Slurm tasks buys on this machine: starts the
# test suite's private one-node Slurm cluster (tests/farm/slurm_cluster.sh,
# as root), renders one image through `penumbra farm submit` with 1, 2 and 4
# shards, and prints the wall time from submission to the merged file, and
# whether each merged file equals the 1-shard one bit for bit.
# Usage: sudo bash scripts/farm_scaling.sh [build/apps/render/penumbra]
set -euo pipefail
cd "$(dirname "$0")/.."
penumbra=$(realpath "${1:-build/apps/render/penumbra}")
source tests/farm/slurm_cluster.sh
work=$(mktemp -d -t penumbra-farm-scaling.XXXXXX)
trap 'slurm_cluster_stop; rm -rf "$work"' EXIT
slurm_cluster_start "$work/cluster"
render=(--scene cornell-box --size 256x256 --seed 1 --spp 256)
echo "cluster: 1 node, $(nproc) CPUs; render: ${render[*]}; device: lavapipe"
for shards in 1 2 4; do
  start=$EPOCHREALTIME
  "$penumbra" farm submit "${render[@]}" --shards "$shards" --out "$work/k$shards.exr" >"$work/log"
  mapfile -t ids < <(sed -n 's/^\(shards\|merge\): job \([0-9]*\).*/\2/p' "$work/log")
  slurm_wait_jobs -t 1800 "${ids[@]}"
  seconds=$(awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { print b - a }')
  same=$(cmp -s "$work/k$shards.exr" "$work/k1.exr" && echo "bit-identical to 1 shard" || echo DIFFERENT)
  printf 'shards %d: %.1f s  %s\n' "$shards" "$seconds" "$same"
done
