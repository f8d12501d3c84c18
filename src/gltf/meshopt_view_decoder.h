// Decoding one bufferView compressed with EXT_meshopt_compression (or KHR_meshopt_compression,
// the same layout) by libmeshoptimizer: the vertex codec for "ATTRIBUTES", the index codecs for
// "TRIANGLES" and "INDICES", then the filter that undoes a lossy quantization ("OCTAHEDRAL",
// "QUATERNION", "EXPONENTIAL"). Source: the extension's specification (KHR glTF repository,
// extensions/2.0/Vendor/EXT_meshopt_compression) and meshoptimizer.h.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace vlit {

struct MeshoptStream {
  std::size_t count = 0;        // elements (vertices or indices)
  std::size_t byte_stride = 0;  // bytes per element after decoding
  std::string mode;             // "ATTRIBUTES", "TRIANGLES" or "INDICES"
  std::string filter = "NONE";  // "NONE", "OCTAHEDRAL", "QUATERNION" or "EXPONENTIAL"
};

// The decoded bytes, count * byte_stride of them. Throws InputError(file, problem, where) when
// the stream's parameters break the extension's rules or the data does not decode (corrupt, or
// an encoding version newer than the installed libmeshoptimizer reads).
std::string decode_meshopt_stream(std::string_view compressed, const MeshoptStream& stream, const std::string& file,
                                  const std::string& where);

}  // namespace vlit
