#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for the sweep's Slurm test (docs/sweeps.md):
#   local_slurm.sh start STATE_DIR   configure and start munged, slurmctld and slurmd with every
#                                    file inside STATE_DIR; prints the SLURM_CONF line to export
#   local_slurm.sh stop STATE_DIR    stop them (idempotent)
# Nothing in /etc or system services is touched, so it runs on a fresh machine where the Debian
# packages (slurm-wlm, munge; tools/setup.sh --slurm) are installed but nothing is configured.
# Exit 77 (the "skipped" code of CTest's SKIP_RETURN_CODE) when the programs are missing or the
# cluster does not come up, with the reason on stderr.
set -u
action=${1:-}
state=${2:-}
[ -n "$action" ] && [ -n "$state" ] || { echo "usage: $0 start|stop STATE_DIR" >&2; exit 2; }

skip() { echo "local_slurm: $*" >&2; exit 77; }

stop() {
  for daemon in slurmd slurmctld; do
    [ -f "$state/$daemon.pid" ] && kill "$(cat "$state/$daemon.pid")" 2>/dev/null
  done
  [ -S "$state/munge.socket" ] && munged --socket="$state/munge.socket" --stop >/dev/null 2>&1
  [ -f "$state/munged.pid" ] && kill "$(cat "$state/munged.pid")" 2>/dev/null
  return 0
}

if [ "$action" = stop ]; then
  stop
  exit 0
fi
[ "$action" = start ] || { echo "usage: $0 start|stop STATE_DIR" >&2; exit 2; }

for program in munged mungekey slurmctld slurmd sbatch sinfo; do
  command -v "$program" >/dev/null || skip "$program not installed (Debian: slurm-wlm, munge)"
done
state=$(mkdir -p "$state" && cd "$state" && pwd)
mkdir -p "$state/spool" "$state/ctld"
user=$(id -un)
host=$(hostname -s)
cpus=$(nproc)
# RealMemory a little under what is free, so slurmd accepts the node.
memory=$(awk '/MemAvailable/ { print int($2 / 1024 * 0.8) }' /proc/meminfo)

# munge: a fresh key and a daemon of our own; Slurm finds its socket through AuthInfo.
mungekey --create --keyfile="$state/munge.key" --force >/dev/null 2>&1 ||
  skip "mungekey could not create a key"
chmod 600 "$state/munge.key"
munged --socket="$state/munge.socket" --key-file="$state/munge.key" \
  --pid-file="$state/munged.pid" --log-file="$state/munged.log" \
  --seed-file="$state/munged.seed" --force 2>>"$state/munged.log" ||
  skip "munged did not start (see $state/munged.log)"

cat >"$state/slurm.conf" <<CONF
ClusterName=tamponade-test
SlurmctldHost=$host
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$state/munge.socket
CredType=cred/munge
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/slurmctld.log
SlurmdLogFile=$state/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
ReturnToService=2
MinJobAge=600
NodeName=$host CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$state/slurm.conf"
slurmctld -f "$SLURM_CONF" 2>>"$state/slurmctld.log" || { stop; skip "slurmctld did not start"; }
slurmd -f "$SLURM_CONF" 2>>"$state/slurmd.log" || { stop; skip "slurmd did not start"; }
for _ in $(seq 60); do
  if sinfo -h -N -o "%T" 2>/dev/null | grep -q idle; then
    echo "export SLURM_CONF=$SLURM_CONF"
    exit 0
  fi
  sleep 0.5
done
stop
skip "the node did not become idle within 30 s (see $state/slurmctld.log, slurmd.log)"
