# cpack -G DEB: one package "vlit" with the command and the development files (docs/library.md
# "Debian package"). Depends: the shared libraries the vlit binary loads (from dpkg-shlibdeps
# when it is installed, otherwise the same list written out for Debian 12). Recommends: the -dev
# packages needed to build against libvlit.a (a static library: its users link its dependencies).
set(CPACK_PACKAGE_NAME vlit)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "vlit")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Per-vertex lighting of triangle meshes, baked into glTF COLOR_0 or rendered")
set(CPACK_PACKAGE_DESCRIPTION
    "vlit lights triangle meshes once per vertex with point, directional, spot, linear (tube) and area (panel) lights, using the analytic models of Picott (1992), then bakes the light into glTF vertex colours or renders PNGs with its own scanline rasterizer. This package holds the vlit command and the static library libvlit.a with its headers, CMake package (find_package(vlit CONFIG)) and pkg-config file.")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "vlit developers <vlit@localhost>")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
find_program(VLIT_DPKG_SHLIBDEPS dpkg-shlibdeps)
if(VLIT_DPKG_SHLIBDEPS)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
else()
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "libc6, libgcc-s1, libstdc++6, libgomp1, libopenmesh1, libstb0, libtinygltf2d, libdraco7, libmeshoptimizer2d")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libtinygltf-dev, libopenmesh-dev, libstb-dev, libdraco-dev, libmeshoptimizer-dev, pkgconf | pkg-config, g++ (>= 4:12), cmake (>= 3.16)")
include(CPack)
