#!/usr/bin/env bash
# Error per unit time of Penumbra's samplers against Blender Cycles on the
# same scene and machine, as docs/results.md reports it. Cycles (CPU) renders
# a reference of REFSPP samples (seed 1000) and SPP-sample images from seeds
# 1..SEEDS; Penumbra's study renders mis at SPP with the random and the Sobol
# sampler, SEEDS seeds each, against the same Cycles reference. Both use max
# depth 64, a box pixel filter, no clamping. Time: Cycles' render wall time,
# Penumbra's GPU timestamps (on lavapipe: the same CPU cores). Prints a
# Markdown table of mean relMSE, mean seconds and efficiency
# 1/(relMSE x seconds).
#   scripts/sampler_vs_cycles.sh PENUMBRA OUTDIR [SIZE SPP REFSPP SEEDS]
# Needs Debian's blender (apt-get install blender).
set -euo pipefail
penumbra="$1" out="$2" size="${3:-128}" spp="${4:-256}" refspp="${5:-4096}" seeds="${6:-3}"
root="$(cd "$(dirname "$0")/.." && pwd)"
scene="$root/scenes/cornell-box.json"
command -v blender >/dev/null || { echo "sampler_vs_cycles.sh: blender not found (apt-get install blender)" >&2; exit 1; }
mkdir -p "$out"
cycles() {  # cycles SPP SEED OUT -> "render-seconds pattern"
  blender -b --factory-startup -P "$root/scripts/cycles_render.py" -- --scene "$scene" \
    --size "$size" --spp "$1" --seed "$2" --out "$3" 2>&1 |
    sed -nE 's/^cycles: render_s=([0-9.]+) spp=[0-9]+ pattern=([A-Z_]+)$/\1 \2/p'
}
ref="$out/cycles-ref-$size-$refspp.exr"
[ -f "$ref" ] || cycles "$refspp" 1000 "$ref" >/dev/null
[ -s "$ref" ] || { echo "sampler_vs_cycles.sh: Cycles wrote no reference" >&2; exit 1; }
cycles_rows=""
for seed in $(seq 1 "$seeds"); do
  img="$out/cycles-$size-$spp-s$seed.exr"
  read -r seconds pattern <<<"$(cycles "$spp" "$seed" "$img")"
  # compare exits non-zero when the images differ beyond its tolerance,
  # which noisy images always do; the relMSE line is what counts.
  relmse=$({ "$penumbra" compare "$img" "$ref" || true; } | awk '/^relative MSE/ { print $NF }')
  [ -n "$relmse" ] && [ -n "$seconds" ] || { echo "sampler_vs_cycles.sh: no measurement for seed $seed" >&2; exit 1; }
  cycles_rows+="$relmse $seconds"$'\n'
done
rm -rf "$out/study"
"$penumbra" study --scene cornell-box --size "${size}x${size}" --strategy mis --sampler random,sobol \
  --max-depth 64 --spp "$spp" --seeds "$seeds" --repeats 1 --reference "$ref" --out "$out/study" >"$out/study.log"
device=$(sed -n 's/^device: //p' "$out/study.log")
echo "Cornell box ${size}x${size}, $spp spp, max depth 64, $seeds seeds each, against Cycles at $refspp spp; Penumbra on $device"
echo
echo "| renderer | sampler | relMSE | seconds | efficiency 1/(relMSE s) | vs Cycles |"
echo "|---|---|---|---|---|---|"
cycles_eff=$(printf '%s' "$cycles_rows" | awk '{ r += $1; s += $2; n++ } END { printf "%.6g", 1 / ((r / n) * (s / n)) }')
printf '%s' "$cycles_rows" | awk -v e="$cycles_eff" '{ r += $1; s += $2; n++ }
  END { printf "| Blender Cycles %s (CPU) | %s | %.4g | %.3f | %.4g | 1.00x |\n", "'"$(blender --version 2>/dev/null | head -1 | cut -d" " -f2)"'", "'"$pattern"'", r / n, s / n, e }'
awk -F, -v e="$cycles_eff" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
  { k = $c["sampler"]; r[k] += $c["relmse"]; t[k] += $c["gpu_ms"] / 1000; n[k]++ }
  END { for (k in n) { rr = r[k] / n[k]; tt = t[k] / n[k]; eff = 1 / (rr * tt)
          printf "| Penumbra | %s | %.4g | %.3f | %.4g | %.2fx |\n", k, rr, tt, eff, eff / e } }' \
  "$out/study/results.csv" | sort
