#!/usr/bin/env bash
# `penumbra study` end to end on lavapipe: a small study (Cornell box, 32x32,
# three strategies, 1..64 spp, three seeds) writes a consistent results.csv
# and results.json and prints its answers; --analyze answers from the CSV;
# bad input fails with one line and leaves nothing behind.
set -eu
penumbra="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$penumbra" study --scene cornell-box --size 32x32 --strategy bsdf,nee,mis --spp 1,4,16,64 \
  --seeds 3 --reference-spp 1024 --target-relmse 0.05 --validation --out "$work/s" | tee "$work/log"
csv="$work/s/results.csv"
head -1 "$csv" | grep -q "^technique,integrator,strategy,mis_heuristic,sampler,max_depth,russian_roulette,clamp,denoise,pipeline,spp,seed,gpu_ms,denoise_ms,rays,relmse,mape,ssim,bias,efficiency,below_reference_noise$"
# Every point present: 3 strategies x 4 spp x 3 seeds, each once.
[ "$(tail -n +2 "$csv" | wc -l)" = 36 ]
[ "$(tail -n +2 "$csv" | cut -d, -f1,11,12 | sort -u | wc -l)" = 36 ]
for t in bsdf nee mis; do
  for spp in 1 4 16 64; do
    [ "$(tail -n +2 "$csv" | awk -F, -v t=$t -v s=$spp '$1 == t && $11 == s' | wc -l)" = 3 ]
  done
done
# Times and rays positive, errors finite and in range.
tail -n +2 "$csv" | awk -F, '{
  if (!($13 > 0) || !($15 > 0)) { print "bad time or rays: " $0; exit 1 }
  for (c = 16; c <= 19; ++c) if ($c == "nan" || $c == "inf" || $c == "-inf" || $c == "") { print "bad metric: " $0; exit 1 }
  if (!($16 >= 0) || !($18 <= 1)) { print "bad relmse or ssim: " $0; exit 1 }
}'
grep -q '"format": "penumbra-study"' "$work/s/results.json"
[ "$(grep -c '"technique": ' "$work/s/results.json")" -ge 48 ]  # 36 rows, 12 summaries, answers
[ -s "$work/s/reference.exr" ] && [ -s "$work/s/images/mis-spp64.exr" ]
grep -q "^within 33.3 ms: the lowest error is " "$work/log"
grep -q "^relMSE <= 0.05: the fastest is " "$work/log"
grep -qE "^  mis +slope -[01]\.[0-9]+ over 4 spp values$" "$work/log"
grep -q "^reference: rendered, 1024 spp (seeds 1000003 and 1000004)" "$work/log"
# The same answers from the CSV alone, for another budget.
"$penumbra" study --analyze "$csv" --budget-ms 5 | tee "$work/analyze"
grep -q "^within 5 ms: " "$work/analyze"
grep -q "^Pareto front" "$work/analyze"
# The cached reference is reused by a second study of the same scene and size.
"$penumbra" study --size 32x32 --spp 2 --seeds 1 --reference-spp 1024 --out "$work/s" | grep -q "(cached)"
# A cache whose noise line is damaged is stale: the reference is rendered
# again, not taken (and not an internal error).
sed -i '2s/.*/not a number/' "$work/s/reference.txt"
"$penumbra" study --size 32x32 --spp 2 --seeds 1 --reference-spp 1024 --out "$work/s" >"$work/recache" 2>&1 ||
  { cat "$work/recache"; echo "a damaged reference cache failed the study"; exit 1; }
if grep -q "(cached)" "$work/recache"; then echo "a damaged reference cache was used"; exit 1; fi

fails() {  # the command must fail with exactly one line on stderr naming `what`
  local what="$1"
  shift
  if "$penumbra" "$@" >"$work/out" 2>"$work/err"; then
    echo "expected failure: $*"
    exit 1
  fi
  [ "$(wc -l <"$work/err")" = 1 ] || { cat "$work/err"; exit 1; }
  grep -q -- "$what" "$work/err" || { cat "$work/err"; exit 1; }
}
fails "'foo' is not one of uniform, cosine, bsdf, nee, mis" study --strategy mis,foo --out "$work/bad"
fails "'0' is not a sample count" study --spp 1,0 --out "$work/bad"
fails "overlap the study's seeds 1..3" study --reference-seed 2 --out "$work/bad"
fails "is required" study --spp 1
fails "no such file\|cannot read" study --analyze "$work/missing.csv"
printf 'technique,spp\nmis,4\n' >"$work/short.csv"
fails "header has no 'seed' column" study --analyze "$work/short.csv"
[ ! -e "$work/bad" ]
# With matplotlib present (scripts/setup.sh installs it), the study made its
# report too.
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
  [ -s "$work/s/report.html" ] && [ -s "$work/s/error_vs_time.png" ] && [ -s "$work/s/error_vs_spp.png" ]
fi
