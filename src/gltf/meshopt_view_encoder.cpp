#include "gltf/meshopt_view_encoder.h"

#include <algorithm>
#include <cstring>

#include <meshoptimizer.h>

#include "gltf/accessor_reader.h"

namespace vlit {
namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";

enum class Use { kNone, kAttribute, kIndices, kOther };

// How the accessors read each bufferView: attributes, indices, or anything else (kOther also
// when the uses are mixed).
std::vector<Use> view_uses(const tinygltf::Model& model) {
  std::vector<Use> accessor_use(model.accessors.size(), Use::kOther);
  std::vector<bool> seen(model.accessors.size(), false);
  auto mark = [&](int accessor, Use use) {
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= accessor_use.size()) return;
    accessor_use[accessor] = seen[accessor] && accessor_use[accessor] != use ? Use::kOther : use;
    seen[accessor] = true;
  };
  for (const tinygltf::Mesh& mesh : model.meshes)
    for (const tinygltf::Primitive& prim : mesh.primitives) {
      for (const auto& [name, accessor] : prim.attributes) mark(accessor, Use::kAttribute);
      for (const auto& target : prim.targets)
        for (const auto& [name, accessor] : target) mark(accessor, Use::kAttribute);
      mark(prim.indices, Use::kIndices);
    }
  std::vector<Use> uses(model.bufferViews.size(), Use::kNone);
  auto add = [&](int view, Use use) {
    if (view < 0 || static_cast<std::size_t>(view) >= uses.size()) return;
    uses[view] = uses[view] == Use::kNone || uses[view] == use ? use : Use::kOther;
  };
  for (std::size_t a = 0; a < model.accessors.size(); ++a) {
    const tinygltf::Accessor& acc = model.accessors[a];
    const bool sparse = acc.sparse.isSparse;
    add(acc.bufferView, sparse ? Use::kOther : (seen[a] ? accessor_use[a] : Use::kOther));
    if (sparse) {
      add(acc.sparse.indices.bufferView, Use::kOther);
      add(acc.sparse.values.bufferView, Use::kOther);
    }
  }
  for (const tinygltf::Image& image : model.images) add(image.bufferView, Use::kOther);
  return uses;
}

std::size_t element_bytes(const tinygltf::Accessor& acc) {
  const int components = tinygltf::GetNumComponentsInType(acc.type);
  const int bytes = component_bytes(acc.componentType);
  return components > 0 && bytes > 0 ? static_cast<std::size_t>(components) * bytes : 0;
}

// What encode_view needs to know of the whole model, gathered in one pass: the accessors that
// read each view, and the accessors some primitive of another mode than triangles reads as its
// indices.
struct ViewReaders {
  std::vector<std::vector<const tinygltf::Accessor*>> of_view;
  std::vector<bool> non_triangle_indices;
  explicit ViewReaders(const tinygltf::Model& model)
      : of_view(model.bufferViews.size()), non_triangle_indices(model.accessors.size(), false) {
    for (const tinygltf::Accessor& acc : model.accessors)
      if (acc.bufferView >= 0 && static_cast<std::size_t>(acc.bufferView) < of_view.size())
        of_view[acc.bufferView].push_back(&acc);
    for (const tinygltf::Mesh& mesh : model.meshes)
      for (const tinygltf::Primitive& prim : mesh.primitives)
        if (prim.indices >= 0 && static_cast<std::size_t>(prim.indices) < model.accessors.size() &&
            prim.mode != TINYGLTF_MODE_TRIANGLES)
          non_triangle_indices[prim.indices] = true;
  }
};

// The encoded bytes of view v, or empty when it is not eligible; sets stride, count and mode.
std::string encode_view(const tinygltf::Model& model, const ViewReaders& all, std::size_t v, Use use,
                        MeshoptEncoding::View& out) {
  const tinygltf::BufferView& view = model.bufferViews[v];
  if (view.buffer != 0 || view.byteLength == 0 || view.byteOffset + view.byteLength > model.buffers[0].data.size())
    return {};
  const std::vector<const tinygltf::Accessor*>& readers = all.of_view[v];
  if (readers.empty()) return {};
  const unsigned char* data = model.buffers[0].data.data() + view.byteOffset;
  if (use == Use::kAttribute) {
    std::size_t stride = view.byteStride;
    if (stride == 0) {
      if (readers.size() != 1 || readers[0]->byteOffset != 0) return {};
      stride = element_bytes(*readers[0]);
    }
    if (stride == 0 || stride % 4 != 0 || stride > 256 || view.byteLength % stride != 0) return {};
    out.byte_stride = stride;
    out.count = view.byteLength / stride;
    out.mode = "ATTRIBUTES";
    std::string encoded(meshopt_encodeVertexBufferBound(out.count, stride), '\0');
    encoded.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(encoded.data()), encoded.size(), data,
                                              out.count, stride));
    return encoded;
  }
  // Indices: one component type of 2 or 4 bytes, tightly packed.
  const int type = readers[0]->componentType;
  for (const tinygltf::Accessor* acc : readers)
    if (acc->componentType != type) return {};
  const std::size_t stride = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2 : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT ? 4 : 0;
  if (stride == 0 || view.byteStride != 0 || view.byteLength % stride != 0) return {};
  const std::size_t count = view.byteLength / stride;
  std::vector<unsigned int> indices(count);
  unsigned int largest = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (stride == 2) {
      std::uint16_t x;
      std::memcpy(&x, data + 2 * i, 2);
      indices[i] = x;
    } else {
      std::memcpy(&indices[i], data + 4 * i, 4);
    }
    largest = std::max(largest, indices[i]);
  }
  // A triangle list read whole by one accessor of triangles: the triangle codec.
  const bool triangles = readers.size() == 1 && readers[0]->byteOffset == 0 && readers[0]->count == count &&
                         count % 3 == 0 && !all.non_triangle_indices[readers[0] - model.accessors.data()];
  out.byte_stride = stride;
  out.count = count;
  out.mode = triangles ? "TRIANGLES" : "INDICES";
  std::string encoded;
  if (triangles) {
    encoded.resize(meshopt_encodeIndexBufferBound(count, static_cast<std::size_t>(largest) + 1));
    encoded.resize(meshopt_encodeIndexBuffer(reinterpret_cast<unsigned char*>(encoded.data()), encoded.size(),
                                             indices.data(), count));
  } else {
    encoded.resize(meshopt_encodeIndexSequenceBound(count, static_cast<std::size_t>(largest) + 1));
    encoded.resize(meshopt_encodeIndexSequence(reinterpret_cast<unsigned char*>(encoded.data()), encoded.size(),
                                               indices.data(), count));
  }
  return encoded;
}

