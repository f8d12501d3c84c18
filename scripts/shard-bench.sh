#!/usr/bin/env bash
# Assets per second for a batch of many small assets, and the overhead of sharding: one process
# against N shard processes on this machine (docs/batch-sharding.md, "Measurements").
# Usage: scripts/shard-bench.sh [COUNT [path/to/vlit]]   (default 1000 assets, build/release/vlit)
# The assets are copies of assets/examples/file-lights.glb (954 vertices, lights inside).
set -euo pipefail
cd "$(dirname "$0")/.."
count=${1:-1000}
vlit=$(realpath "${2:-build/release/vlit}")
work=$(mktemp -d /tmp/vlit-shard-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT
scripts/make-shard-batch.sh "$work/in" "$count"
cores=$(nproc)
now() { date +%s.%N; }
report() {  # NAME START END
  awk -v n="$count" -v name="$1" -v a="$2" -v b="$3" \
    'BEGIN { printf "%-44s %7.2f s  %8.1f assets/s\n", name, b - a, n / (b - a) }'
}
echo "$count assets, $cores cores, $("$vlit" --version)"
"$vlit" bake "$work/in" -o "$work/warm" -q  # page cache and binary warm
rm -rf "$work/warm"

t0=$(now); "$vlit" bake "$work/in" -o "$work/one" -q; t1=$(now)
report "1 process, OpenMP on all cores" "$t0" "$t1"
t0=$(now); OMP_NUM_THREADS=1 "$vlit" bake "$work/in" -o "$work/one1" -q; t1=$(now)
report "1 process, 1 thread" "$t0" "$t1"
for shards in 1 2 4 8; do
  rm -rf "$work/sharded"
  t0=$(now)
  for ((i = 0; i < shards; i++)); do
    OMP_NUM_THREADS=1 "$vlit" bake "$work/in" -o "$work/sharded" -q --shard "$i/$shards" &
  done
  wait
  t1=$(now)
  report "$shards shard processes at once, 1 thread each" "$t0" "$t1"
done
t0=$(now); "$vlit" bake "$work/in" -o "$work/one" -q --skip-existing; t1=$(now)
report "re-run with --skip-existing (all current)" "$t0" "$t1"
