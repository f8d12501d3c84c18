#include "gltf/meshopt_view_decoder.h"

#include <meshoptimizer.h>

#include "core/input_error.h"

namespace vlit {

std::string decode_meshopt_stream(std::string_view compressed, const MeshoptStream& stream, const std::string& file,
                                  const std::string& where) {
  const std::size_t stride = stream.byte_stride;
  // The rules of the extension's "Compressed data" section; the decoders assume them.
  if (stream.mode == "ATTRIBUTES") {
    if (stride == 0 || stride % 4 != 0 || stride > 256)
      throw InputError(file, "ATTRIBUTES byteStride must be a multiple of 4 up to 256, not " + std::to_string(stride), where);
  } else if (stream.mode == "TRIANGLES" || stream.mode == "INDICES") {
    if (stride != 2 && stride != 4)
      throw InputError(file, stream.mode + " byteStride must be 2 or 4, not " + std::to_string(stride), where);
    if (stream.mode == "TRIANGLES" && stream.count % 3 != 0)
      throw InputError(file, "TRIANGLES count must be a multiple of 3, not " + std::to_string(stream.count), where);
    if (stream.filter != "NONE") throw InputError(file, "a filter is allowed only in ATTRIBUTES mode", where);
  } else {
    throw InputError(file, "unknown mode \"" + stream.mode + "\" (ATTRIBUTES, TRIANGLES or INDICES)", where);
  }
  if (stream.count > (std::size_t(1) << 32) / stride)
    throw InputError(file, "decoded size of " + std::to_string(stream.count) + " x " + std::to_string(stride) + " bytes is too large", where);

  std::string out(stream.count * stride, '\0');
  const auto* data = reinterpret_cast<const unsigned char*>(compressed.data());
  int status = 0;
  if (stream.mode == "ATTRIBUTES") status = meshopt_decodeVertexBuffer(out.data(), stream.count, stride, data, compressed.size());
  else if (stream.mode == "TRIANGLES") status = meshopt_decodeIndexBuffer(out.data(), stream.count, stride, data, compressed.size());
  else status = meshopt_decodeIndexSequence(out.data(), stream.count, stride, data, compressed.size());
  if (status != 0)
    throw InputError(file, stream.mode + " data does not decode (libmeshoptimizer " + std::to_string(MESHOPTIMIZER_VERSION) +
                               " returned " + std::to_string(status) + ": corrupt, or a newer encoding version)", where);

  if (stream.filter == "NONE") return out;
  // Each filter fixes the element size it reads (the extension's "Filters" section).
  if (stream.filter == "OCTAHEDRAL") {
    if (stride != 4 && stride != 8) throw InputError(file, "OCTAHEDRAL filter needs byteStride 4 or 8", where);
    meshopt_decodeFilterOct(out.data(), stream.count, stride);
  } else if (stream.filter == "QUATERNION") {
    if (stride != 8) throw InputError(file, "QUATERNION filter needs byteStride 8", where);
    meshopt_decodeFilterQuat(out.data(), stream.count, stride);
  } else if (stream.filter == "EXPONENTIAL") {
    meshopt_decodeFilterExp(out.data(), stream.count, stride);  // any multiple of 4 (checked above)
  } else {
    throw InputError(file, "unknown filter \"" + stream.filter + "\" (NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL)", where);
  }
  return out;
}

}  // namespace vlit
