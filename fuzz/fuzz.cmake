# Included right after project(vlit) by the `fuzz` preset (CMAKE_PROJECT_vlit_INCLUDE), so the
# fuzz build needs no switch in the top-level CMakeLists.txt: fuzz/targets.cmake is included once
# the top level has been processed (vlit_lib exists by then). Deferred arguments are expanded at
# call time, so the directory is kept in a variable.
set(VLIT_FUZZ_DIR ${CMAKE_CURRENT_LIST_DIR})
cmake_language(DEFER DIRECTORY ${CMAKE_SOURCE_DIR} CALL include ${VLIT_FUZZ_DIR}/targets.cmake)
