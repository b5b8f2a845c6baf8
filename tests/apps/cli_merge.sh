#!/usr/bin/env bash
# Sample-split renders through the CLI on lavapipe: `render --samples A:B
# --total-spp N` pieces, split 1, 2, 3 and 7 ways and given to `merge` in
# shuffled orders, give the same file bit for bit as the render of all N
# samples; a plain `render --spp N` (a running mean) agrees within float
# rounding; merge refuses pieces of another seed or scene, duplicates,
# truncated files and gaps, each in one line with no output file.
set -u
penumbra="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
common=(--size 40x40 --total-spp 112)  # 7 frames of 16

piece() {  # piece RANGE FILE [SEED [SCENE]]
  local range="$1" file="$2" seed="${3:-3}" scene="${4:-cornell-box}"
  "$penumbra" render "${common[@]}" --seed "$seed" --scene "$scene" --samples "$range" \
    --out "$file" >"$work/log" 2>&1 || { cat "$work/log"; fail "render --samples $range"; }
}

piece 0:112 "$work/whole.exr"
"$penumbra" merge "$work/whole.exr" --out "$work/single.exr" >/dev/null 2>&1 || fail "merge of one piece"

declare -A splits=(
  [2]="0:48 48:112"
  [3]="0:32 32:64 64:112"
  [7]="0:16 16:32 32:48 48:64 64:80 80:96 96:112"
)
for k in 2 3 7; do
  files=()
  for range in ${splits[$k]}; do
    piece "$range" "$work/k$k-${range/:/-}.exr"
    files+=("$work/k$k-${range/:/-}.exr")
  done
  # Reversed, then rotated by one: the order of the pieces must not matter.
  reversed=()
  for ((i = ${#files[@]} - 1; i >= 0; i--)); do reversed+=("${files[$i]}"); done
  rotated=("${files[@]:1}" "${files[0]}")
  for order in reversed rotated; do
    declare -n list="$order"
    "$penumbra" merge "${list[@]}" --out "$work/merged.exr" >"$work/merge.log" 2>&1 ||
      { cat "$work/merge.log"; fail "merge of $k pieces ($order)"; }
    grep -q "samples merged: 112 of 112" "$work/merge.log" || fail "$k pieces: sample count"
    cmp -s "$work/merged.exr" "$work/single.exr" ||
      fail "$k pieces merged ($order) differ from the single render"
  done
done

# A ragged last frame and frames of 5: 23 samples are frames of 5, 5, 5, 5
# and 3; pieces 0:10 + 10:23 and 0:5 + 5:15 + 15:20 + 20:23 equal 0:23.
ragged=(--scene cornell-box --size 24x24 --seed 9 --spp-per-frame 5 --total-spp 23)
split_piece() {  # split_piece RANGE FILE
  "$penumbra" render "${ragged[@]}" --samples "$1" --out "$2" >"$work/log" 2>&1 ||
    { cat "$work/log"; fail "ragged piece $1"; }
}
split_piece 0:23 "$work/r-whole.exr"
"$penumbra" merge "$work/r-whole.exr" --out "$work/r-single.exr" >/dev/null 2>&1 || fail "ragged merge"
for cut in "0:10 10:23" "0:5 5:15 15:20 20:23"; do
  files=()
  for range in $cut; do
    split_piece "$range" "$work/r-${range/:/-}.exr"
    files=("$work/r-${range/:/-}.exr" "${files[@]}")  # reversed
  done
  "$penumbra" merge "${files[@]}" --out "$work/r-merged.exr" >/dev/null 2>&1 || fail "ragged merge ($cut)"
  cmp -s "$work/r-merged.exr" "$work/r-single.exr" || fail "ragged pieces ($cut) differ"
done
# Fewer samples than a frame: one block, one piece.
"$penumbra" render --scene cornell-box --size 24x24 --total-spp 3 --samples 0:3 \
  --out "$work/tiny.exr" >/dev/null 2>&1 || fail "3 of 3 samples"
"$penumbra" merge "$work/tiny.exr" --out "$work/tiny-merged.exr" | grep -q "samples merged: 3 of 3" ||
  fail "3-sample merge"

# A plain render sums in another order (a running mean over frames): equal
# within float rounding, 1e-5 relative per channel (a lost or doubled frame
# would be 1/7 = 0.14).
"$penumbra" render --scene cornell-box --size 40x40 --seed 3 --spp 112 --out "$work/plain.exr" \
  >/dev/null 2>&1 || fail "plain render"
"$penumbra" compare "$work/plain.exr" "$work/single.exr" --tolerance 1e-5 >"$work/cmp.log" 2>&1 ||
  { cat "$work/cmp.log"; fail "plain render and merged render differ beyond float rounding"; }
# A merged PNG is tone-mapped as the render asked.
"$penumbra" merge "$work/whole.exr" --out "$work/single.png" >/dev/null 2>&1 || fail "merge to PNG"
[ -s "$work/single.png" ] || fail "no PNG"

refuses() {  # refuses WHAT ARGS...: exit != 0, one line naming WHAT, no output
  local what="$1"
  shift
  rm -f "$work/out.exr"
  if "$penumbra" "$@" >"$work/out" 2>"$work/err"; then fail "accepted: $*"; fi
  [ "$(wc -l <"$work/err")" = 1 ] || { cat "$work/err"; fail "not one line: $*"; }
  grep -q -- "$what" "$work/err" || { cat "$work/err"; fail "no '$what': $*"; }
  [ ! -e "$work/out.exr" ] || fail "output written: $*"
}
k3=("$work/k3-0-32.exr" "$work/k3-32-64.exr" "$work/k3-64-112.exr")
piece 0:32 "$work/seed4.exr" 4
refuses "different renders (seed 4 vs 3)" merge "$work/seed4.exr" "${k3[@]:1}" --out "$work/out.exr"
piece 0:32 "$work/other-scene.exr" 3 material-test
refuses "different renders (scene content" merge "$work/other-scene.exr" "${k3[@]:1}" \
  --out "$work/out.exr"
cp "${k3[1]}" "$work/copy.exr"
refuses "overlap" merge "${k3[@]}" "$work/copy.exr" --out "$work/out.exr"
head -c 3000 "${k3[2]}" >"$work/truncated.exr"
refuses "truncated.exr" merge "${k3[0]}" "${k3[1]}" "$work/truncated.exr" --out "$work/out.exr"
refuses "samples 32:64 of 0:112 are missing" merge "${k3[0]}" "${k3[2]}" --out "$work/out.exr"
"$penumbra" merge "${k3[0]}" "${k3[2]}" --allow-partial --out "$work/partial.exr" >"$work/p.log" 2>&1 ||
  { cat "$work/p.log"; fail "--allow-partial"; }
grep -q "samples merged: 80 of 112" "$work/p.log" || fail "--allow-partial count"
grep -q "missing: samples 32:64" "$work/p.log" || fail "--allow-partial names the gap"
refuses "multiples of the samples per frame" render "${common[@]}" --samples 8:24 --out "$work/out.exr"
refuses "go together" render --samples 0:16 --out "$work/out.exr"
refuses "must be an .exr" render "${common[@]}" --samples 0:16 --out "$work/out.png"
echo "sample-split CLI ok"
