#include "bake/vertex_color_bake.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>

#include "gltf/accessor_reader.h"
#include "scene/material.h"
#include "shading/shading_policy.h"

namespace vlit {
namespace {

// Gives every node that instances a mesh its own copy of that mesh (the first user keeps the
// original), so per-instance light can be stored. Returns node -> mesh after duplication.
std::map<int, int> unshare_meshes(tinygltf::Model& model, const Scene& scene, std::size_t& duplicated) {
  std::map<int, int> mesh_of_node;
  std::map<int, int> first_user;
  for (const ScenePrimitive& p : scene.primitives) {
    if (p.node < 0 || mesh_of_node.count(p.node)) continue;
    const auto [it, inserted] = first_user.emplace(p.mesh, p.node);
    if (inserted) {
      mesh_of_node[p.node] = p.mesh;
    } else {
      model.meshes.push_back(model.meshes[p.mesh]);
      const int copy = static_cast<int>(model.meshes.size()) - 1;
      model.nodes[p.node].mesh = copy;
      mesh_of_node[p.node] = copy;
      ++duplicated;
    }
  }
  return mesh_of_node;
}

void append_aligned(std::vector<unsigned char>& data, const void* bytes, std::size_t n) {
  while (data.size() % 4 != 0) data.push_back(0);
  const auto* b = static_cast<const unsigned char*>(bytes);
  data.insert(data.end(), b, b + n);
}

// n of COLOR_n, -1 for any other attribute name.
int color_set_index(const std::string& target) {
  if (target.rfind("COLOR_", 0) != 0) return -1;
  try {
    return std::stoi(target.substr(6));
  } catch (const std::exception&) {
    return -1;
  }
}

// The base-colour multiplier to store for each vertex of one primitive, RGBA: light x exposure,
// times the old colour in multiply mode, plus the specular (shading/shading_policy.h).
std::vector<std::array<double, 4>> vertex_multipliers(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                                                      const Scene& scene, const ScenePrimitive& sp,
                                                      const VertexLight& vertex_light, const BakeOptions& options,
                                                      BakeReport& report) {
  const std::string& file = options.source;
  const std::size_t n = sp.positions.size();
  const auto& diffuse = vertex_light.diffuse;
  std::vector<std::array<double, 4>> rgba(n);
  for (std::size_t v = 0; v < n; ++v)
    rgba[v] = {diffuse[v].x * options.exposure, diffuse[v].y * options.exposure, diffuse[v].z * options.exposure, 1.0};
  const auto existing = prim.attributes.find(options.target);
  if (existing != prim.attributes.end()) {
    ++report.replaced_attributes;
    if (options.mode == BakeMode::kMultiply) {
      const std::vector<double> old = read_accessor_as_doubles(model, existing->second, file);
      const int comps = n > 0 ? static_cast<int>(old.size() / n) : 0;
      if ((comps == 3 || comps == 4) && old.size() == n * comps)
        for (std::size_t v = 0; v < n; ++v) {
          for (int ch = 0; ch < 3; ++ch) rgba[v][ch] *= old[v * comps + ch];
          if (comps == 4) rgba[v][3] = old[v * comps + 3];
        }
    }
  }
  // Specular folded into the multiplier of the base colour (shading/shading_policy.h). In
  // multiply mode the old colour multiplies the diffuse only, so viewer = old x base x diffuse
  // + ks x specular holds without dividing by the old colour.
  const auto& specular = vertex_light.specular;
  if (!specular.empty()) {
    const PhongMaterial phong = phong_from_metallic_roughness(scene.material_of(sp));
    for (std::size_t v = 0; v < n; ++v)
      if (!add_specular_to_multiplier(phong, static_cast<Vec3d>(specular[v]), options.exposure, rgba[v]))
        ++report.specular_unrepresentable;
  }

  return rgba;
}

// Appends the multipliers to `buffer` (index buffer_index) in options.format, with a buffer view
// and an accessor; returns the accessor's index.
int append_color_accessor(tinygltf::Model& model, tinygltf::Buffer& buffer, int buffer_index,
                          const std::vector<std::array<double, 4>>& rgba, const BakeOptions& options,
                          BakeReport& report) {
  const std::size_t n = rgba.size();
  const std::size_t offset = (buffer.data.size() + 3) / 4 * 4;
  std::size_t byte_length = 0;
  int component_type = 0;
  int type = TINYGLTF_TYPE_VEC4;
  bool normalized = true;
  if (options.format == ColorFormat::kFloat) {
    std::vector<float> values(n * 4);
    for (std::size_t v = 0; v < n; ++v)
      for (int ch = 0; ch < 4; ++ch) {
        const double x = rgba[v][ch];
        // NaN and negatives become 0; values beyond the float range saturate.
        values[4 * v + ch] = x > 0 ? static_cast<float>(std::min(x, double(std::numeric_limits<float>::max()))) : 0.0f;
      }
    append_aligned(buffer.data, values.data(), values.size() * sizeof(float));
    byte_length = values.size() * sizeof(float);
    component_type = TINYGLTF_COMPONENT_TYPE_FLOAT;
    normalized = false;
  } else {
    // Normalized integers, VEC4 so every element is 4-byte aligned.
    const bool wide = options.format == ColorFormat::kUnorm16;
    const double max_code = wide ? 65535.0 : 255.0;
    std::vector<std::uint16_t> codes16;
    std::vector<std::uint8_t> codes8;
    for (std::size_t v = 0; v < n; ++v) {
      bool clipped = false;
      for (int ch = 0; ch < 4; ++ch) {
        double x = rgba[v][ch];
        if (!(x >= 0)) x = 0;  // also catches NaN
        if (x > 1) { clipped = true; x = 1; }
        const double code = std::round(x * max_code);
        report.max_quantization_error = std::max(report.max_quantization_error, std::abs(code / max_code - x));
        if (wide) codes16.push_back(static_cast<std::uint16_t>(code));
        else codes8.push_back(static_cast<std::uint8_t>(code));
      }
      if (clipped) ++report.clipped_vertices;
    }
    if (wide) {
      append_aligned(buffer.data, codes16.data(), codes16.size() * 2);
      byte_length = codes16.size() * 2;
      component_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    } else {
      append_aligned(buffer.data, codes8.data(), codes8.size());
      byte_length = codes8.size();
      component_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    }
  }

  tinygltf::BufferView view;
  view.buffer = buffer_index;
  view.byteOffset = offset;
  view.byteLength = byte_length;
  view.target = TINYGLTF_TARGET_ARRAY_BUFFER;
  model.bufferViews.push_back(view);

  tinygltf::Accessor acc;
  acc.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
  acc.byteOffset = 0;
  acc.componentType = component_type;
  acc.normalized = normalized;
  acc.count = n;
  acc.type = type;
  model.accessors.push_back(acc);

  return static_cast<int>(model.accessors.size()) - 1;
}

// Marks every material KHR_materials_unlit, and gives the baked primitives without a material an
// unlit default one.
void mark_unlit(tinygltf::Model& model, const std::string& target) {
  const std::string unlit = "KHR_materials_unlit";
  for (auto& m : model.materials) m.extensions[unlit] = tinygltf::Value(tinygltf::Value::Object());
  // Primitives without a material use glTF's default (lit) material: give them an unlit one.
  bool needs_default = false;
  for (auto& mesh : model.meshes)
    for (auto& prim : mesh.primitives)
      if (prim.material < 0 && prim.attributes.count(target)) needs_default = true;
  if (needs_default) {
    tinygltf::Material m;
    m.name = "vlit default (unlit)";
    m.pbrMetallicRoughness.baseColorFactor = {1, 1, 1, 1};
    m.extensions[unlit] = tinygltf::Value(tinygltf::Value::Object());
    model.materials.push_back(m);
    const int index = static_cast<int>(model.materials.size()) - 1;
    for (auto& mesh : model.meshes)
      for (auto& prim : mesh.primitives)
        if (prim.material < 0 && prim.attributes.count(target)) prim.material = index;
  }
  if (!model.materials.empty() &&
      std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), unlit) == model.extensionsUsed.end())
    model.extensionsUsed.push_back(unlit);
}

}  // namespace

