# shellcheck shell=bash
# A single-machine Slurm of the test's own, sourced by the distributed
# tests: its own munge key and socket, its own slurm.conf on free ports, its
# state, spool, logs and pid files under one temporary folder, daemons run
# as the current user. Never the system's services or configuration.
#
#   slurm_cluster_start DIR   starts munged, slurmctld and slurmd; exports
#                             SLURM_CONF so sbatch, squeue, scancel use them
#   slurm_cluster_stop DIR    stops them by their pid files (call from a trap)

# A TCP port that nothing listens on, from the kernel's tables.
free_port() {
  local port used
  used=$(awk 'NR > 1 && $4 == "0A" { split($2, a, ":"); print strtonum("0x" a[2]) }' \
    /proc/net/tcp /proc/net/tcp6 2>/dev/null)
  while :; do
    port=$((20000 + RANDOM % 20000))
    grep -qx "$port" <<<"$used" || { echo "$port"; return; }
  done
}

# wait_for SECONDS COMMAND...: waits up to SECONDS for COMMAND to succeed.
wait_for() {
  local deadline=$((SECONDS + $1))
  shift
  until "$@" >/dev/null 2>&1; do
    ((SECONDS < deadline)) || return 1
    sleep 0.05
  done
}

slurm_cluster_start() {
  local dir=$1 user node cpus
  user=$(id -un)
  node=$(hostname -s)
  cpus=$(nproc)
  mkdir -p "$dir"/{munge,state,spool,log}
  # The daemons run in sessions of their own; should this shell die without
  # its trap (SIGKILL, a ctest timeout), a watchdog outside its process
  # group stops them.
  setsid bash -c 'while kill -0 "$1" 2>/dev/null; do sleep 1; done; source "$2"; slurm_cluster_stop "$3"' \
    watchdog $$ "${BASH_SOURCE[0]}" "$dir" </dev/null >/dev/null 2>&1 &
  chmod 755 "$dir/munge" # the socket's folder: munged wants it open to all
  head -c 1024 /dev/urandom >"$dir/munge/munge.key"
  chmod 400 "$dir/munge/munge.key"
  # --force: the temporary folder's parents (/tmp) are writable by others.
  munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.sock" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/log/munged.log" \
    --seed-file="$dir/munge/munged.seed" || return 1
  wait_for 10 munge --socket="$dir/munge/munge.sock" --no-input || return 1

  cat >"$dir/slurm.conf" <<CONF
ClusterName=shadelab-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.sock
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
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=1
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$dir/slurm.conf
  slurmctld -i -f "$SLURM_CONF" || return 1
  slurmd -f "$SLURM_CONF" || return 1
  wait_for 30 node_idle
}

no_jobs() {
  local queued
  queued=$(squeue -h) && [[ -z $queued ]]
}

node_idle() {
  [[ $(sinfo -h -N -o %t) == idle ]]
}

slurm_cluster_stop() {
  local dir=$1 pidfile pid
  # Jobs first: their steps outlive slurmd.
  if [[ -s $dir/slurmctld.pid ]]; then
    export SLURM_CONF=$dir/slurm.conf
    scancel --quiet --full --user="$(id -un)" 2>/dev/null &&
      wait_for 20 no_jobs || true
  fi
  for pidfile in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
    [[ -s $pidfile ]] || continue
    pid=$(<"$pidfile")
    kill "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
  done
}