void add_name(std::vector<std::string>& names, const std::string& name) {
  if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

std::size_t aligned(std::size_t x, std::size_t to) { return (x + to - 1) / to * to; }

}  // namespace

MeshoptEncoding encode_views_with_meshopt(tinygltf::Model& model) {
  // The codec versions the extension specifies (vertex 0, index 1), set once.
  static const bool versions_set = [] {
    meshopt_encodeVertexVersion(0);
    meshopt_encodeIndexVersion(1);
    return true;
  }();
  (void)versions_set;
  MeshoptEncoding result;
  if (model.buffers.size() != 1) return result;
  const std::vector<Use> uses = view_uses(model);
  const ViewReaders readers(model);
  std::vector<std::string> encoded(model.bufferViews.size());
  std::vector<MeshoptEncoding::View> info(model.bufferViews.size());
  bool any = false;
  for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
    if (uses[v] != Use::kAttribute && uses[v] != Use::kIndices) continue;
    encoded[v] = encode_view(model, readers, v, uses[v], info[v]);
    any = any || !encoded[v].empty();
  }
  if (!any) return result;

  // Buffer 0 anew: the encoded data of the encoded views, the bytes of the others; every view
  // 16-byte aligned (keeps each accessor's alignment). The encoded views move to the fallback.
  const std::vector<unsigned char>& old = model.buffers[0].data;
  std::vector<unsigned char> data;
  result.fallback_buffer = static_cast<int>(model.buffers.size());
  for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
    tinygltf::BufferView& view = model.bufferViews[v];
    if (view.buffer != 0) continue;
    data.resize(aligned(data.size(), 16), 0);
    if (encoded[v].empty()) {
      const std::size_t begin = std::min(view.byteOffset, old.size());
      const std::size_t end = std::min(view.byteOffset + view.byteLength, old.size());
      view.byteOffset = data.size();
      data.insert(data.end(), old.begin() + begin, old.begin() + end);
      continue;
    }
    MeshoptEncoding::View e = info[v];
    e.view = static_cast<int>(v);
    e.byte_offset = data.size();
    e.byte_length = encoded[v].size();
    data.insert(data.end(), encoded[v].begin(), encoded[v].end());
    result.fallback_bytes = aligned(result.fallback_bytes, 16);
    view.buffer = result.fallback_buffer;
    view.byteOffset = result.fallback_bytes;
    result.fallback_bytes += view.byteLength;
    result.views.push_back(e);
  }
  data.resize(aligned(data.size(), 4), 0);
  model.buffers[0].data = std::move(data);
  model.buffers.emplace_back();  // the fallback: its size and extension are written by add_meshopt_json
  add_name(model.extensionsUsed, kExtension);
  add_name(model.extensionsRequired, kExtension);
  return result;
}

void add_meshopt_json(nlohmann::json& root, const MeshoptEncoding& encoding) {
  if (encoding.views.empty()) return;
  nlohmann::json& fallback = root["buffers"][encoding.fallback_buffer];
  fallback = nlohmann::json::object();
  fallback["byteLength"] = encoding.fallback_bytes;
  fallback["extensions"][kExtension]["fallback"] = true;
  for (const MeshoptEncoding::View& e : encoding.views) {
    nlohmann::json& ext = root["bufferViews"][e.view]["extensions"][kExtension];
    ext["buffer"] = 0;
    ext["byteOffset"] = e.byte_offset;
    ext["byteLength"] = e.byte_length;
    ext["byteStride"] = e.byte_stride;
    ext["count"] = e.count;
    ext["mode"] = e.mode;
  }
}

}  // namespace vlit
