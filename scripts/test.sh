#!/usr/bin/env bash
# Installs what is missing (Debian packages), builds the release preset and runs every test
# (ctest through the release workflow preset). Exit status is the tests'.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --workflow --preset release
