#!/usr/bin/env bash
# GNU parallel bakes a batch as 4 shards (`vlit bake --shard {}/4`, and `--shard auto` from
# PARALLEL_SEQ), and every input must be baked exactly once (docs/batch-sharding.md). Needs the
# Debian package parallel; without it, prints a notice and exits 0.
# Usage: scripts/parallel-shards-test.sh [path/to/vlit]   (default build/release/vlit)
set -euo pipefail
cd "$(dirname "$0")/.."
vlit=$(realpath "${1:-build/release/vlit}")
if ! command -v parallel >/dev/null 2>&1 || ! parallel --version 2>/dev/null | grep -q "GNU parallel"; then
  echo "parallel-shards-test: skipped: GNU parallel not found (apt-get install parallel)" >&2
  exit 0
fi
[[ -x $vlit ]] || { echo "parallel-shards-test: no vlit at $vlit (build first)" >&2; exit 2; }
work=$(mktemp -d /tmp/vlit-parallel.XXXXXX)
trap 'rm -rf "$work"' EXIT
scripts/make-shard-batch.sh "$work/in" 40
expected=$(cd "$work/in" && find . -name '*.glb' | sed 's|^\./||' | sort)

# check NAME OUT MANIFEST...: every input baked once into OUT, by 4 shards.
check() {
  local name=$1 out=$2
  shift 2
  local summary actual
  summary=$("$vlit" manifest-summary "$@")
  grep -q "^40 inputs in 40 records; shards 0/4 1/4 2/4 3/4$" <<<"$summary" &&
    grep -q "^baked 40, skipped 0, failed 0, interrupted 0$" <<<"$summary" &&
    ! grep -q "baked more than once" <<<"$summary" ||
    { echo "parallel-shards-test: $name: unexpected summary:"$'\n'"$summary" >&2; exit 1; }
  actual=$(cd "$out" && find . -name '*.glb' | sed 's|^\./||' | sort)
  [[ $actual == "$expected" ]] || { echo "parallel-shards-test: $name: outputs differ from inputs" >&2; exit 1; }
  echo "parallel-shards-test: OK: $name: each of 40 inputs baked exactly once"
}

# The recipe: the shard index is parallel's argument.
OMP_NUM_THREADS=1 parallel --will-cite -j 4 "$vlit" bake "$work/in" -o "$work/out" --shard {}/4 \
  --manifest "$work/m-{}.jsonl" -q ::: 0 1 2 3
check "--shard {}/4" "$work/out" "$work"/m-*.jsonl

# --shard auto: the job number PARALLEL_SEQ (1..4) with VLIT_SHARD_COUNT; 2 jobs at a time.
OMP_NUM_THREADS=1 VLIT_SHARD_COUNT=4 parallel --will-cite -j 2 "$vlit" bake "$work/in" -o "$work/auto" --shard auto \
  --manifest "$work/a-{#}.jsonl" -q ::: 1 2 3 4
check "--shard auto (PARALLEL_SEQ)" "$work/auto" "$work"/a-*.jsonl
