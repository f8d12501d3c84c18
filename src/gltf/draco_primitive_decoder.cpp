#include "gltf/draco_primitive_decoder.h"

#include <cstring>
#include <vector>

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>
#include <tiny_gltf.h>

#include "core/input_error.h"
#include "gltf/accessor_reader.h"

namespace vlit {
namespace {

// The glTF component type that stores a Draco data type unchanged, or 0.
int gltf_component_type(draco::DataType type) {
  switch (type) {
    case draco::DT_INT8: return TINYGLTF_COMPONENT_TYPE_BYTE;
    case draco::DT_UINT8: return TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    case draco::DT_INT16: return TINYGLTF_COMPONENT_TYPE_SHORT;
    case draco::DT_UINT16: return TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    case draco::DT_UINT32: return TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    case draco::DT_FLOAT32: return TINYGLTF_COMPONENT_TYPE_FLOAT;
    default: return 0;
  }
}

}  // namespace

DracoPrimitive::DracoPrimitive(std::string_view compressed, const std::string& file, const std::string& where)
    : file_(file), where_(where) {
  draco::DecoderBuffer buffer;
  buffer.Init(compressed.data(), compressed.size());
  const auto geometry = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!geometry.ok() || geometry.value() != draco::TRIANGULAR_MESH)
    throw InputError(file, "the KHR_draco_mesh_compression data is not a Draco triangle mesh", where);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok())
    throw InputError(file, "the KHR_draco_mesh_compression data does not decode: " + decoded.status().error_msg_string(), where);
  mesh_ = std::move(decoded).value();
}

DracoPrimitive::~DracoPrimitive() = default;
DracoPrimitive::DracoPrimitive(DracoPrimitive&&) noexcept = default;

std::size_t DracoPrimitive::point_count() const { return mesh_->num_points(); }
std::size_t DracoPrimitive::index_count() const { return std::size_t(mesh_->num_faces()) * 3; }

std::string DracoPrimitive::indices(int component_type) const {
  const std::size_t size = static_cast<std::size_t>(component_bytes(component_type));
  if (size == 0 || component_type == TINYGLTF_COMPONENT_TYPE_FLOAT || component_type == TINYGLTF_COMPONENT_TYPE_BYTE ||
      component_type == TINYGLTF_COMPONENT_TYPE_SHORT)
    throw InputError(file_, "the index accessor's componentType must be an unsigned integer", where_);
  const std::uint64_t limit = size == 4 ? 0xFFFFFFFFull : (std::uint64_t(1) << (8 * size)) - 1;
  std::string out(index_count() * size, '\0');
  char* p = out.data();
  for (draco::FaceIndex f(0); f < mesh_->num_faces(); ++f)
    for (const draco::PointIndex& point : mesh_->face(f)) {
      const std::uint32_t v = point.value();
      if (v > limit)
        throw InputError(file_, "index " + std::to_string(v) + " does not fit the index accessor's componentType", where_);
      if (size == 1) *p = static_cast<char>(v);
      else if (size == 2) { const std::uint16_t s = static_cast<std::uint16_t>(v); std::memcpy(p, &s, 2); }
      else std::memcpy(p, &v, 4);
      p += size;
    }
  return out;
}

std::string DracoPrimitive::attribute(int unique_id, int component_type, int components, std::size_t byte_stride) const {
  const std::string id = std::to_string(unique_id);
  const draco::PointAttribute* attr = unique_id >= 0 ? mesh_->GetAttributeByUniqueId(static_cast<std::uint32_t>(unique_id)) : nullptr;
  if (!attr) throw InputError(file_, "no Draco attribute with id " + id, where_);
  if (attr->num_components() != components)
    throw InputError(file_, "Draco attribute " + id + " has " + std::to_string(int(attr->num_components())) +
                                " components, its accessor " + std::to_string(components), where_);
  const std::size_t element = static_cast<std::size_t>(component_bytes(component_type)) * static_cast<std::size_t>(components);
  if (element == 0 || byte_stride < element) throw InputError(file_, "unsupported accessor layout for Draco attribute " + id, where_);
  const bool same_type = gltf_component_type(attr->data_type()) == component_type;
  if (!same_type && component_type != TINYGLTF_COMPONENT_TYPE_FLOAT)
    throw InputError(file_, "Draco attribute " + id + " does not store its accessor's componentType", where_);
  if (same_type && attr->byte_stride() != static_cast<std::int64_t>(element))
    throw InputError(file_, "Draco attribute " + id + " has an unexpected layout", where_);

  std::string out(point_count() * byte_stride, '\0');
  std::vector<float> converted(static_cast<std::size_t>(components));
  for (draco::PointIndex i(0); i < mesh_->num_points(); ++i) {
    char* dst = out.data() + std::size_t(i.value()) * byte_stride;
    const draco::AttributeValueIndex value = attr->mapped_index(i);
    if (value.value() >= attr->size()) throw InputError(file_, "Draco attribute " + id + " maps a point out of range", where_);
    if (same_type) {
      attr->GetValue(value, dst);
    } else {
      if (!attr->ConvertValue<float>(value, static_cast<std::int8_t>(components), converted.data()))
        throw InputError(file_, "Draco attribute " + id + " cannot be converted to float", where_);
      std::memcpy(dst, converted.data(), element);
    }
  }
  return out;
}

}  // namespace vlit
