#!/usr/bin/env bash
# The denoiser's quality against converged references, as docs/results.md
# reports it: for each showcase scene, a reference of REFSPP samples (its own
# seed), then raw, single-frame a-trous and temporal SVGF (one frame per
# sample) images at 1, 2, 4 and 16 spp from one seed; relMSE and SSIM of
# each against the reference, and the denoiser's GPU time. Prints a Markdown
# table.
#   scripts/denoiser_quality.sh PENUMBRA WIDTHxHEIGHT REFSPP OUTDIR [SCENE...]
set -euo pipefail
penumbra="$1" size="$2" refspp="$3" out="$4"
shift 4
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(cornell-box material-test implicit-surfaces cornell-box-whitted)
mkdir -p "$out"
metric() {  # metric IMAGE REFERENCE -> "relMSE SSIM"
  "$penumbra" compare "$1" "$2" | awk '/^relative MSE/ { r = $NF } /^SSIM/ { s = $NF } END { printf "%.4g %.4f", r, s }'
}
echo "| scene | spp | raw relMSE | raw SSIM | a-trous relMSE | a-trous SSIM | SVGF relMSE | SVGF SSIM | a-trous ms | SVGF ms (all frames) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
  ref="$out/$scene-ref.exr"
  [ -f "$ref" ] || "$penumbra" render --scene "$scene" --size "$size" --spp "$refspp" --seed 9999 --out "$ref" >/dev/null
  for spp in 1 2 4 16; do
    "$penumbra" render --scene "$scene" --size "$size" --spp "$spp" --seed 1 --out "$out/$scene-$spp-raw.exr" >/dev/null
    atrous_ms=$("$penumbra" render --scene "$scene" --size "$size" --spp "$spp" --seed 1 --denoise atrous \
      --out "$out/$scene-$spp-atrous.exr" | sed -nE 's/^denoiser \(atrous\): ([0-9.]+) ms.*/\1/p')
    svgf_ms=$("$penumbra" render --scene "$scene" --size "$size" --spp "$spp" --spp-per-frame 1 --seed 1 \
      --denoise svgf --out "$out/$scene-$spp-svgf.exr" | sed -nE 's/^denoiser \(svgf\): ([0-9.]+) ms.*/\1/p')
    read -r rr rs <<<"$(metric "$out/$scene-$spp-raw.exr" "$ref")"
    read -r ar as <<<"$(metric "$out/$scene-$spp-atrous.exr" "$ref")"
    read -r sr ss <<<"$(metric "$out/$scene-$spp-svgf.exr" "$ref")"
    echo "| $scene | $spp | $rr | $rs | $ar | $as | $sr | $ss | $atrous_ms | $svgf_ms |"
  done
done
