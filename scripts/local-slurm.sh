#!/usr/bin/env bash
# A single-node Slurm on this machine, for the farm's tests and for trying
# whitted-farm without a cluster: munged with its own key, slurmctld
# and one slurmd, all from Debian's packages (slurmctld slurmd slurm-client
# munge), without systemd, as root or as a normal user.
#
#   scripts/local-slurm.sh start    start the daemons (if not already up) and
#                                   wait until the node takes jobs
#   scripts/local-slurm.sh stop     stop them (nothing running is fine)
#   scripts/local-slurm.sh status   exit 0 and say so when the node is up
#   scripts/local-slurm.sh env      print the variable its clients need:
#                                   eval "$(scripts/local-slurm.sh env)"
#
# Everything lives in $WHITTED_SLURM_DIR (default /tmp/whitted-slurm-$USER):
# configuration, key, sockets, state, logs. Safe to re-run; `start` after a
# crash starts afresh. Ports: $WHITTED_SLURM_PORT and the one after it
# (default 16817).
#
# Settings measured with Slurm 22.05: proctrack/linuxproc,
# task/none and jobacct_gather/none need no cgroups or systemd; the scheduler
# runs every second, so an array job and a job depending on it finish about 5
# s after they are submitted; kill_invalid_depend cancels a job whose
# dependency failed, which otherwise stays pending for ever; finished jobs
# stay visible to `scontrol show job` for MinJobAge seconds.
set -euo pipefail

dir=${WHITTED_SLURM_DIR:-/tmp/whitted-slurm-$(id -un)}
port=${WHITTED_SLURM_PORT:-16817}
conf=$dir/slurm.conf
node=$(hostname -s)
user=$(id -un)

say() { echo "local-slurm: $*" >&2; }

running() {  # running PIDFILE: the daemon of that pid file is alive
    local pid
    pid=$(cat "$1" 2>/dev/null) && kill -0 "$pid" 2>/dev/null
}

up() {  # the controller answers and the node is idle, mixed or allocated
    [[ -f $conf ]] || return 1
    SLURM_CONF=$conf scontrol ping 2>/dev/null | grep -q "is UP" || return 1
    local state
    state=$(SLURM_CONF=$conf sinfo -h -N -n "$node" -o %T 2>/dev/null || true)
    [[ $state =~ ^(idle|mixed|allocated|completing) ]]
}

write_config() {
    mkdir -p "$dir"/{state,spool,log}
    chmod 700 "$dir"
    local cpus memory
    cpus=$(nproc)
    memory=$(awk '/MemTotal/ { print int($2 / 1024 * 0.9) }' /proc/meminfo)
    cat >"$conf" <<EOF
# Written by scripts/local-slurm.sh; rewritten on every start.
ClusterName=whitted-local
SlurmctldHost=localhost
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/log/jobcomp.log
SchedulerType=sched/backfill
SchedulerParameters=batch_sched_delay=0,sched_interval=1,bf_interval=1
DependencyParameters=kill_invalid_depend
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MinJobAge=120
ReturnToService=2
MpiDefault=none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
}

start_munge() {
    running "$dir/munged.pid" && return 0
    if [[ ! -f $dir/munge.key ]]; then
        dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
        chmod 600 "$dir/munge.key"
    fi
    # --force: munged refuses sockets in a directory others can reach (/tmp).
    munged --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
        --pid-file="$dir/munged.pid" --log-file="$dir/log/munged.log" \
        --seed-file="$dir/munged.seed"
}

start() {
    if up; then
        say "already up ($conf)"
        return 0
    fi
    for tool in munged slurmctld slurmd scontrol sinfo sbatch; do
        command -v "$tool" >/dev/null || {
            say "$tool is missing: apt-get install slurmctld slurmd slurm-client munge"
            exit 1
        }
    done
    stop_daemons quiet
    write_config
    start_munge
    # -c: no state from an earlier run (its jobs, its node's last state).
    SLURM_CONF=$conf slurmctld -c -f "$conf"
    SLURM_CONF=$conf slurmd -c -N "$node" -f "$conf"
    for _ in $(seq 1 60); do
        if up; then
            say "up: node $node, partition local ($conf)"
            return 0
        fi
        sleep 0.5
    done
    say "the node did not come up in 30 s; logs in $dir/log:"
    tail -n 20 "$dir"/log/*.log >&2 || true
    exit 1
}

stop_daemons() {
    local name
    for name in slurmd slurmctld munged; do
        local pidfile=$dir/$name.pid
        local pid
        pid=$(cat "$pidfile" 2>/dev/null) || continue
        kill "$pid" 2>/dev/null || true
        for _ in $(seq 1 50); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.1
        done
        if kill -0 "$pid" 2>/dev/null; then kill -9 "$pid" 2>/dev/null || true; fi
        rm -f "$pidfile"
    done
    [[ ${1:-} == quiet ]] || say "stopped"
}

case "${1:-}" in
start) start ;;
stop) stop_daemons ;;
status)
    if up; then
        say "up: node $node ($conf)"
    else
        say "down"
        exit 1
    fi
    ;;
env) echo "export SLURM_CONF=$(printf '%q' "$conf")" ;;
*)
    echo "usage: $0 start|stop|status|env" >&2
    exit 2
    ;;
esac
