# Sourced by the timing scripts (shadow-bake-times.sh, specular-times.sh): the median wall time in
# seconds of RUNS runs of a command, its output discarded.
#   median_seconds RUNS COMMAND...
median_seconds() {
  local runs=$1 run times=()
  shift
  for ((run = 0; run < runs; run++)); do
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null 2>&1
    end=$(date +%s.%N)
    times+=("$(awk -v s="$start" -v e="$end" 'BEGIN { print e - s }')")
  done
  printf '%s\n' "${times[@]}" | sort -g | sed -n "$(((runs + 1) / 2))p"
}
