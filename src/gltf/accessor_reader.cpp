#include "gltf/accessor_reader.h"

#include <cmath>
#include <cstring>

#include "core/input_error.h"

namespace vlit {
namespace {

// One component at `p`, decoded (and normalized if asked) as the glTF spec defines.
double decode_component(const unsigned char* p, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: { const double v = *p; return normalized ? v / 255.0 : v; }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double v = static_cast<std::int8_t>(*p);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t u; std::memcpy(&u, p, 2);
      return normalized ? u / 65535.0 : u;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t s; std::memcpy(&s, p, 2);
      return normalized ? std::max(s / 32767.0, -1.0) : s;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t u; std::memcpy(&u, p, 4); return u; }
  }
  return 0;
}

struct ByteRange {
  const unsigned char* data;
  std::size_t stride;
};

// Checks that `count` elements of `element_bytes` each, `stride` apart, starting at byte
// `offset` of buffer view `view_index`, lie inside the view and its buffer.
ByteRange checked_range(const tinygltf::Model& model, int view_index, std::size_t offset, std::size_t count,
                        std::size_t element_bytes, std::size_t stride, const std::string& file,
                        const std::string& where) {
  if (view_index < 0 || static_cast<std::size_t>(view_index) >= model.bufferViews.size())
    throw InputError(file, "bufferView " + std::to_string(view_index) + " does not exist", where);
  const tinygltf::BufferView& view = model.bufferViews[view_index];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
    throw InputError(file, "bufferView refers to a missing buffer", where);
  const tinygltf::Buffer& buffer = model.buffers[view.buffer];
  if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
    throw InputError(file, "bufferView " + std::to_string(view_index) + " lies outside its buffer", where);
  if (view.byteStride != 0) stride = view.byteStride;
  if (stride < element_bytes) throw InputError(file, "byteStride is smaller than one element", where);
  if (count > 0) {
    // last byte needed = offset + (count-1)*stride + element_bytes; guard each step against overflow.
    const std::size_t limit = view.byteLength;
    if (offset > limit) throw InputError(file, "accessor byteOffset lies outside its bufferView", where);
    if ((count - 1) > (limit - offset) / stride)
      throw InputError(file, "accessor reads past the end of its bufferView", where);
    if (offset + (count - 1) * stride + element_bytes > limit)
      throw InputError(file, "accessor reads past the end of its bufferView", where);
  }
  return {buffer.data.data() + view.byteOffset + offset, stride};
}

}  // namespace

int component_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int accessor_components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

std::vector<double> read_accessor_as_doubles(const tinygltf::Model& model, int index, const std::string& file) {
  const std::string where = "accessors[" + std::to_string(index) + "]";
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
    throw InputError(file, "accessor does not exist", where);
  const tinygltf::Accessor& acc = model.accessors[index];
  const int components = accessor_components(acc.type);
  const int bytes = component_bytes(acc.componentType);
  if (components == 0 || bytes == 0) throw InputError(file, "unsupported accessor type or componentType", where);
  const std::size_t count = acc.count;
  // Refuse absurd counts before allocating: the data must fit in the file's buffers.
  std::size_t total_buffer_bytes = 0;
  for (const auto& b : model.buffers) total_buffer_bytes += b.data.size();
  if (acc.bufferView >= 0 && count > total_buffer_bytes / (static_cast<std::size_t>(components) * bytes) + 1)
    throw InputError(file, "accessor count " + std::to_string(count) + " exceeds the file's buffer data", where);
  // Without a bufferView (zeros, possibly with sparse values) nothing in the file bounds the count:
  // cap the array at 2^27 doubles (1 GiB), sparse or not.
  if (acc.bufferView < 0 && count > (std::size_t(1) << 27) / static_cast<std::size_t>(components))
    throw InputError(file, "accessor count " + std::to_string(count) + " without a bufferView is unreasonably large", where);

  std::vector<double> out(count * components, 0.0);  // no bufferView: zeros (glTF spec)
  const std::size_t element_bytes = static_cast<std::size_t>(components) * bytes;
  if (acc.bufferView >= 0) {
    const ByteRange range = checked_range(model, acc.bufferView, acc.byteOffset, count, element_bytes,
                                          element_bytes, file, where);
    for (std::size_t i = 0; i < count; ++i)
      for (int c = 0; c < components; ++c)
        out[i * components + c] = decode_component(range.data + i * range.stride + c * bytes, acc.componentType, acc.normalized);
  }

  if (acc.sparse.isSparse) {
    const auto& sparse = acc.sparse;
    const std::size_t n = static_cast<std::size_t>(std::max(sparse.count, 0));
    if (sparse.count < 1 || n > count) throw InputError(file, "sparse count must be in [1, accessor count]", where);
    const int index_bytes = component_bytes(sparse.indices.componentType);
    if (index_bytes == 0 || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT)
      throw InputError(file, "sparse indices must be unsigned integers", where);
    const ByteRange idx = checked_range(model, sparse.indices.bufferView, sparse.indices.byteOffset, n, index_bytes,
                                        index_bytes, file, where + ".sparse.indices");
    const ByteRange val = checked_range(model, sparse.values.bufferView, sparse.values.byteOffset, n, element_bytes,
                                        element_bytes, file, where + ".sparse.values");
    for (std::size_t k = 0; k < n; ++k) {
      const double target_d = decode_component(idx.data + k * index_bytes, sparse.indices.componentType, false);
      const std::size_t target = static_cast<std::size_t>(target_d);
      if (target >= count) throw InputError(file, "sparse index " + std::to_string(target) + " is out of range", where);
      for (int c = 0; c < components; ++c)
        out[target * components + c] = decode_component(val.data + k * element_bytes + c * bytes, acc.componentType, acc.normalized);
    }
  }
  return out;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index, std::size_t vertex_count,
                                        const std::string& file) {
  const std::string where = "accessors[" + std::to_string(index) + "]";
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
    throw InputError(file, "index accessor does not exist", where);
  const tinygltf::Accessor& acc = model.accessors[index];
  if (acc.type != TINYGLTF_TYPE_SCALAR ||
      (acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
       acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
       acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
    throw InputError(file, "indices must be unsigned byte, short or int scalars", where);
  const std::vector<double> values = read_accessor_as_doubles(model, index, file);
  std::vector<std::uint32_t> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] >= static_cast<double>(vertex_count))
      throw InputError(file, "index " + std::to_string(static_cast<std::uint64_t>(values[i])) + " at position " +
                                 std::to_string(i) + " is not below the vertex count " + std::to_string(vertex_count), where);
    out[i] = static_cast<std::uint32_t>(values[i]);
  }
  return out;
}

std::vector<std::uint32_t> draw_order_of(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                                         std::size_t vertex_count, const std::string& file) {
  if (prim.indices >= 0) return read_indices(model, prim.indices, vertex_count, file);
  std::vector<std::uint32_t> order(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i) order[i] = static_cast<std::uint32_t>(i);
  return order;
}

}  // namespace vlit
