#!/usr/bin/env bash
# vlit as an installed package (docs/library.md): installs the release build into a temporary
# prefix; configures and builds examples/bake_tube_light against it with only
# -DCMAKE_PREFIX_PATH and runs it on the bundled demo scene; builds a second consumer through
# pkg-config alone, which reads the baked file back with vlit's loader and checks COLOR_0 (and the
# Khronos glTF-Validator checks it when node and npm are present); then builds the Debian package
# with cpack, checks its metadata and contents, and builds the example against its unpacked files. Reuses build/release (builds only the library
# and the binary if they are out of date). Exit status 1 on any failure.
#   scripts/install-test.sh [BUILD_DIR]     (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
[[ -f $build/CMakeCache.txt ]] || cmake --preset release >/dev/null
cmake --build "$build" -j2 --target vlit vlit_lib >/dev/null

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
fail() { echo "install-test: FAIL: $*" >&2; exit 1; }
step() { echo "install-test: $*"; }

step "cmake --install into a temporary prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/vlit include/vlit/vlit.h lib/libvlit.a lib/cmake/vlit/vlitConfig.cmake lib/cmake/vlit/vlitConfigVersion.cmake \
         lib/cmake/vlit/vlitTargets.cmake lib/pkgconfig/vlit.pc; do
  [[ -f $prefix/$f ]] || fail "$f not installed"
done
# Nothing of the internals may leak into the installed headers.
[[ $(find "$prefix/include" -type f | wc -l) == 1 ]] || fail "unexpected headers: $(find "$prefix/include" -type f)"
"$prefix/bin/vlit" --version | grep -q '^vlit ' || fail "installed vlit does not run"

step "example: find_package(vlit CONFIG) with only -DCMAKE_PREFIX_PATH"
cmake -S examples/bake_tube_light -B "$work/example" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >"$work/example-configure.log" 2>&1 || { cat "$work/example-configure.log"; fail "configure"; }
cmake --build "$work/example" >"$work/example-build.log" 2>&1 || { cat "$work/example-build.log"; fail "build"; }
"$work/example/bake_tube_light" assets/demo/studio.glb "$work/studio-tube.glb" || fail "example run"

step "consumer through pkg-config: read the output back, check COLOR_0"
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
# shellcheck disable=SC2046
c++ -std=c++17 -O1 scripts/install_check_baked.cpp -o "$work/check_baked" $(pkg-config --cflags --libs vlit) \
  || fail "pkg-config build"
"$work/check_baked" "$work/studio-tube.glb" || fail "baked output"
if command -v node >/dev/null && command -v npm >/dev/null; then
  (cd tests/validator && npm ci --no-audit --no-fund --silent) && node tests/validator/validate.js "$work/studio-tube.glb" \
    || fail "glTF-Validator"
else
  echo "install-test: node/npm not found; glTF-Validator check skipped" >&2
fi

step "cpack -G DEB"
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/deb" >"$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; fail "cpack"; }
deb=$(ls "$work"/deb/vlit_*.deb)
info=$(dpkg-deb --info "$deb")
contents=$(dpkg-deb --contents "$deb")
echo "$info" | grep -E '^ (Package|Version|Architecture|Depends|Recommends):'
depends=$(echo "$info" | sed -n 's/^ Depends: //p')
for lib in libgomp1 libopenmesh1 libstb0 libtinygltf2d libdraco7 libmeshoptimizer2d libstdc++6 libc6; do
  [[ $depends == *"$lib"* ]] || fail "Depends lacks $lib: $depends"
done
for f in ./usr/bin/vlit ./usr/include/vlit/vlit.h ./usr/lib/libvlit.a ./usr/lib/cmake/vlit/vlitConfig.cmake \
         ./usr/lib/cmake/vlit/vlitConfigVersion.cmake ./usr/lib/cmake/vlit/vlitTargets.cmake ./usr/lib/pkgconfig/vlit.pc; do
  echo "$contents" | grep -q " $f\$" || fail "$f not in $(basename "$deb")"
done
# The packaged files themselves (unpacked, not installed): the example builds against them too.
dpkg-deb -x "$deb" "$work/unpacked"
cmake -S examples/bake_tube_light -B "$work/example-deb" -G Ninja -DCMAKE_PREFIX_PATH="$work/unpacked/usr" \
  >"$work/example-deb.log" 2>&1 && cmake --build "$work/example-deb" >>"$work/example-deb.log" 2>&1 \
  || { cat "$work/example-deb.log"; fail "example against the unpacked .deb"; }
grep -q "$work/unpacked/usr/lib/cmake/vlit" "$work/example-deb/CMakeCache.txt" || fail "the example did not use the unpacked package"
step "$(basename "$deb"): $(echo "$contents" | grep -vc '/$') files, $(du -h "$deb" | cut -f1)"
step "OK"