BakeReport bake_vertex_colors(tinygltf::Model& model, const Scene& scene, const std::vector<VertexLight>& light,
                              const BakeOptions& options) {
  BakeReport report;
  std::vector<double> peaks;  // per vertex, its brightest RGB channel (unorm formats)
  const auto mesh_of_node = unshare_meshes(model, scene, report.duplicated_meshes);

  // All colours go into one new buffer.
  tinygltf::Buffer buffer;
  buffer.name = "vlit baked vertex light";
  const int buffer_index = static_cast<int>(model.buffers.size());

  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const ScenePrimitive& sp = scene.primitives[i];
    if (sp.node < 0) continue;
    tinygltf::Primitive& prim = model.meshes[mesh_of_node.at(sp.node)].primitives[sp.primitive];
    const auto rgba = vertex_multipliers(model, prim, scene, sp, light[i], options, report);
    prim.attributes[options.target] = append_color_accessor(model, buffer, buffer_index, rgba, options, report);
    // glTF 2.0 section 3.7.2.1: the indices of COLOR_n start at 0 and are consecutive. A bake into
    // COLOR_n of a primitive that lacks a lower set fills it with white, the multiplier a viewer
    // assumes when COLOR_0 is absent, so the asset looks as before and stays valid.
    for (int set = 0; set < color_set_index(options.target); ++set)
      if (const std::string name = "COLOR_" + std::to_string(set); !prim.attributes.count(name)) {
        const std::vector<std::array<double, 4>> white(rgba.size(), {1.0, 1.0, 1.0, 1.0});
        prim.attributes[name] = append_color_accessor(model, buffer, buffer_index, white, options, report);
        ++report.filled_color_sets;
      }
    report.vertices += rgba.size();
    if (options.format != ColorFormat::kFloat)
      for (const auto& c : rgba) {
        const double peak = std::max({c[0], c[1], c[2]});
        peaks.push_back(peak > 0 ? peak : 0);  // also catches NaN
      }
  }
  if (!buffer.data.empty()) model.buffers.push_back(std::move(buffer));
  if (options.mark_unlit) mark_unlit(model, options.target);
  if (!peaks.empty()) {
    // The 99th percentile: the value at rank ceil(0.99 n) - 1 in ascending order.
    const std::size_t rank = (peaks.size() * 99 + 99) / 100 - 1;
    std::nth_element(peaks.begin(), peaks.begin() + static_cast<long>(rank), peaks.end());
    report.brightest_channel_p99 = peaks[rank];
    report.brightest_channel = *std::max_element(peaks.begin() + static_cast<long>(rank), peaks.end());
  }
  return report;
}

}  // namespace vlit
