#!/usr/bin/env bash
# The studies docs/study/ holds, for one device: what accuracy costs in time
# on the four showcase scenes, and how deep the Cornell box's paths must go.
# Each study's CSV, JSON, plots, report and sRGB previews land in
# OUTDIR/SCENE/ (the EXRs are left out to keep the folder small).
#   scripts/studies.sh PENUMBRA OUTDIR SIZE REFSPP [penumbra study options...]
# e.g. scripts/studies.sh build/apps/render/penumbra docs/study/lavapipe 64x64 1024
set -euo pipefail
penumbra="$1" out="$2" size="$3" refspp="$4"
shift 4
study() {  # study NAME SCENE OPTIONS...
  local name="$1" scene="$2"
  shift 2
  local dir="$out/$name"
  rm -rf "$dir"
  "$penumbra" study --scene "$scene" --size "$size" --reference-spp "$refspp" --seeds 3 \
    --out "$dir" "$@" "${extra[@]}" | grep -v '^progress: ' | tee "$dir.txt"
  mv "$dir.txt" "$dir/answers.txt"
  find "$dir" -name '*.exr' -delete
}
extra=("$@")
mkdir -p "$out"
study cornell-box cornell-box --strategy bsdf,nee,mis --sampler random,sobol --spp 1,4,16,64
study cornell-box-depth cornell-box --strategy mis --sampler sobol --max-depth 2,4,8,16,64 --spp 16,64
study material-test material-test --strategy bsdf,mis --sampler random,sobol --spp 1,4,16,64
study cornell-box-whitted cornell-box-whitted --integrator path,whitted --sampler random,sobol --spp 1,4,16,64
study implicit-surfaces implicit-surfaces --strategy nee,mis --sampler random,sobol --spp 1,4,16
