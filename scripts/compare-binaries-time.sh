#!/usr/bin/env bash
# Times one vlit command with two binaries, run alternately (old, new, old, new, ...), so that a
# machine whose speed drifts during the comparison slows both alike. Prints every run's wall and
# CPU (user + system) seconds, then per binary the fastest and the median, and new / old of the
# medians. For changes whose effect is near the noise of one run (docs/shadows.md, "Benchmarks").
#
#   scripts/compare-binaries-time.sh OLD_VLIT NEW_VLIT RUNS VLIT_ARGS...
#
# VLIT_ARGS is the command after the binary's name; each OUT in it is replaced by a file in a
# temporary directory of that binary's own, e.g.
#   scripts/compare-binaries-time.sh /tmp/old/vlit build/release/vlit 5 \
#       bake assets/paper/bowling.glb --lights assets/paper/bowling-area.json -o OUT/lane.glb --shadows on
# OMP_NUM_THREADS and the other variables of the caller's environment reach both binaries.
set -euo pipefail
if [[ $# -lt 4 ]]; then
  echo "usage: scripts/compare-binaries-time.sh OLD_VLIT NEW_VLIT RUNS VLIT_ARGS..." >&2
  exit 2
fi
old=$1 new=$2 runs=$3
shift 3
for b in "$old" "$new"; do
  [[ -x "$b" ]] || { echo "compare-binaries-time: $b: not an executable" >&2; exit 2; }
done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || { echo "compare-binaries-time: RUNS must be a positive integer, not '$runs'" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/old" "$work/new"

# One run: "wall cpu" in seconds; the command's own output goes to a log, shown if it fails.
run_once() {
  local binary=$1 out=$2 args=() a
  shift 2
  for a in "$@"; do args+=("${a//OUT/$out}"); done
  local TIMEFORMAT='%R %U %S' timing
  if ! timing=$({ time "$binary" "${args[@]}" >"$out/log" 2>&1; } 2>&1); then
    echo "compare-binaries-time: $binary failed:" >&2
    cat "$out/log" >&2
    exit 1
  fi
  awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' <<<"$timing"
}

# The fastest or the median of column COLUMN (1: wall, 2: CPU) of a times file.
fastest() { cut -d' ' -f"$2" "$1" | sort -g | head -n 1; }
median() { cut -d' ' -f"$2" "$1" | sort -g | awk '{ v[NR] = $1 } END { printf "%.3f", (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%s\n' "| run | old wall (s) | old CPU (s) | new wall (s) | new CPU (s) |" "|---|---|---|---|---|"
: >"$work/old.times"
: >"$work/new.times"
for ((i = 1; i <= runs; i++)); do
  o=$(run_once "$old" "$work/old" "$@")
  n=$(run_once "$new" "$work/new" "$@")
  echo "$o" >>"$work/old.times"
  echo "$n" >>"$work/new.times"
  echo "| $i | ${o% *} | ${o#* } | ${n% *} | ${n#* } |"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
for which in old new; do
  t="$work/$which.times"
  echo "$which: wall fastest $(fastest "$t" 1), median $(median "$t" 1); CPU fastest $(fastest "$t" 2), median $(median "$t" 2)"
done
awk -v ow="$(median "$work/old.times" 1)" -v nw="$(median "$work/new.times" 1)" \
    -v oc="$(median "$work/old.times" 2)" -v nc="$(median "$work/new.times" 2)" \
    'BEGIN { printf "new / old of the medians: wall %.3f, CPU %.3f\n", nw / ow, nc / oc }'
