#!/usr/bin/env bash
# A study on a real Slurm: starts a one-node cluster on this machine (munge,
# slurmctld and slurmd on loopback, proctrack/linuxproc, task/none, all
# state, spool, logs and sockets in a temporary folder), then
#  A. `study slurm --submit` of tests/slurm/small.toml as a job array of 3
#     shards and its collect job; waits; the tables equal a local `study run`;
#  B. the same study again, one array task at a time (`--array=1-3%1`, so
#     the first task's checkpoints are its own); kills task 1 midway; the
#     collect job (afterany) then fails and lists the missing runs, and
#     `study status` names the task to submit again; resubmits it and the
#     collect; the study completes, continuing the killed runs from their
#     checkpoints, and the tables equal the local run's;
#  C. `study slurm --submit` into an output folder named with `%a`: the
#     scripts double the `%`, so the logs and tables land in that folder.
# Every daemon it started is stopped by its process id when it exits.
# Needs root (slurmd runs the jobs), slurm-wlm, munge, python3 with pyarrow,
# and a built `study` (STUDY=path, default $CARGO_TARGET_DIR/release/study).
# KEEP=1 keeps the temporary folder.
set -euo pipefail
cd "$(dirname "$0")/../.."
STUDY=$(realpath -m "${STUDY:-${CARGO_TARGET_DIR:-target}/release/study}")
for tool in munged mungekey slurmctld slurmd sbatch squeue scontrol sinfo scancel; do
  command -v "$tool" >/dev/null || { echo "run.sh: $tool is missing (apt-get install slurm-wlm munge)" >&2; exit 2; }
done
[ -x "$STUDY" ] || { echo "run.sh: no study binary at $STUDY (cargo build --release)" >&2; exit 2; }

