#!/usr/bin/env bash
# Fuzzes one libFuzzer target (fuzz/, docs/robustness.md) for MINUTES minutes:
#   scripts/fuzz.sh gltf|lights_json|points_csv|obj MINUTES
# MINUTES = 0 is the CI smoke run: RUNS executions (default 2000) from the seeds, no time limit.
# Builds the `fuzz` preset (clang, -fsanitize=fuzzer,address,undefined) into build/fuzz, seeds
# build/fuzz/corpus/TARGET from the real assets (copied here at fuzz time, never committed), keeps
# the inputs the fuzzer adds there, and writes any finding to build/fuzz/findings/TARGET/. Exit
# status is non-zero when the fuzzer found a crash, a leak, a timeout or an out-of-memory input.
# Needs clang and libclang-rt-14-dev (scripts/install-deps.sh installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:?usage: scripts/fuzz.sh gltf|lights_json|points_csv|obj MINUTES}
minutes=${2:?usage: scripts/fuzz.sh gltf|lights_json|points_csv|obj MINUTES}
runs=${RUNS:-2000}
case "$target" in gltf|lights_json|points_csv|obj) ;; *) echo "fuzz.sh: unknown target $target" >&2; exit 2 ;; esac

build=build/fuzz
if [[ ! -f $build/CMakeCache.txt ]]; then cmake --preset fuzz >/dev/null; fi
cmake --build --preset fuzz -j2 >/dev/null

corpus=$build/corpus/$target
findings=$build/findings/$target
mkdir -p "$corpus" "$findings"
seed() { [[ -f "$1" ]] && cp -n "$1" "$corpus/seed-$(basename "$(dirname "$1")")-$(basename "$1")" || true; }
case "$target" in
  gltf)
    # Self-contained assets (GLB, embedded buffers) and the malformed corpus; nothing over 1 MB.
    while IFS= read -r -d '' f; do seed "$f"; done < <(find assets \
        \( -name '*.gltf' -o -name '*.glb' \) -size -1024k -print0 2>/dev/null)
    dict=(-dict=fuzz/gltf.dict) ;;
  lights_json)
    while IFS= read -r -d '' f; do seed "$f"; done < <(find assets -path assets/bad-gltf -prune -o -name '*.json' -size -64k -print0)
    printf '%s' '{"lights":[{"type":"area","polygon":[[0,0,1],[1,0,1],[1,1,1]],"intensity":2,"two_sided":true},{"type":"disk","center":[0,0,2],"normal":[0,0,-1],"radius":0.5},{"type":"spot","position":[0,0,3],"direction":[0,0,-1],"outer_cone_angle":0.5,"inner_cone_angle":0.2,"falloff":2.5,"color":[1,0.5,0.2]},{"type":"directional","direction":[0,-1,0],"name":"sun"}]}' \
        > "$corpus/seed-all-types.json"
    dict=() ;;
  obj)
    # One text read as the OBJ and as its .mtl (fuzz/fuzz_obj.cpp): materials, emitters, normals,
    # negative indices, a continued line.
    printf 'mtllib fuzz.mtl other.mtl\nnewmtl white\nKd 0.7 0.7 0.7\nNs 20\nnewmtl lamp\nKd 1\nKe 5 4 3\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nusemtl white\nf 1//1 2//1 3//1 4//1\nusemtl lamp\nv 0 0 1\nv 0 1 1\nv 1 1 1\nf -3 -2 \\\n -1\nusemtl none\nf 1/1 2/2/1 3\n' \
        > "$corpus/seed-cornell.obj"
    dict=() ;;
  points_csv)
    printf 'px,py,pz,nx,ny,nz,ex,ey,ez,m\n0,0,0,0,0,1,0,0,5,10\n# comment\n1.5e-3, -2, +3 ,0,1,0, 1e300,0,0,0\n' > "$corpus/seed-points.csv"
    dict=() ;;
esac

options=(-rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=20 -max_len=1048576 -artifact_prefix="$findings/"
         -print_final_stats=1 "${dict[@]}")
if [[ "$minutes" == 0 ]]; then
  options+=(-runs="$runs")
else
  options+=(-max_total_time=$((minutes * 60)))
fi
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
echo "fuzz.sh: $target, ${minutes} min (corpus $corpus, findings $findings)" >&2
"$build/fuzz_$target" "${options[@]}" "$corpus"
