#!/usr/bin/env bash
# A single-node Slurm on the loopback address for the slurm test (docs/sweep.md "Slurm"):
#   local_slurm.sh start DIR   munge key, munged as user munge, slurmctld and slurmd as root,
#                              a small slurm.conf in DIR; prints the SLURM_CONF path when the
#                              node is idle, or, within START_WAIT_S, what went wrong and the
#                              daemons' last log lines (then the daemons are stopped, DIR kept)
#   local_slurm.sh logs DIR    the node's state and reason and the daemons' last log lines
#   local_slurm.sh stop DIR    stops the daemons it started (by their pid files), removes DIR
# Needs root (slurmd) and the Debian packages slurm-wlm and munge (scripts/install-deps.sh).
# No host name has to resolve: controller and node are addressed as 127.0.0.1, the node is
# named explicitly (slurmd -N). No cgroup file system is needed either (see cgroup.conf below).
set -euo pipefail
cmd=${1:?start|logs|stop}
DIR=${2:?DIR}
# Registration takes about a second on an idle machine; 30 s leaves room for a loaded one and,
# with one sinfo call's bound (SINFO_S) on top, keeps a failed start well under a minute.
START_WAIT_S=30
SINFO_S=5
pids=("$DIR"/slurmd.pid "$DIR"/slurmctld.pid "$DIR"/munge/munged.pid)

stop_daemons() {
  local running=()
  for pid in "${pids[@]}"; do  # read once: munged removes its pid file as it exits
    [[ -f $pid ]] && running+=("$(cat "$pid")")
  done
  ((${#running[@]})) || return 0
  kill "${running[@]}" 2>/dev/null || true
  for _ in $(seq 50); do  # wait for them to go, so DIR can be removed
    local alive=0
    for p in "${running[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
    ((alive)) || break
    sleep 0.1
  done
}

logs() {
  if [[ -f $DIR/slurm.conf ]]; then
    echo "--- node state (sinfo -N -o '%N %T %E')"
    SLURM_CONF=$DIR/slurm.conf timeout "$SINFO_S" sinfo -h -N -o '%N %T %E' 2>&1 || true
  fi
  for log in "$DIR"/munge/munged.log "$DIR"/slurmctld.log "$DIR"/slurmd.log; do
    [[ -f $log ]] || continue
    # A daemon's fatal error can be followed by lines of detail (e.g. its cgroup list).
    if grep -q 'fatal:' "$log"; then
      echo "--- fatal errors in $log"
      grep 'fatal:' "$log" | tail -n 3
    fi
    echo "--- last lines of $log"
    tail -n 8 "$log"
  done
}

fail() {
  echo "local_slurm: $*" >&2
  logs >&2
  stop_daemons
  echo "local_slurm: daemons stopped; their logs are in $DIR" >&2
  exit 1
}

case $cmd in
  stop)
    stop_daemons
    rm -rf "$DIR"
    exit 0
    ;;
  logs)
    logs
    exit 0
    ;;
  start) ;;
  *)
    echo "local_slurm: unknown command '$cmd' (start|logs|stop)" >&2
    exit 2
    ;;
esac

[[ $(id -u) -eq 0 ]] || { echo "local_slurm: needs root (slurmd runs as root)" >&2; exit 1; }
for b in mungekey munged slurmctld slurmd sbatch sinfo; do
  command -v "$b" >/dev/null || { echo "local_slurm: $b missing (scripts/install-deps.sh: slurm-wlm munge)" >&2; exit 1; }
done
mkdir -p "$DIR"/munge "$DIR"/state "$DIR"/spool
chmod 755 "$DIR"
mungekey -c -k "$DIR/munge/munge.key" >/dev/null
chown -R munge:munge "$DIR/munge"
chmod 700 "$DIR/munge"
# --force: the temp dir's parents (/tmp) are world-writable, which munged refuses by default.
runuser -u munge -- munged --force --key-file="$DIR/munge/munge.key" --socket="$DIR/munge/munge.socket" \
  --pid-file="$DIR/munge/munged.pid" --log-file="$DIR/munge/munged.log" --seed-file="$DIR/munge/munged.seed" ||
  fail "munged did not start"
# Ports from the pid, so two runs on one machine do not collide.
port=$((20000 + ($$ % 20000)))
# slurmctld accepts to be the controller only under its own short host name; the address in
# parentheses is what every daemon and client connects to, so the name never has to resolve.
host=$(uname -n)
host=${host%%.*}
cat > "$DIR/slurm.conf" <<CONF
ClusterName=shadowc-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$DIR/munge/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
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
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
# Nothing above tracks or confines jobs with cgroups (proctrack/linuxproc, task/none,
# jobacct_gather/none), yet slurmd and slurmstepd load a cgroup plugin at start. The default,
# autodetect, fails where no cgroup file system is mounted ("can't stat /sys/fs/cgroup/systemd/:
# No such file or directory", "Unable to initialize cgroup plugin"), and its v2 choice moves
# slurmd into a cgroup scope of its own (through systemd where there is one). The v1 plugin's
# start-up only sets up empty lists, so naming it works with any cgroup set-up or none.
echo "CgroupPlugin=cgroup/v1" > "$DIR/cgroup.conf"
export SLURM_CONF=$DIR/slurm.conf
slurmctld -c || fail "slurmctld did not start"
slurmd -N "$host" || fail "slurmd did not start"
state=
while ((SECONDS < START_WAIT_S)); do
  state=$(timeout "$SINFO_S" sinfo -h -n "$host" -o %t 2>&1 || true)
  [[ $state == idle ]] && { echo "$SLURM_CONF"; exit 0; }
  sleep 0.2
done
fail "the node did not become idle within ${START_WAIT_S} s (last state: ${state:-none})"
