#!/usr/bin/env bash
# `penumbra farm` against a real Slurm controller and node on localhost
# (tests/farm/slurm_cluster.sh), rendering on lavapipe:
# - a 4-shard job array plus its dependent merge job give the file a single
#   render of the same samples gives, bit for bit;
# - a shard killed mid-render (SIGKILL while it renders) leaves no shard
#   file, fails its task, and the merge is cancelled; a second shard file
#   damaged on disk is refused; `farm submit` run again resubmits exactly
#   those two shards and the final image is again bit-identical;
# - `farm status` reports shards done and missing; a rerun with other
#   options in the same work directory is refused; a rerun after the scene
#   file changed refuses the old shards;
# - `farm study` (a reference job, a 3-task array over the points, a gather
#   job) gives the rows of the same study run in one process: every column
#   but the measured times identical.
set -Eeuo pipefail
penumbra=$(realpath "$1")
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=SCRIPTDIR/slurm_cluster.sh
source "$here/slurm_cluster.sh"

work=$(mktemp -d -t penumbra-farm.XXXXXX)
reason=""
fail() {
  reason=$*
  exit 1
}
trap 'fail "line $LINENO: $BASH_COMMAND failed"' ERR
on_exit() {
  local rc=$?
  trap - ERR
  if ((rc != 0)); then
    for log in "$work"/*/logs/*.log; do [[ -e $log ]] && { echo "== $log"; tail -5 "$log"; }; done
    _slurm_cluster_dump_logs 2>/dev/null || true
  fi
  slurm_cluster_stop
  rm -rf "$work"
  ((rc == 0)) || echo "FAIL: ${reason:-exit status $rc}" >&2
  exit "$rc"
}
trap on_exit EXIT
((EUID == 0)) || fail "must run as root (the test cluster runs jobs as root)"

slurm_cluster_start "$work/cluster"

render=(--scene cornell-box --size 160x160 --seed 5)
# The single-machine render of the same 128 samples.
"$penumbra" render "${render[@]}" --total-spp 128 --samples 0:128 --out "$work/whole.exr" \
  >/dev/null 2>&1 || fail "single render"
"$penumbra" merge "$work/whole.exr" --out "$work/single.exr" >/dev/null || fail "single merge"

# submit OUT [more farm options]: prints the shard and merge job ids.
submit() {
  local out=$1
  shift
  "$penumbra" farm submit "${render[@]}" --spp 128 --shards 4 --out "$out" "$@" >"$work/submit.log" 2>&1 ||
    { cat "$work/submit.log"; fail "farm submit $out"; }
  cat "$work/submit.log"
}
job_ids() { sed -n 's/^\(shards\|merge\): job \([0-9]*\).*/\2/p' "$work/submit.log"; }

# 1. Four shards and the merge.
submit "$work/final.exr"
grep -q "array 0-3, 4 task(s)" "$work/submit.log" || fail "not a 4-task array"
mapfile -t ids < <(job_ids)
((${#ids[@]} == 2)) || fail "expected a shards job and a merge job"
slurm_wait_jobs -t 300 "${ids[@]}"
[[ -f $work/final.exr ]] || fail "the merge job wrote no final image"
cmp -s "$work/final.exr" "$work/single.exr" || fail "farm render differs from the single render"
"$penumbra" farm status --out "$work/final.exr" >"$work/status.log"
grep -q "4 of 4 shards done; output .* written" "$work/status.log" || fail "status after success"

# The pid of the render writing FILE: one grep over every process's command
# line (procps is not installed everywhere). The pattern ends in "[r]" so
# that grep's own command line, which holds the pattern, does not match it.
render_pid() {
  local pattern hit
  pattern=$(printf '%s' "$1" | sed 's/[].[\\*^$]/\\&/g; s/r$/[r]/')
  hit=$(grep -l -- "$pattern" /proc/[0-9]*/cmdline 2>/dev/null | head -1 || true)
  [[ -n $hit ]] && basename "$(dirname "$hit")"
  return 0
}

# 2. A shard killed mid-render, another damaged on disk, then resumed.
out="$work/again.exr"
submit "$out"
mapfile -t ids < <(job_ids)
shard2="$out.farm/shards/shard-002.exr"
pid=""
deadline=$((SECONDS + 240))
while [[ -z $pid ]] && ((SECONDS < deadline)); do  # shard 2's render to start
  pid=$(render_pid "$shard2")
  [[ -n $pid ]] || sleep 0.02
done
[[ -n $pid ]] || fail "shard 2's render never started"
kill -STOP "$pid"  # frozen mid-render: its file must not exist yet
[[ ! -e $shard2 ]] || fail "shard 2 exists before its render finished"
kill -KILL "$pid"
slurm_wait_jobs -t 300 "${ids[@]}"
[[ ! -e $shard2 ]] || fail "a killed shard left a file"
[[ ! -e $out ]] || fail "the merge ran although a shard failed"
"$penumbra" farm status --out "$out" >"$work/status.log"
grep -q "shard   2 .* missing" "$work/status.log" || { cat "$work/status.log"; fail "status: shard 2"; }
grep -q "3 of 4 shards done" "$work/status.log" || fail "status after the kill"
# Shard 1 damaged after it was written: refused, rendered again.
shard1="$out.farm/shards/shard-001.exr"
head -c 2000 "$shard1" >"$work/cut" && cat "$work/cut" >"$shard1"
# Another render in the same work directory is refused.
if "$penumbra" farm submit "${render[@]}" --spp 64 --shards 4 --out "$out" >"$work/other.log" 2>&1; then
  fail "a different render resumed another's work directory"
fi
grep -q "holds the plan of another render" "$work/other.log" || fail "no reason for the refusal"
submit "$out"
grep -q "resuming: 2 of 4 shards present" "$work/submit.log" || fail "resume count"
grep -q "array 1-2, 2 task(s)" "$work/submit.log" || fail "resume submitted other shards"
mapfile -t ids < <(job_ids)
slurm_wait_jobs -t 300 "${ids[@]}"
cmp -s "$out" "$work/single.exr" || fail "resumed farm render differs from the single render"

# 3. The scene file edited after its shards were rendered: a rerun refuses
# every shard of the old content (it would otherwise merge two scenes) and
# renders them all again.
scene_copy="$work/scene.json"
cp "$here/../../scenes/cornell-box.json" "$scene_copy"
edited=(--scene "$scene_copy" --size 48x48 --seed 5 --spp 32 --shards 2 --out "$work/edited.exr")
"$penumbra" farm submit "${edited[@]}" >"$work/submit.log" 2>&1 || { cat "$work/submit.log"; fail "submit"; }
mapfile -t ids < <(job_ids)
slurm_wait_jobs -t 300 "${ids[@]}"
[[ -f $work/edited.exr ]] || fail "no image of the scene file"
sed -i 's/"red": { "model": "lambert", "albedo": \[0.63, 0.065, 0.05\] }/"red": { "model": "lambert", "albedo": [0.05, 0.065, 0.63] }/' "$scene_copy"
grep -q '0.05, 0.065, 0.63' "$scene_copy" || fail "the scene edit did not apply"
"$penumbra" farm submit "${edited[@]}" >"$work/submit.log" 2>&1 || { cat "$work/submit.log"; fail "resubmit"; }
grep -q "resuming: 0 of 2 shards present" "$work/submit.log" || { cat "$work/submit.log"; fail "old shards kept"; }
grep -q "rendered from other scene content" "$work/submit.log" || fail "no reason for the refusal"
mapfile -t ids < <(job_ids)
slurm_wait_jobs -t 300 "${ids[@]}"
"$penumbra" farm status --out "$work/edited.exr" | grep -q "2 of 2 shards done" || fail "re-rendered"

# 4. A study split over three tasks and gathered.
study=(--scene cornell-box --size 16x16 --spp 1,4 --seeds 2 --strategy mis,bsdf
  --reference-spp 32 --repeats 1)
"$penumbra" study "${study[@]}" --out "$work/study-one" >"$work/study.log" 2>&1 ||
  { cat "$work/study.log"; fail "study in one process"; }
"$penumbra" farm study --tasks 3 --out "$work/study-farm" -- "${study[@]}" >"$work/submit.log" 2>&1 ||
  { cat "$work/submit.log"; fail "farm study"; }
grep -q "points: job .* (array 0-2: 8 points in 3 parts)" "$work/submit.log" || fail "study parts"
mapfile -t ids < <(sed -n 's/^\(reference\|points\|gather\): job \([0-9]*\).*/\2/p' "$work/submit.log")
((${#ids[@]} == 3)) || fail "expected reference, points and gather jobs"
slurm_wait_jobs -t 300 "${ids[@]}"
[[ -f $work/study-farm/results.csv ]] || fail "the gather job wrote no results"
# Columns 13, 14 and 20 are measured times (gpu_ms, denoise_ms, efficiency).
untimed() { cut -d, -f1-12,15-19,21 "$1"; }
[[ $(untimed "$work/study-farm/results.csv") == "$(untimed "$work/study-one/results.csv")" ]] ||
  fail "the gathered study's rows differ from the one-process study's"
echo "farm on Slurm ok"
