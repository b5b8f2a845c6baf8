#!/usr/bin/env bash
#
# Self-test for tests/farm/slurm_cluster.sh: bring up the private Slurm
# cluster, run a job array plus a dependent job, requeue a running job, and
# tear everything down. Must run as root (the cluster uses SlurmUser=root).
#
# Prints timings; on failure dumps the daemons' log tails and ends with a
# single "FAIL: reason" line and a non-zero exit status.
# SLURM_TEST_KEEP=1 keeps the temporary directory for inspection.

set -Eeuo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=SCRIPTDIR/slurm_cluster.sh
source "$here/slurm_cluster.sh"

fail_reason=""
fail() {
    fail_reason=$*
    exit 1
}
# Unexpected command failures still end with a one-line reason.
trap 'fail "line $LINENO: command failed: $BASH_COMMAND"' ERR

work=$(mktemp -d -t slurm-selftest.XXXXXX)
started=0

on_exit() {
    local rc=$?
    trap - ERR
    # slurm_cluster_start prints the logs itself when it fails.
    if (( rc != 0 && started )); then
        _slurm_cluster_dump_logs
    fi
    slurm_cluster_stop
    if [[ ${SLURM_TEST_KEEP:-0} == 1 ]]; then
        echo "kept $work" >&2
    else
        rm -rf "$work"
    fi
    (( rc == 0 )) || echo "FAIL: ${fail_reason:-exit status $rc}" >&2
    exit "$rc"
}
trap on_exit EXIT

(( EUID == 0 )) || fail "must run as root (the test cluster uses SlurmUser=root)"

# Stopwatch with sub-second resolution (bash 5 EPOCHREALTIME).
t_begin=$EPOCHREALTIME
t_mark=$t_begin
lap() {
    local now=$EPOCHREALTIME
    awk -v a="$t_mark" -v b="$now" -v what="$1" 'BEGIN { printf "  %-30s %6.2f s\n", what, b - a }'
    t_mark=$now
}

echo "test_slurm_cluster: work dir $work"
slurm_cluster_start "$work/cluster" || fail "slurm_cluster_start failed"
started=1
lap "cluster start"

out=$work/out
jobs=$work/jobs
mkdir -p "$out" "$jobs"

# Job scripts are files with a bash shebang: --wrap would run them under
# /bin/sh (dash), which has no EPOCHREALTIME. Results are written to a temp
# name and renamed, so no reader ever sees a partial file.
cat >"$jobs/array.sh" <<'JOB'
#!/bin/bash
set -eu
start=$EPOCHREALTIME
sleep 1
printf '%s\n' "$SLURM_ARRAY_TASK_ID" >"task.$SLURM_ARRAY_TASK_ID.tmp"
mv "task.$SLURM_ARRAY_TASK_ID.tmp" "task.$SLURM_ARRAY_TASK_ID"
printf '%s %s\n' "$start" "$EPOCHREALTIME" >"times.$SLURM_ARRAY_TASK_ID"
JOB
cat >"$jobs/concat.sh" <<'JOB'
#!/bin/bash
set -eu
printf '%s\n' "$EPOCHREALTIME" >concat.start
cat task.0 task.1 task.2 task.3 >all.tmp
mv all.tmp all
JOB
# First run blocks until it is requeued; the rerun sees SLURM_RESTART_COUNT=1.
cat >"$jobs/requeue.sh" <<'JOB'
#!/bin/bash
set -eu
n=${SLURM_RESTART_COUNT:-0}
echo "$n" >>requeue.runs
if [[ $n == 0 ]]; then
    sleep 300
fi
JOB

# --- job array + dependent job -------------------------------------------------
array_id=$(sbatch --parsable --array=0-3 --job-name=selftest-array --cpus-per-task=1 \
    --chdir="$out" --output="$out/array-%A_%a.log" "$jobs/array.sh") \
    || fail "sbatch of the job array failed"
[[ $array_id =~ ^[0-9]+$ ]] || fail "unexpected sbatch --parsable output: '$array_id'"

concat_id=$(sbatch --parsable --dependency="afterok:$array_id" --job-name=selftest-concat \
    --chdir="$out" --output="$out/concat-%j.log" "$jobs/concat.sh") \
    || fail "sbatch of the dependent job failed"

slurm_wait_jobs -t 90 "$array_id" "$concat_id" \
    || fail "array/dependent jobs did not finish within 90 s"
lap "4-task array + dependent job"

for i in 0 1 2 3; do
    [[ -f $out/task.$i ]] || fail "array task $i wrote no result (see $out/array-${array_id}_$i.log)"
done
[[ -f $out/all ]] || fail "dependent job wrote no result"
[[ $(<"$out/all") == $'0\n1\n2\n3' ]] \
    || fail "dependent job wrote '$(tr '\n' ' ' <"$out/all")', expected '0 1 2 3'"

# afterok must hold the dependent job until every array task has ended.
last_end=$(cat "$out"/times.* | awk '$2 > m { m = $2 } END { print m }')
awk -v s="$(<"$out/concat.start")" -v e="$last_end" 'BEGIN { exit !(s >= e) }' \
    || fail "dependent job started before the array finished"

# With CR_CPU and more than one CPU, some 1-CPU tasks must have overlapped.
if (( $(nproc) > 1 )); then
    sort -n "$out"/times.* | awk '
        NR > 1 && $1 < max_end { overlap = 1 }
        $2 > max_end { max_end = $2 }
        END { exit !overlap }' \
        || fail "array tasks never ran concurrently on $(nproc) CPUs"
fi

# --- requeue of a running job ----------------------------------------------------
requeue_id=$(sbatch --parsable --requeue --job-name=selftest-requeue \
    --chdir="$out" --output="$out/requeue-%j.log" "$jobs/requeue.sh") \
    || fail "sbatch of the requeue job failed"
deadline=$(( SECONDS + 30 ))
until [[ -s $out/requeue.runs ]]; do
    (( SECONDS < deadline )) || fail "requeue job did not start within 30 s"
    sleep 0.2
done
scontrol requeue "$requeue_id" || fail "scontrol requeue $requeue_id failed"
slurm_wait_jobs -t 90 "$requeue_id" || fail "requeued job did not finish within 90 s"
runs=$(tr '\n' ' ' <"$out/requeue.runs")
[[ $runs == "0 1 " ]] || fail "requeue job ran with restart counts '$runs', expected '0 1 '"
lap "requeue of a running job"

# --- teardown --------------------------------------------------------------------
slurm_cluster_stop
lap "cluster stop"

# Only processes of this cluster count (they carry our work dir in their
# command line or environment): a system Slurm or munged may run here too.
leftover=""
for dir in /proc/[0-9]*; do
    case $(cat "$dir/comm" 2>/dev/null || true) in
        slurmctld | slurmd | slurmstepd | munged) ;;
        *) continue ;;
    esac
    if tr '\0' '\n' 2>/dev/null <"$dir/environ" | grep -qF "$work" \
        || tr '\0' ' ' 2>/dev/null <"$dir/cmdline" | grep -qF "$work"; then
        leftover+=" ${dir#/proc/}($(cat "$dir/comm" 2>/dev/null || true))"
    fi
done
[[ -z $leftover ]] || fail "processes still running after slurm_cluster_stop:$leftover"

awk -v a="$t_begin" -v b="$EPOCHREALTIME" 'BEGIN { printf "  %-30s %6.2f s\n", "total", b - a }'
echo "test_slurm_cluster: PASS"
