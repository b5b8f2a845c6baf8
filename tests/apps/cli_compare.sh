#!/usr/bin/env bash
# `penumbra compare`: two renders on the same device are identical (exit 0),
# renders with different seeds are not (exit 1), file mode agrees, and the
# false-colour difference image is written.
set -u
penumbra="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$penumbra" compare --a vulkan:0 --b vulkan:0 --size 24x24 --spp 4 --seed 5 >"$work/same.log" 2>&1
[ $? -eq 0 ] || { cat "$work/same.log"; fail "identical renders did not compare equal"; }
grep -q "max absolute difference: 0$" "$work/same.log" || fail "identical renders differ"

"$penumbra" render --size 24x24 --spp 4 --seed 1 --out "$work/a.exr" >/dev/null 2>&1 || fail "render a"
"$penumbra" render --size 24x24 --spp 4 --seed 2 --out "$work/b.exr" >/dev/null 2>&1 || fail "render b"
"$penumbra" compare "$work/a.exr" "$work/a.exr" >/dev/null 2>&1 || fail "a file differs from itself"
"$penumbra" compare "$work/a.exr" "$work/b.exr" --diff "$work/diff.png" >"$work/diff.log" 2>&1
[ $? -eq 1 ] || { cat "$work/diff.log"; fail "different seeds compared equal (want exit 1)"; }
grep -q "NOT within tolerance" "$work/diff.log" || fail "no verdict line"
[ -s "$work/diff.png" ] || fail "no difference image"
# Loose enough a tolerance accepts the noise difference.
"$penumbra" compare "$work/a.exr" "$work/b.exr" --tolerance 1e9 >/dev/null 2>&1 || fail "tolerance ignored"
"$penumbra" compare --a vulkan:0 --size 8x8 >/dev/null 2>&1 && fail "--a without --b accepted"
# AOV layers: a file without them is refused in one line naming the layer.
"$penumbra" compare "$work/a.exr" "$work/a.exr" --layer albedo >"$work/layer.log" 2>&1 &&
  fail "--layer on a file without layers accepted"
grep -q "has no layer 'albedo'" "$work/layer.log" || { cat "$work/layer.log"; fail "no clear error for a missing layer"; }
# Two seeds differ by noise, not systematically: the bias test passes them
# when the per-pixel tolerance is waived, and prints the mean difference.
"$penumbra" compare "$work/a.exr" "$work/b.exr" --allowed-fraction 1 --max-bias-sigmas 4 >"$work/bias.log" 2>&1 ||
  { cat "$work/bias.log"; fail "two seeds' noise called systematic"; }
grep -q "^mean difference b - a:" "$work/bias.log" || fail "no mean difference line"
echo "compare CLI ok"
