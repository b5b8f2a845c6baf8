#!/usr/bin/env bash
# Runs one libFuzzer target for a bounded time from a committed corpus:
#   run_fuzzer.sh FUZZER CORPUS_DIR DICTIONARY SECONDS
# New inputs go to a scratch folder (the committed corpus is only read). Fails
# on any crash, sanitizer report, leak, timeout (10 s per input), or input
# over 4 GB of memory; the reproducer is left in the scratch folder and
# named in the output. Prints the executions reached.
set -u
fuzzer="$1" corpus="$2" dict="$3" seconds="$4"
scratch=$(mktemp -d)
export LSAN_OPTIONS="suppressions=$(cd "$(dirname "$0")" && pwd)/lsan.supp"
mkdir -p "$scratch/new" "$scratch/artifacts"
# The same seed every run: the same binary and corpus explore the same
# inputs (how far they get still depends on the machine's speed).
"$fuzzer" -seed=1 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=65536 \
  -dict="$dict" -artifact_prefix="$scratch/artifacts/" -print_final_stats=1 \
  "$scratch/new" "$corpus" >"$scratch/log" 2>&1
status=$?
grep -E "^(#[0-9]+ *DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::peak_rss_mb)" "$scratch/log"
if [ $status -ne 0 ]; then
  tail -60 "$scratch/log"
  echo "run_fuzzer.sh: $(basename "$fuzzer") failed (status $status); reproducer(s): $(ls "$scratch/artifacts")" >&2
  echo "run_fuzzer.sh: kept in $scratch" >&2
  exit 1
fi
rm -rf "$scratch"
