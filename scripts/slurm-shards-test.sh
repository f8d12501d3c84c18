#!/usr/bin/env bash
# A real single-node Slurm cluster bakes a batch as a job array of 4 shards (`vlit bake --shard
# auto`), and every input must be baked exactly once (docs/batch-sharding.md).
#
# Starts its own munged (private key and socket), slurmctld and slurmd from a generated slurm.conf
# in a temporary directory, submits `sbatch --array=1-4` (tasks numbered from 1, so that
# SLURM_ARRAY_TASK_MIN is exercised), waits, checks the outputs and the merged manifests, and stops
# the daemons it started (by their pid). Needs root (slurmd runs jobs as root here) and the Debian
# packages slurm-wlm and munge; without them it prints a notice and exits 0.
# Usage: scripts/slurm-shards-test.sh [path/to/vlit]   (default build/release/vlit)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
vlit=$(realpath "${1:-build/release/vlit}")
for tool in munged slurmctld slurmd sbatch squeue; do
  if ! command -v "$tool" >/dev/null 2>&1 && [[ ! -x /usr/sbin/$tool ]]; then
    echo "slurm-shards-test: skipped: $tool not found (apt-get install slurm-wlm munge)" >&2
    exit 0
  fi
done
if [[ $(id -u) != 0 ]]; then
  echo "slurm-shards-test: skipped: needs root to run slurmd" >&2
  exit 0
fi
[[ -x $vlit ]] || { echo "slurm-shards-test: no vlit at $vlit (build first)" >&2; exit 2; }
PATH=$PATH:/usr/sbin

work=$(mktemp -d /tmp/vlit-slurm.XXXXXX)
chmod 755 "$work"
pids=()
cleanup() {
  local status=$?
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  if [[ $status != 0 ]]; then
    echo "slurm-shards-test: FAILED; daemon logs:" >&2
    tail -n 20 "$work"/*.log >&2 2>/dev/null || true
  fi
  rm -rf "$work"
  exit $status
}
trap cleanup EXIT

# munge, with a key and a socket of its own.
mkdir -p "$work/munge"
chmod 755 "$work/munge"  # munged wants its socket directory searchable by all
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
munged --foreground --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
  --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/seed" --log-file="$work/munged.log" >"$work/munged.stderr" 2>&1 &
pids+=($!)

# Free TCP ports for the two daemons.
port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])' 2>/dev/null ||
         echo $((20000 + RANDOM % 20000)); }
host=$(hostname -s)
cpus=$(nproc)
mkdir -p "$work/state" "$work/spool" "$work/out" "$work/jobs"
cat >"$work/slurm.conf" <<CONF
ClusterName=vlit-test
SlurmctldHost=$host
SlurmctldPort=$(port)
SlurmdPort=$(port)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/pgid
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=batch Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
for i in $(seq 50); do [[ -S $work/munge/munge.socket ]] && break; sleep 0.1; done
slurmctld -D -c -f "$SLURM_CONF" >"$work/slurmctld.stderr" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$work/slurmd.stderr" 2>&1 &
pids+=($!)
for i in $(seq 100); do
  sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)' && break
  sleep 0.2
done
sinfo -h -o %t | grep -qE '^(idle|mix|alloc)' || { echo "slurm-shards-test: the node did not come up" >&2; exit 1; }

# The batch: 40 assets, the same names in different folders.
scripts/make-shard-batch.sh "$work/in" 40
expected=$(cd "$work/in" && find . -name '*.glb' | sed 's|^\./||' | sort)

# The job array: tasks 1..4 are shards 0/4 .. 3/4 (index = SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN).
# The batch script of docs/batch-sharding.md, with this test's paths.
cat >"$work/bake-shards.sbatch" <<SCRIPT
#!/bin/bash
#SBATCH --array=1-4
#SBATCH --cpus-per-task=1
#SBATCH --output=$work/jobs/%A_%a.out
export OMP_NUM_THREADS=\$SLURM_CPUS_PER_TASK
exec '$vlit' bake '$work/in' -o '$work/out' --shard auto --skip-existing \\
  --manifest "$work/jobs/manifest-\$SLURM_ARRAY_TASK_ID.jsonl"
SCRIPT
job=$(sbatch --parsable "$work/bake-shards.sbatch")
echo "slurm-shards-test: submitted job array $job (4 tasks)"
for i in $(seq 300); do
  [[ -z $(squeue -h -j "$job" 2>/dev/null) ]] && break
  sleep 0.2
done
[[ -z $(squeue -h -j "$job") ]] || { echo "slurm-shards-test: the job array did not finish within 60 s" >&2; exit 1; }

cat "$work"/jobs/*.out
manifests=("$work"/jobs/manifest-*.jsonl)
[[ ${#manifests[@]} == 4 ]] || { echo "slurm-shards-test: expected 4 manifests, found ${#manifests[@]}" >&2; exit 1; }
summary=$("$vlit" manifest-summary "${manifests[@]}")
echo "$summary"
grep -q "^40 inputs in 40 records; shards 0/4 1/4 2/4 3/4$" <<<"$summary"
grep -q "^baked 40, skipped 0, failed 0, interrupted 0$" <<<"$summary"
if grep -q "baked more than once" <<<"$summary"; then echo "slurm-shards-test: an input was baked twice" >&2; exit 1; fi
actual=$(cd "$work/out" && find . -name '*.glb' | sed 's|^\./||' | sort)
[[ $actual == "$expected" ]] || { echo "slurm-shards-test: outputs differ from inputs" >&2; diff <(echo "$expected") <(echo "$actual") >&2; exit 1; }
for out in "$work"/jobs/*_*.out; do grep -q "^shard [0-3]/4 from SLURM_ARRAY_TASK_ID=" "$out"; done
echo "slurm-shards-test: OK: 4 Slurm array tasks baked each of 40 inputs exactly once"
