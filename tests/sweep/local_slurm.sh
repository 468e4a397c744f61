#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for the sweep's Slurm test (docs/sweeps.md):
#   local_slurm.sh start STATE_DIR   configure and start munged, slurmctld and slurmd with every
#                                    file inside STATE_DIR, wait until the node is idle, and print
#                                    the line to eval: export SLURM_CONF=STATE_DIR/slurm.conf
#   local_slurm.sh stop STATE_DIR    stop those daemons (by their pid files; idempotent)
# Nothing in /etc, /run or /var and no system service is read or touched, so it runs on a fresh
# machine where the Debian packages (slurm-wlm and munge, i.e. slurmctld, slurmd, slurm-client,
# munge; tools/setup.sh) are installed but nothing is configured or running, and next to a system
# Slurm if there is one (own ports, own munge socket and key).
# Exit 77 (the "skipped" code of CTest's SKIP_RETURN_CODE) when the programs are missing or the
# cluster does not come up, with a one-line reason on stderr; the logs stay in STATE_DIR.
# No accounting: finished jobs (and the state of failed array tasks) are visible through
# `squeue -t all` or `scontrol show job` for MinJobAge (10 minutes) after they end; sacct is not.
set -u
# slurmctld, slurmd and munged live in /usr/sbin, which is not on an ordinary user's PATH.
PATH=$PATH:/usr/sbin:/sbin

usage() { echo "usage: $0 start|stop STATE_DIR" >&2; exit 2; }
skip() { echo "local_slurm: $*" >&2; exit 77; }

action=${1:-}
[ -n "${2:-}" ] || usage
case $action in start | stop) ;; *) usage ;; esac
if [ "$action" = stop ] && [ ! -d "$2" ]; then exit 0; fi
mkdir -p "$2" || skip "cannot create $2"
state=$(cd "$2" && pwd -P)

# True while PID is a live (not zombie) process whose command line names STATE_DIR: a stale pid
# file then never makes us signal an unrelated process that happens to have the same pid.
ours() {
  local pid=$1
  [[ $pid =~ ^[0-9]+$ ]] && [ -r "/proc/$pid/cmdline" ] || return 1
  tr '\0' ' ' <"/proc/$pid/cmdline" | grep -qF "$state/" || return 1
  [ "$(sed 's/.*) //' "/proc/$pid/stat" 2>/dev/null | cut -d' ' -f1)" != Z ]
}

# SIGTERM the daemon of STATE_DIR/NAME.pid and wait until it is gone (SIGKILL after 10 s), so
# its port and socket are free when this returns.
stop_daemon() {
  local pidfile="$state/$1.pid" pid
  [ -f "$pidfile" ] || return 0
  pid=$(cat "$pidfile" 2>/dev/null)
  if ours "$pid"; then
    kill -TERM "$pid" 2>/dev/null
    for _ in $(seq 50); do ours "$pid" || break; sleep 0.2; done
    ours "$pid" && kill -KILL "$pid" 2>/dev/null
  fi
  rm -f "$pidfile"
}

# munged last: the Slurm daemons may still talk to it while shutting down.
stop_all() {
  stop_daemon slurmd
  stop_daemon slurmctld
  stop_daemon munged
  return 0
}

if [ "$action" = stop ]; then
  stop_all
  exit 0
fi

for program in munged munge unmunge slurmctld slurmd sbatch sinfo squeue; do
  command -v "$program" >/dev/null || skip "$program not installed (Debian: slurm-wlm, munge)"
done
# A second start on the same folder begins afresh instead of finding its ports taken.
stop_all
mkdir -p "$state/ctld" "$state/spool" || skip "cannot write to $state"

user=$(id -un)
host=$(hostname -s)
cpus=$(nproc)
# RealMemory must not exceed what slurmd finds, or the node is drained; a fifth under what is
# available now leaves room for whatever else runs on the machine.
memory=$(awk '/^MemAvailable:/ { print int($2 / 1024 * 0.8) }' /proc/meminfo)

