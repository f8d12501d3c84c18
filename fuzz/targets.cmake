# libFuzzer targets (docs/robustness.md), included by fuzz/fuzz.cmake. Built only by the `fuzz` preset (clang; every object is
# compiled with -fsanitize=fuzzer-no-link,address,undefined, the targets link -fsanitize=fuzzer).
#   cmake --preset fuzz && cmake --build --preset fuzz     then   scripts/fuzz.sh TARGET MINUTES
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "fuzz/: libFuzzer needs clang (configure with the fuzz preset)")
endif()

# tinygltf's implementation, instrumented (Debian's libtinygltf.so is not).
add_library(vlit_tinygltf_instrumented OBJECT ${VLIT_FUZZ_DIR}/tinygltf_instrumented.cpp)
target_link_libraries(vlit_tinygltf_instrumented PRIVATE TinyGLTF::TinyGLTF nlohmann_json::nlohmann_json PkgConfig::STB)
target_compile_options(vlit_tinygltf_instrumented PRIVATE -w)

foreach(target fuzz_gltf fuzz_lights_json fuzz_points_csv fuzz_obj)
  add_executable(${target} ${VLIT_FUZZ_DIR}/${target}.cpp)
  target_link_libraries(${target} PRIVATE vlit_lib)
  target_link_options(${target} PRIVATE -fsanitize=fuzzer)
endforeach()
target_sources(fuzz_gltf PRIVATE $<TARGET_OBJECTS:vlit_tinygltf_instrumented>)
