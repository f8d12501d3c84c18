#include "gltf/gltf_append.h"

#include <algorithm>
#include <limits>

namespace vlit {

int append_buffer_view(tinygltf::Model& model, const void* data, std::size_t bytes, int target) {
  if (model.buffers.empty()) model.buffers.resize(1);
  std::vector<unsigned char>& buffer = model.buffers[0].data;
  buffer.resize((buffer.size() + 3) & ~std::size_t(3), 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), p, p + bytes);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

int append_vec3_accessor(tinygltf::Model& model, const std::vector<Vec3d>& values, bool with_bounds) {
  std::vector<float> flat;
  flat.reserve(values.size() * 3);
  std::vector<double> lo(3, std::numeric_limits<double>::max()), hi(3, std::numeric_limits<double>::lowest());
  for (const Vec3d& v : values)
    for (int k = 0; k < 3; ++k) {
      const float f = static_cast<float>(v[k]);
      flat.push_back(f);
      lo[k] = std::min<double>(lo[k], f);
      hi[k] = std::max<double>(hi[k], f);
    }
  tinygltf::Accessor a;
  a.bufferView = append_buffer_view(model, flat.data(), flat.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.type = TINYGLTF_TYPE_VEC3;
  a.count = values.size();
  if (with_bounds) {
    a.minValues = lo;
    a.maxValues = hi;
  }
  model.accessors.push_back(a);
  return static_cast<int>(model.accessors.size()) - 1;
}

}  // namespace vlit
