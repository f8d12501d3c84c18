// Reads glTF accessors into plain arrays with every range checked against the file first:
// component types, normalized integers (KHR_mesh_quantization), interleaved byte strides and
// sparse substitution. A bad accessor is an InputError naming the file and "accessors[i]".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace vlit {

// All elements of accessor `index` as doubles, `components` per element (1 for SCALAR, 3 for
// VEC3, ...). Normalized integer components are mapped to [0,1] or [-1,1] as the glTF spec says.
// Throws InputError(file, ...) when the accessor is malformed or out of the buffer's bounds.
std::vector<double> read_accessor_as_doubles(const tinygltf::Model& model, int index, const std::string& file);

// Index data (unsigned byte, short or int scalars) as uint32; every value is checked < vertex_count.
std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index, std::size_t vertex_count,
                                        const std::string& file);

// The order in which a primitive draws its vertices: its indices (read_indices), or 0, 1, ...,
// vertex_count - 1 when it has none.
std::vector<std::uint32_t> draw_order_of(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                                         std::size_t vertex_count, const std::string& file);

// Number of components of a glTF accessor type (TINYGLTF_TYPE_*), or 0 if unknown.
int accessor_components(int type);
// Bytes of one component of a glTF 2.0 componentType (5120-5123, 5125, 5126); 0 for any other.
int component_bytes(int component_type);

}  // namespace vlit
