#!/usr/bin/env bash
# Accuracy report: error against run time for every light-model method, stability on stiff cases,
# and an end-to-end bake of a real asset (bench/accuracy_report.cpp, one file per light model in
# bench/accuracy/). The program measures and writes the tables; the text of docs/accuracy.md is
# docs/accuracy.md.in, whose {{names}} the program fills with this run's tables and numbers.
#
#   scripts/accuracy-report.sh           full report: writes docs/accuracy.md and docs/images/accuracy/*.png
#   scripts/accuracy-report.sh --quick   seconds-long smoke version (what CI runs through ctest
#                                        accuracy_report_quick): writes only into the build directory
#
# Builds in build/report (override with VLIT_REPORT_BUILD_DIR), Release, at most -j2; runs the
# program on one thread; draws the plots with gnuplot (Debian: apt-get install gnuplot-nox).
# Exit status 1 if any method returned NaN or Inf.
#
# Blender Cycles comparison (full report only, optional): when `blender` is installed,
# scripts/blender-compare.sh bakes the asset with Cycles first (a few minutes) into
# $build/blender. VLIT_BLENDER=off skips it (the report then says Blender was not available);
# VLIT_BLENDER=reuse uses the Cycles data already in $build/blender without baking again.
set -euo pipefail
cd "$(dirname "$0")/.."

quick=()
[[ "${1:-}" == "--quick" ]] && quick=(--quick)

build=${VLIT_REPORT_BUILD_DIR:-build/report}
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target accuracy_report -j2 >/dev/null

# The full report of docs/accuracy.md used Khronos' DamagedHelmet.glb (not vendored: 3.7 MB); pass
# it as VLIT_ACCURACY_ASSET to reproduce those tables. The default is the vendored Avocado.
asset=${VLIT_ACCURACY_ASSET:-assets/samples/Avocado/Avocado.gltf}
[[ ${#quick[@]} -gt 0 ]] && asset=assets/samples/Avocado/Avocado.gltf

blender_args=()
if [[ ${#quick[@]} -eq 0 ]]; then
  case "${VLIT_BLENDER:-run}" in
    off) ;;
    reuse) [[ -f "$build/blender/cycles-times.txt" ]] && blender_args=(--blender "$build/blender") ;;
    *)
      if command -v blender >/dev/null; then
        if VLIT_REPORT_BUILD_DIR="$build" scripts/blender-compare.sh "$build/blender"; then
          blender_args=(--blender "$build/blender")
        else
          echo "accuracy-report: the Cycles comparison failed; the report goes on without it" >&2
        fi
      else
        echo "accuracy-report: blender not installed, no Cycles comparison (Debian: apt-get install blender python3-numpy)" >&2
      fi ;;
  esac
fi

out="$build/accuracy-report${quick[0]:+-quick}"
rm -rf "$out"
status=0
OMP_NUM_THREADS=1 "$build/bench/accuracy_report" "${quick[@]}" --out-dir "$out" --asset "$asset" \
  --template docs/accuracy.md.in "${blender_args[@]}" || status=$?
if [[ $status -ne 0 && $status -ne 1 ]]; then
  echo "accuracy-report: the program failed (status $status)" >&2
  exit "$status"
fi

if command -v gnuplot >/dev/null; then
  (cd "$out" && for gp in data/*.gp; do gnuplot "$gp"; done)
else
  echo "accuracy-report: gnuplot not found, plots not drawn (Debian: sudo apt-get install gnuplot-nox)" >&2
  [[ ${#quick[@]} -eq 0 ]] && exit 1
fi

if [[ ${#quick[@]} -eq 0 ]]; then
  mkdir -p docs/images/accuracy
  cp "$out/accuracy.md" docs/accuracy.md
  cp "$out"/images/accuracy/*.png docs/images/accuracy/
  echo "accuracy-report: wrote docs/accuracy.md and docs/images/accuracy/*.png" >&2
else
  echo "accuracy-report: quick report in $out/accuracy.md" >&2
fi
[[ $status -eq 1 ]] && echo "accuracy-report: NaN or Inf appeared, see the report" >&2
exit "$status"
