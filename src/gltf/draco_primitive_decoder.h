// Decoding the Draco bitstream of one glTF primitive (KHR_draco_mesh_compression) with Debian's
// libdraco, and laying its data out as the primitive's accessors declare it: indices in the index
// accessor's component type, each attribute in its accessor's component type and count. Source:
// the extension's specification (KHR glTF repository, extensions/2.0/Khronos/
// KHR_draco_mesh_compression): the accessors keep their type, count and min/max, the extension
// maps each semantic to a Draco attribute's unique id, and the decoded point order is the one the
// indices refer to.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace draco {
class Mesh;
}

namespace vlit {

class DracoPrimitive {
 public:
  // Throws InputError(file, problem, where) if the bytes are not a Draco triangle mesh.
  DracoPrimitive(std::string_view compressed, const std::string& file, const std::string& where);
  ~DracoPrimitive();
  DracoPrimitive(DracoPrimitive&&) noexcept;

  std::size_t point_count() const;
  std::size_t index_count() const;  // 3 per face

  // The indices as unsigned bytes, shorts or ints (component_type 5121, 5123 or 5125), tightly
  // packed. Throws if an index does not fit the type.
  std::string indices(int component_type) const;

  // The attribute with Draco unique id `unique_id`, `components` values of `component_type` per
  // point, each point `byte_stride` bytes apart (>= the element size; padding is zero). Values
  // are copied bit for bit when Draco stores the accessor's type, converted when the accessor is
  // float (normalized integers mapped as glTF does); anything else throws.
  std::string attribute(int unique_id, int component_type, int components, std::size_t byte_stride) const;

 private:
  std::unique_ptr<draco::Mesh> mesh_;
  std::string file_, where_;
};

}  // namespace vlit
