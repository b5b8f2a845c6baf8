#!/usr/bin/env bash
# Runs one libFuzzer target from a committed corpus, for at most SECONDS and,
# if RUNS is given, at most RUNS executions:
#   run_fuzzer.sh FUZZER CORPUS_DIR DICTIONARY SECONDS [RUNS]
# New inputs go to a scratch folder (the committed corpus is only read). Fails
# on any crash, sanitizer report, leak, timeout (10 s per input), or input
# over 4 GB of memory; the reproducer is left in the scratch folder and
# named in the output. Prints the executions reached.
set -u
fuzzer="$1" corpus="$2" dict="$3" seconds="$4" runs="${5:-}"
scratch=$(mktemp -d)
export LSAN_OPTIONS="suppressions=$(cd "$(dirname "$0")" && pwd)/lsan.supp"
mkdir -p "$scratch/new" "$scratch/artifacts"
# The same seed every run, and with RUNS the same number of executions on
# every machine that is not cut short by SECONDS. The same binary then
# tries exactly the same inputs every time, given two more things:
# address-space randomisation off (libFuzzer's comparison tracing feeds
# operand values, pointers included, into its mutations) and no timed
# re-reading of the output folder (-reload=0). (A build in another folder is
# another binary and tries other inputs.) Where the personality call is not
# permitted, the run is randomised and says so.
limits=(-max_total_time="$seconds")
[ -z "$runs" ] || limits+=(-runs="$runs")
fixed_layout=()
if setarch "$(uname -m)" -R true 2>/dev/null; then
  fixed_layout=(setarch "$(uname -m)" -R)
else
  echo "run_fuzzer.sh: cannot turn off address-space randomisation; this run is not reproducible"
fi
"${fixed_layout[@]}" "$fuzzer" -seed=1 "${limits[@]}" -reload=0 -timeout=10 -rss_limit_mb=4096 -max_len=65536 \
  -dict="$dict" -artifact_prefix="$scratch/artifacts/" -print_final_stats=1 \
  "$scratch/new" "$corpus" >"$scratch/log" 2>&1
status=$?
grep -E "^(#[0-9]+[[:space:]]+DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::peak_rss_mb)" "$scratch/log"
if [ $status -ne 0 ]; then
  tail -60 "$scratch/log"
  echo "run_fuzzer.sh: $(basename "$fuzzer") failed (status $status); reproducer(s): $(ls "$scratch/artifacts")" >&2
  echo "run_fuzzer.sh: kept in $scratch" >&2
  exit 1
fi
rm -rf "$scratch"
