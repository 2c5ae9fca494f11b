# shellcheck shell=bash
# Sourced by the Slurm tests (issue 31): a one-node Slurm cluster on
# loopback from Debian's packages, started by hand (no systemd as PID 1 on
# these machines), everything in one temporary folder, free ports, no
# accounting. slurm_start DIR starts munged, slurmctld and slurmd and waits
# until the node is idle; slurm_stop cancels what is queued and stops exactly
# those three processes (by the PIDs it started). Clients find the cluster
# through SLURM_CONF, which slurm_start exports.

slurm_packages_missing() { # prints the missing commands
  local c
  for c in munged mungekey munge slurmctld slurmd sbatch squeue scontrol srun; do
    command -v "$c" > /dev/null || printf '%s ' "$c"
  done
}

slurm_free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

slurm_wait() { # slurm_wait SECONDS WHAT COMMAND...: until COMMAND succeeds
  local deadline=$((SECONDS + $1)) what=$2
  shift 2
  until "$@" > /dev/null 2>&1; do
    if [ "$SECONDS" -ge "$deadline" ]; then
      echo "slurm: $what not reached within the time; logs:" >&2
      tail -n 20 "$SLURM_TEST_DIR"/*.log >&2 || true
      return 1
    fi
    sleep 0.1
  done
}

slurm_start() {
  SLURM_TEST_DIR=$1
  SLURM_PIDS=()
  local d=$1 host hardware ctld_port slurmd_port
  mkdir -p "$d/munge" "$d/state" "$d/spool"
  chmod 700 "$d/munge"
  mungekey --create --keyfile="$d/munge/munge.key" --bits=1024
  munged --foreground --force --key-file="$d/munge/munge.key" --socket="$d/munge/socket" \
    --pid-file="$d/munge/munged.pid" --seed-file="$d/munge/seed" --log-file="$d/munged.log" > "$d/munged.out" 2>&1 &
  SLURM_PIDS+=($!)
  slurm_wait 10 "munged" bash -c "munge -S '$d/munge/socket' -n | unmunge -S '$d/munge/socket'"

  host=$(hostname -s) # slurmctld only starts on the host SlurmctldHost names
  # The node as slurmd sees it ("CPUs=2 Boards=1 SocketsPerBoard=1 ..."), so it is not drained as "differs from hardware".
  hardware=$(slurmd -C | head -n 1 | tr ' ' '\n' | grep -E '^(CPUs|Boards|SocketsPerBoard|CoresPerSocket|ThreadsPerCore)=' | tr '\n' ' ')
  ctld_port=$(slurm_free_port)
  slurmd_port=$(slurm_free_port)
  cat > "$d/slurm.conf" << CONF
ClusterName=sreh-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$d/munge/socket
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/slurmctld.log
SlurmdLogFile=$d/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SwitchType=switch/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
SchedulerParameters=batch_sched_delay=0
ReturnToService=2
SlurmdParameters=config_overrides
MinJobAge=60
MailProg=/bin/true
NodeName=$host NodeAddr=127.0.0.1 $hardware State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$d/slurm.conf
  slurmctld -D -i -f "$SLURM_CONF" > "$d/slurmctld.out" 2>&1 &
  SLURM_PIDS+=($!)
  slurmd -D -f "$SLURM_CONF" -N "$host" > "$d/slurmd.out" 2>&1 &
  SLURM_PIDS+=($!)
  slurm_wait 30 "an idle node" bash -c '[ "$(sinfo -h -o %t)" = idle ]'
}

slurm_stop() {
  if [ -n "${SLURM_CONF:-}" ]; then scancel --full --quiet --user="$(id -un)" > /dev/null 2>&1 || true; fi
  local pid i
  for ((i = ${#SLURM_PIDS[@]} - 1; i >= 0; i--)); do # slurmd, slurmctld, then munged
    pid=${SLURM_PIDS[i]}
    kill -TERM "$pid" 2> /dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2> /dev/null || true
    wait "$pid" 2> /dev/null || true
  done
  SLURM_PIDS=()
}
