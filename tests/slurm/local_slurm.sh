#!/usr/bin/env bash
# A single-node Slurm on localhost for the slurm test (Debian's slurm-wlm and munge):
#   local_slurm.sh start DIR   munge key, munged as user munge, slurmctld and slurmd as root,
#                              a small slurm.conf in DIR; prints the SLURM_CONF path when the
#                              node is idle
#   local_slurm.sh stop DIR    stops the daemons it started (by their pid files), removes DIR
# Needs root (slurmd) and the Debian packages slurm-wlm and munge (scripts/install-deps.sh).
set -euo pipefail
cmd=${1:?start|stop}
DIR=${2:?DIR}
if [[ $cmd == stop ]]; then
  for pid in "$DIR"/slurmd.pid "$DIR"/slurmctld.pid "$DIR"/munge/munged.pid; do
    [[ -f $pid ]] && kill "$(cat "$pid")" 2>/dev/null || true
  done
  for _ in $(seq 50); do  # wait for them to go, so DIR can be removed
    alive=0
    for pid in "$DIR"/slurmd.pid "$DIR"/slurmctld.pid "$DIR"/munge/munged.pid; do
      [[ -f $pid ]] && kill -0 "$(cat "$pid")" 2>/dev/null && alive=1
    done
    ((alive)) || break
    sleep 0.1
  done
  rm -rf "$DIR"
  exit 0
fi
[[ $(id -u) -eq 0 ]] || { echo "local_slurm: needs root (slurmd runs as root)" >&2; exit 1; }
for b in mungekey munged slurmctld slurmd sbatch; do
  command -v "$b" >/dev/null || { echo "local_slurm: $b missing (scripts/install-deps.sh: slurm-wlm munge)" >&2; exit 1; }
done
mkdir -p "$DIR"/munge "$DIR"/state "$DIR"/spool
chmod 755 "$DIR"
mungekey -c -k "$DIR/munge/munge.key" >/dev/null
chown -R munge:munge "$DIR/munge"
chmod 700 "$DIR/munge"
# --force: the temp dir's parents (/tmp) are world-writable, which munged refuses by default.
runuser -u munge -- munged --force --key-file="$DIR/munge/munge.key" --socket="$DIR/munge/munge.socket" \
  --pid-file="$DIR/munge/munged.pid" --log-file="$DIR/munge/munged.log" --seed-file="$DIR/munge/munged.seed"
# Ports from the pid, so two runs on one machine do not collide.
port=$((20000 + ($$ % 20000)))
host=$(hostname -s)
cat > "$DIR/slurm.conf" <<CONF
ClusterName=shadowc-test
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$DIR/munge/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
StateSaveLocation=$DIR/state
SlurmdSpoolDir=$DIR/spool
SlurmctldPidFile=$DIR/slurmctld.pid
SlurmdPidFile=$DIR/slurmd.pid
SlurmctldLogFile=$DIR/slurmctld.log
SlurmdLogFile=$DIR/slurmd.log
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$DIR/slurm.conf
slurmctld -c
slurmd
for _ in $(seq 150); do
  if sinfo -h -o %t 2>/dev/null | grep -q idle; then
    echo "$SLURM_CONF"
    exit 0
  fi
  sleep 0.2
done
echo "local_slurm: the node did not become idle; logs in $DIR" >&2
tail -5 "$DIR"/slurmctld.log "$DIR"/slurmd.log >&2 || true
exit 1
