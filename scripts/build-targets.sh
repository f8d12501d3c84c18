# Sourced by the scripts that need vlit's programs: configures a Release build directory if it is
# not configured yet (build/release through the preset, any other directory with Ninja) and builds
# the named targets in it.
#   build_targets BUILD_DIR TARGET...     (parallel jobs: $JOBS, default 2)
build_targets() {
  local dir=$1
  shift
  if [[ ! -f "$dir/CMakeCache.txt" ]]; then
    if [[ "$dir" == build/release ]]; then cmake --preset release >/dev/null
    else cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null; fi
  fi
  cmake --build "$dir" -j"${JOBS:-2}" --target "$@"
}
