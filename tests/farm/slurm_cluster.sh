# shellcheck shell=bash
#
# slurm_cluster.sh - a private, single-node Slurm cluster on localhost for tests.
#
# Source this file from a test script (CI runs tests as root on Debian 12
# with the slurm-wlm and munge packages installed):
#
#   source tests/farm/slurm_cluster.sh
#   dir=$(mktemp -d)
#   trap 'slurm_cluster_stop; rm -rf "$dir"' EXIT
#   slurm_cluster_start "$dir"            # exports SLURM_CONF
#   id=$(sbatch --parsable --wrap true)
#   slurm_wait_jobs -t 60 "$id"
#
# Everything (munge key and socket, slurm.conf, state, spool, pid and log
# files) lives under the caller's directory. Nothing in /etc/slurm, /etc/munge,
# /run/munge or /var/spool is read or written, and system munged/slurm
# services, running or not, are not touched: we use our own munge socket and
# randomly chosen free ports.
#
# Call slurm_cluster_start in the current shell (not in $(...)), because it
# records the daemons' pids in shell variables for slurm_cluster_stop. The
# functions work under `set -euo pipefail` and leave shell options alone.

# Set by slurm_cluster_start; callers may use them (e.g. sbatch -w "$SLURM_CLUSTER_NODE").
SLURM_CLUSTER_DIR=""
SLURM_CLUSTER_NODE=""

# Seconds slurm_cluster_start waits for the node to become idle.
: "${SLURM_CLUSTER_START_TIMEOUT:=60}"

_slurm_cluster_log() { printf 'slurm_cluster: %s\n' "$*" >&2; }

# Only bash, coreutils, grep and awk are used besides Slurm and munge: procps
# (ps, pgrep) and iproute2 (ss) are not in minimal Debian images and are not
# pulled in by the slurm-wlm/munge packages.

