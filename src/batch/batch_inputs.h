// The inputs of a batch bake and where each one's output goes. Every input argument is a root: a
// file, a directory searched recursively for glTF and mesh files, or a glob pattern whose root is the folder before its
// first wildcard. An input's key is its path relative to its root ('/'-separated); its output is
// OUT_DIR/key, with .glb for a mesh file (OBJ, PLY, OFF, STL). So `Duck/glTF/Duck.gltf` and
// `Duck/glTF-Quantized/Duck.gltf` under `Duck/` (or `'Duck/*/Duck.gltf'`) keep their folders.
// Two different inputs that would still share an output (two file arguments of one name, x.obj
// next to x.glb) are an error before anything is written.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vlit {

struct BatchInput {
  std::string path;  // as found: the argument, or the argument joined with the found path
  std::string key;   // relative to the argument's root, '/'-separated: names the output, picks the shard
};

// Expands one argument. Throws InputError(arg, ...) when it is missing, a directory with no glTF,
// or a pattern matching nothing.
std::vector<BatchInput> expand_batch_argument(const std::string& arg);

// True when the argument names several inputs (a directory or a glob pattern).
bool is_batch_argument(const std::string& arg);

// The pattern's root: the folders before the first component with * ? or [ ("." if none).
std::filesystem::path glob_root(const std::string& pattern);

struct BatchItem {
  std::string input;
  std::string key;
  std::filesystem::path output;  // out_dir / key, .glb for a mesh file
};

// Every input with its output under out_dir, in order; the same file named twice (same output)
// is kept once. Throws InputError(output, ...) naming every input of the first few outputs that
// two different inputs would share.
std::vector<BatchItem> lay_out_batch(const std::vector<BatchInput>& inputs, const std::filesystem::path& out_dir);

}  // namespace vlit
