#!/usr/bin/env bash
# Installs the Debian packages vlit needs to build and test, and nothing else.
# Idempotent: prints nothing and touches nothing when every package is already there.
# Needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config       # toolchain
  libopenmesh-dev                        # mesh structure, normals, OBJ/PLY/OFF/STL readers
  libtinygltf-dev nlohmann-json3-dev     # glTF read/write (tinygltf uses nlohmann-json)
  libdraco-dev libmeshoptimizer-dev      # compressed glTF geometry: KHR_draco_mesh_compression, EXT_meshopt_compression
  libstb-dev                             # PNG encode/decode
  libcli11-dev                           # command line
  doctest-dev                            # tests
  draco                                  # tests: draco_transcoder makes the Draco-compressed test assets
  libboost-dev                           # Boost.Math: incomplete beta (linear specular), quadrature for the tests' references
  libbenchmark-dev                       # bench/ programs
  clang libclang-rt-14-dev libomp-dev    # fuzz/ targets (libFuzzer, clang's OpenMP), run by .ci/run
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
[[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
