#!/usr/bin/env bash
# What the environment, the lights and the lens cost on the GPU
# (docs/results.md, "Light and camera"): each row renders one scene at
# 1920x1080, 16 spp, seed 1, three times interleaved with the other rows,
# and prints the median GPU time (ms) of the three.
#   scripts/feature_costs.sh NEW_PENUMBRA [OLD_PENUMBRA] [RTSMOKE]
# OLD_PENUMBRA (a build from before the features) adds the rows that check
# that a scene without them costs what it cost; RTSMOKE adds the probe's
# ray rate on the Cornell box beside Penumbra's, in the same run.
set -euo pipefail
new="$1"
old="${2:-}"
rtsmoke="${3:-}"
here="$(cd "$(dirname "$0")/.." && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
size="${PENUMBRA_COST_SIZE:-1920x1080}"  # smaller only to try the script out
glass="$here/tests/data/scenes/sunlit-glass.json"
sed 's/"angularRadiusDegrees": 2/"angularRadiusDegrees": 0/' "$glass" >"$work/delta-sun.json"
sed 's/"type": "spot"/"type": "point"/' "$glass" >"$work/point-not-spot.json"
sed 's/"attenuationColor": \[0.9, 0.5, 0.2\]/"attenuationColor": [1, 1, 1]/' "$glass" >"$work/clear-glass.json"

rows=(
  "cornell-box|$new|--scene cornell-box"
  "material-test|$new|--scene material-test"
  "cornell-box + default environment|$new|--scene cornell-box --env default"
  "material-test + default environment|$new|--scene material-test --env default"
  "cornell-box + thin lens|$new|--scene cornell-box --aperture 0.01 --focus-distance 0.8"
  "cornell-box + thin lens, 6 blades|$new|--scene cornell-box --aperture 0.01 --focus-distance 0.8 --aperture-blades 6"
  "sunlit-glass (soft sun, spot, absorbing glass)|$new|--scene $glass"
  "sunlit-glass, delta sun|$new|--scene $work/delta-sun.json"
  "sunlit-glass, point light for the spot|$new|--scene $work/point-not-spot.json"
  "sunlit-glass, clear glass|$new|--scene $work/clear-glass.json"
  "sunlit-glass + default environment|$new|--scene $glass --env default"
)
if [ -n "$old" ]; then
  rows+=("cornell-box, build before|$old|--scene cornell-box"
         "material-test, build before|$old|--scene material-test")
fi
declare -A times rays
for run in 1 2 3; do
  for row in "${rows[@]}"; do
    IFS='|' read -r name binary args <<<"$row"
    # shellcheck disable=SC2086
    out=$("$binary" render $args --size "$size" --spp 16 --seed 1 --out "$work/frame.exr" 2>/dev/null)
    ms=$(grep '^GPU time' <<<"$out" | sed 's/GPU time: \([0-9.]*\) ms.*/\1/')
    times[$name]="${times[$name]:-} $ms"
    rays[$name]=$(grep '^rays:' <<<"$out" | sed 's/.*(\([0-9.]*\) Mrays\/s)/\1/')
  done
done
median() { tr ' ' '\n' <<<"$1" | grep . | sort -g | sed -n 2p; }
echo "| scene | GPU ms, $size 16 spp (runs) | median | Mrays/s |"
echo "|---|---|---|---|"
for row in "${rows[@]}"; do
  IFS='|' read -r name _ _ <<<"$row"
  echo "| $name |${times[$name]} | $(median "${times[$name]}") | ${rays[$name]} |"
done
if [ -n "$rtsmoke" ]; then
  for run in 1 2 3; do
    "$rtsmoke" --scene cornell --size 1920x1080 --spp 16 --depth 4 --frames 6 --out '' | grep "^RESULT"
  done
fi