# Two free TCP ports, chosen at random so that clusters started at once (ctest -j, two
# checkouts) and a system Slurm on 6817/6818 do not collide. A port is free when connecting
# to it is refused.
port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
ctld_port=
for _ in $(seq 20); do
  p=$((20000 + RANDOM % 20000))
  if port_free "$p" && port_free "$((p + 1))"; then ctld_port=$p; break; fi
done
[ -n "$ctld_port" ] || skip "found no two free TCP ports"

# munge: a fresh key and a daemon of our own on a socket in STATE_DIR (Slurm finds it through
# AuthInfo). The key must be readable by its owner only, or munged refuses it. --force lets
# munged run where STATE_DIR sits under a world-writable /tmp, which it would otherwise reject.
(umask 077 && head -c 1024 /dev/urandom >"$state/munge.key") || skip "cannot write a munge key"
munged --force --socket="$state/munge.socket" --key-file="$state/munge.key" \
  --pid-file="$state/munged.pid" --log-file="$state/munged.log" \
  --seed-file="$state/munged.seed" 2>>"$state/munged.log" ||
  { stop_all; skip "munged did not start (see $state/munged.log)"; }
munge -n --socket="$state/munge.socket" 2>/dev/null |
  unmunge --socket="$state/munge.socket" >/dev/null 2>&1 ||
  { stop_all; skip "munge credentials do not round-trip (see $state/munged.log)"; }

# The node and the controller are this host, reached on 127.0.0.1 whatever `hostname` resolves
# to (a fresh machine's name may be missing from /etc/hosts or resolve to another interface).
# select/cons_tres with CR_CPU: CPUs are allocated per task; memory is checked against
# RealMemory at submission (so --mem beyond it is refused) but not reserved, which keeps tasks
# from waiting on a memory estimate. proctrack/linuxproc and task/none: no cgroups needed.
# No accounting daemon: accounting_storage/none, jobcomp/none.
# EnforcePartLimits=ALL: a request no node can ever satisfy is refused at sbatch time rather
# than pending forever. MinJobAge=600: finished jobs stay visible for 10 minutes.
# batch_sched_delay=0: array tasks waiting for a free CPU start within a second of one freeing
# (the default 3 s delay made a 3-task array on 2 CPUs take about 3.5 s instead of 1.5 s).
cat >"$state/slurm.conf" <<CONF
ClusterName=localtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$((ctld_port + 1))
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$state/munge.socket
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/slurmctld.log
SlurmdLogFile=$state/slurmd.log
PlugStackConfig=$state/plugstack.conf
MailProg=/bin/true
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
SchedulerParameters=batch_sched_delay=0
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
EnforcePartLimits=ALL
ReturnToService=2
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 NodeHostname=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
# An empty plugin stack, so that nothing from /etc/slurm/plugstack.conf is loaded.
: >"$state/plugstack.conf"
export SLURM_CONF="$state/slurm.conf"

# -c: no state recovered from an earlier run in the same folder.
slurmctld -c -f "$SLURM_CONF" 2>>"$state/slurmctld.log" ||
  { stop_all; skip "slurmctld did not start (see $state/slurmctld.log)"; }
slurmd -N "$host" -f "$SLURM_CONF" 2>>"$state/slurmd.log" ||
  { stop_all; skip "slurmd did not start (see $state/slurmd.log)"; }

# Ready when the controller answers and the node has registered as idle (30 s at most); a
# daemon that died meanwhile ends the wait at once.
for _ in $(seq 150); do
  if [ "$(sinfo -h -n "$host" -o %T 2>/dev/null)" = idle ]; then
    echo "export SLURM_CONF=$SLURM_CONF"
    exit 0
  fi
  for daemon in slurmctld slurmd; do
    [ -f "$state/$daemon.pid" ] && ! ours "$(cat "$state/$daemon.pid")" &&
      { stop_all; skip "$daemon exited during start-up (see $state/$daemon.log)"; }
  done
  sleep 0.2
done
stop_all
skip "node $host not idle within 30 s (see $state/slurmctld.log and slurmd.log)"
