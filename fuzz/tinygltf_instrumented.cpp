// tinygltf's implementation compiled into the fuzz targets, so that libFuzzer sees coverage inside
// the glTF parser (Debian's libtinygltf.so is not instrumented). These definitions take precedence
// over the shared library's for the whole fuzz executable. Same header, same version (2.7).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
