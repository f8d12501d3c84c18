#!/usr/bin/env bash
# make-shard-batch.sh DIR COUNT: a batch of COUNT small glTF assets for the shard tests and bench,
# copies of assets/examples/file-lights.glb (lights inside, ~10 ms to bake) in nested folders where
# the same file name recurs: DIR/setK/glTF/model.glb next to DIR/setK/glTF-Quantized/model.glb.
set -euo pipefail
dir=$1 count=$2
src="$(cd "$(dirname "$0")/.." && pwd)/assets/examples/file-lights.glb"
for ((i = 0; i < count; i++)); do
  folder="$dir/set$((i / 4))/$([[ $((i % 2)) == 0 ]] && echo glTF || echo glTF-Quantized)"
  mkdir -p "$folder"
  cp "$src" "$folder/model$((i % 4 / 2)).glb"
done
