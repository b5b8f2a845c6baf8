#!/usr/bin/env bash
# The merge's memory: renders a 1920x1080 Cornell box as PIECES pieces of
# one sample each (one GPU frame of 1 sample per piece), merges them with
# each penumbra binary given, and prints each merge's peak resident memory
# and wall time (/usr/bin/time) and whether their outputs agree byte for
# byte. The first binary renders the pieces.
# Usage: bash scripts/merge_memory.sh PIECES path/to/penumbra [other/penumbra...]
set -euo pipefail
pieces="$1"
shift
binaries=()
for b in "$@"; do binaries+=("$(realpath "$b")"); done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for ((i = 0; i < pieces; i++)); do
  "${binaries[0]}" render --scene cornell-box --size 1920x1080 --seed 3 --spp-per-frame 1 \
    --total-spp "$pieces" --samples "$i:$((i + 1))" --out "piece-$(printf %04d "$i").exr" \
    >/dev/null 2>&1
done
echo "$pieces pieces of 1920x1080, $(du -sh . | cut -f1) on disk"
n=0
for b in "${binaries[@]}"; do
  /usr/bin/time -f "$b: merge peak RSS %M KB, %e s wall" "$b" merge piece-*.exr \
    --out "merged-$n.exr" 2>&1 >/dev/null | grep "peak RSS"
  n=$((n + 1))
done
for ((k = 1; k < n; k++)); do
  if cmp -s merged-0.exr "merged-$k.exr"; then
    echo "merge $k = merge 0, byte for byte"
  else
    echo "merge $k DIFFERS from merge 0"
  fi
done