T=$(mktemp -d /tmp/bonkers-slurm.XXXXXX)
pids=()
say() { echo "slurm test: $*"; }
cleanup() {
  local code=$?
  set +e
  if [ -n "${SLURM_CONF:-}" ] && [ -f "$SLURM_CONF" ]; then
    scancel --quiet --user=root 2>/dev/null
    for _ in $(seq 50); do [ -z "$(squeue -h 2>/dev/null)" ] && break; sleep 0.2; done
  fi
  # Newest first: slurmd, slurmctld, munged.
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
    kill "${pids[i]}" 2>/dev/null && wait "${pids[i]}" 2>/dev/null
  done
  if [ "$code" != 0 ]; then
    for log in "$T"/*.log "$T"/*.out "$T"/*/slurm/*.log; do
      [ -f "$log" ] && { echo "--- $log"; tail -n 30 "$log"; }
    done
  fi
  if [ "${KEEP:-0}" = 1 ]; then say "kept $T"; else rm -rf "$T"; fi
  exit "$code"
}
trap cleanup EXIT

# munge: its own key, socket and files.
mkdir -m 0700 "$T/munge"
mungekey --create --keyfile="$T/munge/munge.key"
munged --foreground --force --socket="$T/munge/munge.socket" --key-file="$T/munge/munge.key" \
  --pid-file="$T/munge/munged.pid" --log-file="$T/munged.log" --seed-file="$T/munge/munged.seed" \
  >>"$T/munged.out" 2>&1 &
pids+=($!)

free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
host=$(hostname -s)
cpus=$(nproc)
mkdir -p "$T/state" "$T/spool"
export SLURM_CONF="$T/slurm.conf"
cat > "$SLURM_CONF" <<CONF
ClusterName=bonkers-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$T/munge/munge.socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/slurmctld.pid
SlurmdPidFile=$T/slurmd.pid
SlurmctldLogFile=$T/slurmctld.log
SlurmdLogFile=$T/slurmd.log
SlurmdParameters=config_overrides
ReturnToService=2
KillWait=2
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
for _ in $(seq 50); do [ -S "$T/munge/munge.socket" ] && break; sleep 0.1; done
slurmctld -D -i -f "$SLURM_CONF" >>"$T/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$host" >>"$T/slurmd.out" 2>&1 &
pids+=($!)

# Wait until the shell test `check` holds, at most `seconds`.
wait_for() {
  local what=$1 seconds=$2 check=$3
  for _ in $(seq $((seconds * 5))); do
    eval "$check" && return 0
    sleep 0.2
  done
  echo "run.sh: timed out after ${seconds}s waiting for $what" >&2
  exit 1
}
wait_for "the node to be idle" 60 '[ "$(sinfo -h -o %T 2>/dev/null)" = idle ]'
say "a one-node Slurm is up ($host, $cpus CPUs)"

job_state() { scontrol show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort -u | tr '\n' ' ' | sed 's/ $//'; }
jobs_done() { [ -z "$(squeue -h -j "$1" 2>/dev/null)" ]; }

small=tests/slurm/small.toml
"$STUDY" run "$small" --out "$T/local" --threads "$cpus" --quiet
say "local run done"

# A: submitted by study slurm --submit.
"$STUDY" slurm "$small" --shards 3 --out "$T/a" --submit | tee "$T/a.txt"
read -r array collect < <(sed -n 's/^submitted: array job \([0-9]*\) .* collect job \([0-9]*\) after it$/\1 \2/p' "$T/a.txt")
wait_for "jobs $array and $collect" 150 "jobs_done $array,$collect"
[ "$(job_state "$collect")" = COMPLETED ] || { echo "collect job: $(job_state "$collect")" >&2; exit 1; }
[ "$(job_state "$array")" = COMPLETED ] || { echo "array job: $(job_state "$array")" >&2; exit 1; }
python3 tests/slurm/compare.py "$T/local" "$T/a"
say "A: the job array and its collect gave the local run's tables"

# B: one task at a time; kill task 1 once it has saved a checkpoint.
"$STUDY" slurm "$small" --shards 3 --out "$T/b" --checkpoint-every 0.05 > "$T/b.txt"
array=$(sbatch --parsable --array=1-3%1 "$T/b/slurm/shards.sbatch")
array=${array%%;*}
collect=$(sbatch --parsable --dependency=afterany:"$array" "$T/b/slurm/collect.sbatch")
wait_for "a checkpoint of task 1" 120 \
  '[ -n "$(squeue -h -j "${array}_1" -t RUNNING 2>/dev/null)" ] && compgen -G "$T/b/runs/run-*.ckpt" >/dev/null'
scancel "${array}_1"
say "B: killed array task ${array}_1 midway"
wait_for "jobs $array and $collect" 150 "jobs_done $array,$collect"
[ "$(job_state "$collect")" = FAILED ] || { echo "collect job after the kill: $(job_state "$collect")" >&2; exit 1; }
grep -q "have no usable record" "$T/b/slurm/collect.log"
grep -q "resubmit them with \`sbatch --array=1 $T/b/slurm/shards.sbatch\`" "$T/b/slurm/collect.log"
[ ! -e "$T/b/runs.parquet" ]
"$STUDY" status "$T/b"
again=$(sbatch --parsable --array=1 "$T/b/slurm/shards.sbatch")
again=${again%%;*}
collect=$(sbatch --parsable --dependency=afterany:"$again" "$T/b/slurm/collect.sbatch")
wait_for "jobs $again and $collect" 150 "jobs_done $again,$collect"
[ "$(job_state "$collect")" = COMPLETED ] || { echo "collect job after resubmitting: $(job_state "$collect")" >&2; exit 1; }
grep "continued from their checkpoints" "$T/b/slurm/shard-1.log"
"$STUDY" status "$T/b" | grep -q "done: 6, failed: 0, pending: 0"
python3 tests/slurm/compare.py "$T/local" "$T/b"
say "B: after resubmitting the killed task the study completed with the local run's tables"

# C: an output folder whose name has `%a` in it: the scripts double the `%`
# in `#SBATCH --output=`, so sbatch writes the logs into that folder.
pct="$T/c%a"
"$STUDY" slurm "$small" --shards 1 --out "$pct" --submit | tee "$T/c.txt"
read -r array collect < <(sed -n 's/^submitted: array job \([0-9]*\) .* collect job \([0-9]*\) after it$/\1 \2/p' "$T/c.txt")
wait_for "jobs $array and $collect" 150 "jobs_done $array,$collect"
[ "$(job_state "$collect")" = COMPLETED ] || { echo "collect job (C): $(job_state "$collect")" >&2; exit 1; }
[ -s "$pct/slurm/shard-1.log" ]
[ -s "$pct/slurm/collect.log" ]
[ ! -e "$T/c1" ]
python3 tests/slurm/compare.py "$T/local" "$pct"
say "C: an output folder named with % got its logs and the local run's tables"
say "ok"
