#!/usr/bin/env bash
# Regenerates the golden images under tests/golden/images/ ON PURPOSE: after a change that is
# meant to change what vlit draws. Builds vlit and golden_tests, renders every golden case and
# overwrites its PNG; review the result (git diff --stat, look at the images) before committing.
# Usage: scripts/update-goldens.sh            (build dir: build/release, configured if needed)
#        BUILD_DIR=build/mine scripts/update-goldens.sh
# docs/golden-images.md explains the comparison and how to add a golden.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${BUILD_DIR:-build/release}"
# shellcheck source=scripts/build-targets.sh
source scripts/build-targets.sh
build_targets "$build_dir" vlit golden_tests
VLIT_UPDATE_GOLDENS=1 "$build_dir/tests/golden_tests" --test-case='golden: *'
git status --short tests/golden/images