# True while pid $1 exists and is not a zombie (our own exited children stay
# zombies until bash reaps them, and kill -0 succeeds on zombies).
_slurm_cluster_alive() {
    local stat
    [[ -n ${1:-} ]] || return 1
    { read -r stat <"/proc/$1/stat"; } 2>/dev/null || return 1
    stat=${stat##*) }                   # state is the field after "(comm)"
    [[ ${stat%% *} != [ZX] ]]
}

# True if any TCP socket (listening or connected, IPv4 or IPv6) uses local
# port $1: either would make the daemon's bind() fail.
_slurm_cluster_port_in_use() {
    local hex f files=()
    printf -v hex '%04X' "$1"
    for f in /proc/net/tcp /proc/net/tcp6; do
        if [[ -r $f ]]; then files+=("$f"); fi
    done
    (( ${#files[@]} )) || return 1
    awk -v suffix=":$hex" 'NR > 1 && substr($2, length($2) - 4) == suffix { found = 1 }
                           END { exit !found }' "${files[@]}"
}

# Print a random free TCP port that is not one of "$@". Ports are taken from
# below the kernel's ephemeral range, so an outgoing connection cannot grab
# the port between this check and the daemon's bind(); anything else that
# binds it in that window shows up as "Address already in use" in the logs.
_slurm_cluster_free_port() {
    local low=20000 high=60000 eph_low=0 eph_high=0 port taken
    read -r eph_low eph_high 2>/dev/null </proc/sys/net/ipv4/ip_local_port_range || true
    if (( eph_low > 21000 )); then
        high=$eph_low                   # Linux default: [20000, 32768)
    elif (( eph_high > 0 && eph_high < 64000 )); then
        low=$(( eph_high + 1 )); high=65536
    fi
    for _ in $(seq 1 200); do
        port=$(( low + (RANDOM * 32768 + RANDOM) % (high - low) ))
        for taken in "$@"; do
            [[ $port == "$taken" ]] && continue 2
        done
        _slurm_cluster_port_in_use "$port" || { echo "$port"; return 0; }
    done
    _slurm_cluster_log "no free TCP port found"
    return 1
}

# Print the tail of each daemon's log to stderr. NAME.stdio (the captured
# stderr) repeats NAME.log without timestamps once the log file is open, so it
# is shown only when there is no log file: early failures (bad slurm.conf)
# and munged (which logs to stderr in --foreground mode).
_slurm_cluster_dump_logs() {
    local name f
    for name in munged slurmctld slurmd; do
        f=$SLURM_CLUSTER_DIR/log/$name.log
        [[ -s $f ]] || f=$SLURM_CLUSTER_DIR/log/$name.stdio
        [[ -s $f ]] || continue
        printf '\n===== %s (last 30 lines) =====\n' "$f" >&2
        tail -n 30 "$f" >&2 || true
    done
}

# Start "$@" in the background with stdio detached (so a caller piping our
# output into tee is not held open by a daemon) and record its pid in
# DIR/run/NAME.harness-pid, where slurm_cluster_stop finds it.
_slurm_cluster_spawn() {
    local name=$1; shift
    "$@" </dev/null >>"$SLURM_CLUSTER_DIR/log/$name.stdio" 2>&1 &
    echo $! >"$SLURM_CLUSTER_DIR/run/$name.harness-pid"
}

_slurm_cluster_pid() {
    cat "$SLURM_CLUSTER_DIR/run/$1.harness-pid" 2>/dev/null || true
}

# SIGTERM, bounded wait, then SIGKILL. Checks the process name first, so a
# stale pid file (stop called twice, long after) cannot hit a reused pid.
_slurm_cluster_kill() {
    local name=$1 pid
    pid=$(_slurm_cluster_pid "$name")
    rm -f "$SLURM_CLUSTER_DIR/run/$name.harness-pid"
    [[ -n $pid ]] || return 0
    if [[ $(cat "/proc/$pid/comm" 2>/dev/null) != "$name" ]] || ! _slurm_cluster_alive "$pid"; then
        wait "$pid" 2>/dev/null || true
        return 0
    fi
    kill -TERM "$pid" 2>/dev/null || true
    local deadline=$(( SECONDS + 20 ))
    while _slurm_cluster_alive "$pid"; do
        if (( SECONDS >= deadline )); then
            _slurm_cluster_log "$name (pid $pid) ignored SIGTERM for 20s, sending SIGKILL"
            kill -KILL "$pid" 2>/dev/null || true
            break
        fi
        sleep 0.1
    done
    # Reap it if it is our child; harmless otherwise.
    wait "$pid" 2>/dev/null || true
}

# slurm_cluster_start DIR
#   Create keys and config under DIR, start munged, slurmctld and slurmd,
#   and wait until the node is idle. Exports SLURM_CONF. On failure prints
#   the daemons' log tails, stops whatever it started and returns non-zero.
slurm_cluster_start() {
    local dir=${1:?usage: slurm_cluster_start DIR}
    local cmd
    for cmd in munged slurmctld slurmd sinfo squeue scontrol scancel; do
        command -v "$cmd" >/dev/null || { _slurm_cluster_log "missing command: $cmd"; return 1; }
    done
    if [[ -n $SLURM_CLUSTER_DIR ]] && _slurm_cluster_alive "$(_slurm_cluster_pid slurmctld)"; then
        _slurm_cluster_log "a cluster is already running in $SLURM_CLUSTER_DIR"
        return 1
    fi
    mkdir -p "$dir"
    dir=$(cd "$dir" && pwd -P)
    SLURM_CLUSTER_DIR=$dir

    # munged checks that every directory above its socket is traversable by
    # all users and that key/socket/log/pid directories are not writable by
    # group/other. mktemp -d gives 0700, and the caller's DIR may itself sit
    # inside a private directory we must not chmod, so munged gets --force
    # below (turns those checks into log warnings). Our own directories are
    # still created with sane modes regardless of the caller's umask.
    # Consequence: only root (or DIR's owner) can talk to this munged unless
    # the caller makes DIR and its parents world-traversable.
    mkdir -p "$dir"/{munge,log,run,state,spool}
    chmod 0755 "$dir/munge"
    chmod 0700 "$dir/log" "$dir/run" "$dir/state" "$dir/spool"

    # --- munge ---------------------------------------------------------------
    # munged runs as the user who starts it (root in CI; munged accepts that),
    # and insists the key is owned by that user and unreadable by others.
    # In --foreground mode munged logs to stderr (our munged.stdio), not to
    # --log-file; the option is still given so nothing defaults to /var/log.
    local key=$dir/munge/munge.key sock=$dir/munge/munge.socket
    dd if=/dev/urandom of="$key" bs=1024 count=1 status=none
    chmod 0400 "$key"
    _slurm_cluster_spawn munged munged --foreground --force \
        --socket="$sock" --key-file="$key" --seed-file="$dir/munge/munged.seed" \
        --pid-file="$dir/run/munged.pid" --log-file="$dir/log/munged.log"
    local deadline=$(( SECONDS + 10 ))
    until [[ -S $sock ]]; do
        if ! _slurm_cluster_alive "$(_slurm_cluster_pid munged)" || (( SECONDS >= deadline )); then
            _slurm_cluster_log "munged did not come up"
            _slurm_cluster_dump_logs; slurm_cluster_stop; return 1
        fi
        sleep 0.1
    done

    # --- slurm.conf ----------------------------------------------------------
    local node ctld_port slurmd_port cpus mem_mb
    # Same as `hostname -s`, without needing the hostname package.
    node=$(uname -n)
    node=${node%%.*}
    # shellcheck disable=SC2034 # read by callers
    SLURM_CLUSTER_NODE=$node
    ctld_port=$(_slurm_cluster_free_port) || { slurm_cluster_stop; return 1; }
    slurmd_port=$(_slurm_cluster_free_port "$ctld_port") || { slurm_cluster_stop; return 1; }
    cpus=$(nproc)
    # Memory is not a consumable resource here (CR_CPU); the value only has
    # to be plausible. Stay under MemTotal so slurmd never sees "low memory".
    mem_mb=$(awk '/^MemTotal:/ { printf "%d", $2 / 1024 * 0.9 }' /proc/meminfo)

    cat >"$dir/slurm.conf" <<EOF
# Generated by tests/farm/slurm_cluster.sh for a private test cluster.
ClusterName=penumbra-test
# Loopback addresses: no DNS lookup of the host name, nothing reachable
# from outside.
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root

# In 22.05 AuthInfo's socket= is read by both auth/munge and cred/munge
# (there is no separate credential option). cred_expire is also the delay
# before a requeued job may start again (default 120 s), so keep it short.
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sock,cred_expire=10

# No cgroups: CI containers rarely offer a usable cgroup hierarchy.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
# The default /bin/mail is usually absent; avoid an error line in the log.
MailProg=/bin/true
# Trust the node line below even where slurmd measures a different CPU
# topology or memory size (containers, cpusets).
SlurmdParameters=config_overrides

StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
# Default would be plugstack.conf next to slurm.conf; make that explicit
# and empty, so /etc/slurm/plugstack.conf(.d) can never be picked up.
PlugStackConfig=$dir/plugstack.conf
SlurmctldDebug=info
SlurmdDebug=info

# Several 1-CPU jobs side by side; memory is not tracked.
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
# In practice jobs are started by the periodic passes, not at submit or
# completion time, so make both passes run every second (defaults: 60 s main,
# 30 s backfill, plus up to 3 s batching delay). A job then starts within
# about 1 s of becoming eligible.
SchedulerParameters=batch_sched_delay=0,sched_interval=1,bf_interval=1,sched_min_interval=0

ReturnToService=2
JobRequeue=1
MinJobAge=5
KillWait=5
InactiveLimit=0
SlurmdTimeout=60
SlurmctldTimeout=60
MessageTimeout=10

NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem_mb State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
    : >"$dir/plugstack.conf"
    export SLURM_CONF=$dir/slurm.conf

    # --- slurm daemons -------------------------------------------------------
    # -D keeps them in the foreground as our children: $! is the real pid
    # (no pid-file race) and stop can reap them. -c: never recover state.
    _slurm_cluster_spawn slurmctld slurmctld -D -c -f "$SLURM_CONF"
    _slurm_cluster_spawn slurmd slurmd -D -N "$node" -f "$SLURM_CONF"

    deadline=$(( SECONDS + SLURM_CLUSTER_START_TIMEOUT ))
    local state="" name
    while :; do
        state=$(sinfo -h -n "$node" -o %T 2>/dev/null || true)
        [[ $state == idle ]] && return 0
        for name in munged slurmctld slurmd; do
            if ! _slurm_cluster_alive "$(_slurm_cluster_pid $name)"; then
                _slurm_cluster_log "$name exited during start-up"
                _slurm_cluster_dump_logs; slurm_cluster_stop; return 1
            fi
        done
        if (( SECONDS >= deadline )); then
            _slurm_cluster_log "node $node not idle after ${SLURM_CLUSTER_START_TIMEOUT}s (state: '$state')"
            scontrol show node "$node" >&2 || true
            _slurm_cluster_dump_logs; slurm_cluster_stop; return 1
        fi
        sleep 0.2
    done
}

# slurm_cluster_stop
#   Cancel remaining jobs, stop slurmd, slurmctld and munged, and kill any job
#   processes left behind. Idempotent, never fails: fit for an EXIT trap.
slurm_cluster_stop() {
    [[ -n $SLURM_CLUSTER_DIR && -d $SLURM_CLUSTER_DIR/run ]] || return 0
    local conf=$SLURM_CLUSTER_DIR/slurm.conf

    # slurmd and slurmctld exit on SIGTERM but leave running jobs (their
    # slurmstepd) alive, so cancel jobs while the daemons can still act on it.
    if _slurm_cluster_alive "$(_slurm_cluster_pid slurmctld)"; then
        local jobs
        jobs=$(SLURM_CONF=$conf timeout 10 squeue -h -o %A 2>/dev/null || true)
        if [[ -n $jobs ]]; then
            # shellcheck disable=SC2086 # one job id per word
            SLURM_CONF=$conf timeout 10 scancel $jobs 2>/dev/null || true
            local deadline=$(( SECONDS + 10 ))
            while [[ -n $(SLURM_CONF=$conf timeout 10 squeue -h -o %A 2>/dev/null || true) ]] \
                  && (( SECONDS < deadline )); do
                sleep 0.2
            done
        fi
    fi

    _slurm_cluster_kill slurmd
    _slurm_cluster_kill slurmctld
    _slurm_cluster_kill munged

    # Backstop for job processes that survived the above (e.g. slurmd died
    # first): anything started by our slurmd carries our SLURM_CONF in its
    # environment, and job processes also carry SLURM_JOB_ID. Do not match
    # on SLURM_CONF alone: the calling test script has it too.
    local p comm
    for p in /proc/[0-9]*; do
        [[ ${p#/proc/} == "$$" || ${p#/proc/} == "${BASHPID:-}" ]] && continue
        grep -qzxF "SLURM_CONF=$conf" "$p/environ" 2>/dev/null || continue
        comm=""
        { read -r comm <"$p/comm"; } 2>/dev/null || true
        if [[ $comm == slurmstepd ]] || grep -qz '^SLURM_JOB_ID=' "$p/environ" 2>/dev/null; then
            kill -KILL "${p#/proc/}" 2>/dev/null || true
        fi
    done
    return 0
}

# slurm_wait_jobs [-t TIMEOUT_S] JOBID...
#   Wait until none of the given jobs is pending, running, completing or
#   otherwise unfinished. A job-array id covers all its tasks. Default
#   timeout 120 s. Returns 1 and names the leftover jobs on timeout.
#   Says nothing about success; check the jobs' outputs for that.
slurm_wait_jobs() {
    local timeout=120
    if [[ ${1:-} == -t ]]; then
        timeout=${2:?slurm_wait_jobs: -t needs a value}; shift 2
    fi
    (( $# > 0 )) || { _slurm_cluster_log "usage: slurm_wait_jobs [-t TIMEOUT_S] JOBID..."; return 1; }

    local want=" $* " deadline=$(( SECONDS + timeout )) out left
    while :; do
        # Without -t, squeue lists exactly the unfinished jobs (pending,
        # running, completing, suspended, ...). %A is the job's own id, %F the
        # array's id (= %A for plain jobs). A failing squeue (controller
        # busy or gone) must not be mistaken for "queue empty".
        if out=$(squeue -h -o '%A %F %i %T' 2>/dev/null); then
            left=$(while read -r a f i t; do
                       if [[ $want == *" $a "* || $want == *" $f "* ]]; then
                           printf '%s(%s) ' "$i" "$t"
                       fi
                   done <<<"$out")
            [[ -z $left ]] && return 0
        else
            left="(squeue is failing)"
        fi
        if (( SECONDS >= deadline )); then
            _slurm_cluster_log "still unfinished after ${timeout}s: $left"
            return 1
        fi
        sleep 0.5
    done
}
