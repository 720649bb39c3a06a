#!/usr/bin/env bash
# A one-machine Slurm cluster of Debian's slurm-wlm and munge, in a folder of
# its own: sourced by the Slurm tests, which call start_slurm FOLDER, then
# submit with sbatch (SLURM_CONF points at its configuration), then
# stop_slurm. Nothing outside FOLDER is written, and the daemons listen on
# ports free when it starts. Where the daemons cannot start, start_slurm
# prints why and returns 1 (the test then reports itself skipped).

free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }

start_slurm() {
  local dir=$1
  SLURM_DIR=$dir
  mkdir -p "$dir/state" "$dir/spool" "$dir/munge" "$dir/log"
  chmod 700 "$dir/munge"
  # munge's key: 1 KiB of random bytes, readable by its owner alone.
  head -c 1024 /dev/urandom > "$dir/munge/munge.key"
  chmod 400 "$dir/munge/munge.key"
  # A socket's path holds at most 107 bytes: a short folder of its own.
  SLURM_MUNGE_SOCKET_DIR=$(mktemp -d /tmp/umbra-munge.XXXXXX)
  local munge_socket="$SLURM_MUNGE_SOCKET_DIR/socket"
  if ! munged --force --socket="$munge_socket" --key-file="$dir/munge/munge.key" --pid-file="$dir/munge/munged.pid" \
       --log-file="$dir/log/munged.log" --seed-file="$dir/munge/munged.seed" 2> "$dir/log/munged.stderr"; then
    echo "munged could not start: $(cat "$dir/log/munged.stderr" "$dir/log/munged.log" 2>/dev/null | tail -3)"
    return 1
  fi
  local host user cpus memory
  host=$(hostname -s)
  user=$(id -un)
  cpus=$(nproc)
  memory=$(($(awk '/MemTotal/ {print $2}' /proc/meminfo) / 2048))  # half the machine's, in MiB
  export SLURM_CONF="$dir/slurm.conf"
  cat > "$SLURM_CONF" <<CONF
ClusterName=umbratest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$munge_socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=umbra Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
  echo "" > "$dir/cgroup.conf"
  if ! slurmctld -f "$SLURM_CONF" 2> "$dir/log/slurmctld.stderr"; then
    echo "slurmctld could not start: $(tail -3 "$dir/log/slurmctld.stderr" "$dir/log/slurmctld.log" 2>/dev/null)"
    stop_slurm
    return 1
  fi
  if ! slurmd -f "$SLURM_CONF" 2> "$dir/log/slurmd.stderr"; then
    echo "slurmd could not start: $(tail -3 "$dir/log/slurmd.stderr" "$dir/log/slurmd.log" 2>/dev/null)"
    stop_slurm
    return 1
  fi
  # Up when the node takes work: idle within a few seconds.
  local waited
  for waited in $(seq 1 60); do
    if sinfo -h -N -o %t 2>/dev/null | grep -q idle; then return 0; fi
    sleep 0.5
  done
  echo "the Slurm node did not come up in 30 s: $(sinfo -h -N -o '%t %E' 2>&1 | head -1); $(tail -3 "$dir/log/slurmd.log" 2>/dev/null)"
  stop_slurm
  return 1
}

stop_slurm() {
  local dir=$SLURM_DIR pidfile
  # The daemons by their configuration's path (a pid file is written late),
  # then munge.
  pkill -f -- "-f $dir/slurm.conf" 2>/dev/null
  for pidfile in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
    [ -s "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null
  done
  [ -n "${SLURM_MUNGE_SOCKET_DIR:-}" ] && rm -rf "$SLURM_MUNGE_SOCKET_DIR"
  return 0
}
