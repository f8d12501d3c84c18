#include "gltf/gltf_scene.h"

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <array>
#include <functional>

#include "core/affine.h"
#include "core/input_error.h"
#include "gltf/accessor_reader.h"
#include "gltf/extension_object.h"
#include "gltf/gltf_area_lights.h"
#include "gltf/gltf_linear_lights.h"
#include "mesh/vertex_normals.h"
#include "scene/emissive_lights.h"

namespace vlit {
namespace {

Affine local_transform(const tinygltf::Node& node) {
  Affine a;
  if (node.matrix.size() == 16) {
    // glTF matrices are column-major.
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) a.m[r][c] = node.matrix[c * 4 + r];
    return a;
  }
  Vec3d t{0, 0, 0}, s{1, 1, 1};
  std::array<double, 4> q{0, 0, 0, 1};
  if (node.translation.size() == 3) t = {node.translation[0], node.translation[1], node.translation[2]};
  if (node.scale.size() == 3) s = {node.scale[0], node.scale[1], node.scale[2]};
  if (node.rotation.size() == 4) q = {node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]};
  return Affine::from_trs(t, q, s);
}

Vec3d vec3_at(const std::vector<double>& data, std::size_t i) { return {data[3 * i], data[3 * i + 1], data[3 * i + 2]}; }

std::string limit_message(const char* what, std::size_t limit) {
  return std::string("the scene needs more than ") + std::to_string(limit) + " " + what +
         " (the limit that protects the machine; raise it with --max-vertices)";
}

// What build_scene collects besides the scene: the lights of emissive geometry (ranked and limited)
// and the state of the limits.
struct BuildState {
  explicit BuildState(const SceneLimits& limits) : emissive_lights(limits.max_emissive_lights) {}
  bool file_lights = true;
  bool vertex_colors = false;
  std::size_t vertices_so_far = 0, corners_so_far = 0;
  EmissiveLightSet emissive_lights;
};

bool is_line_mode(int mode) {
  return mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP;
}

const Material* material_at(const Scene& scene, int index) {
  return index >= 0 && static_cast<std::size_t>(index) < scene.materials.size() ? &scene.materials[index] : nullptr;
}

// COLOR_0 (VEC3 or VEC4; float, or normalized unsigned byte or short) as linear RGB, alpha dropped.
std::vector<Vec3f> read_vertex_colors(const GltfFile& file, int accessor, std::size_t vertex_count, const std::string& where) {
  const tinygltf::Model& model = file.model;
  if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size())
    throw InputError(file.path, "COLOR_0 accessor " + std::to_string(accessor) + " does not exist", where);
  const tinygltf::Accessor& acc = model.accessors[accessor];
  const int components = acc.type == TINYGLTF_TYPE_VEC3 ? 3 : acc.type == TINYGLTF_TYPE_VEC4 ? 4 : 0;
  if (components == 0) throw InputError(file.path, "COLOR_0 must be a VEC3 or VEC4 accessor", where);
  // Compare counts before reading (an accessor without a bufferView could be huge).
  if (acc.count != vertex_count) throw InputError(file.path, "COLOR_0 and POSITION counts differ", where);
  const std::vector<double> values = read_accessor_as_doubles(model, accessor, file.path);
  if (values.size() != vertex_count * components) throw InputError(file.path, "COLOR_0 and POSITION counts differ", where);
  std::vector<Vec3f> colors(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i) {
    const double* c = &values[i * components];
    colors[i] = static_cast<Vec3f>(Vec3d{c[0], c[1], c[2]});
    if (!is_finite(colors[i])) colors[i] = {0, 0, 0};
  }
  return colors;
}


// The primitive's POSITION accessor, nullptr when it has none; throws unless it is a VEC3 accessor.
const tinygltf::Accessor* position_accessor(const GltfFile& file, const tinygltf::Primitive& prim, const std::string& where) {
  const auto it = prim.attributes.find("POSITION");
  if (it == prim.attributes.end()) return nullptr;
  const tinygltf::Model& model = file.model;
  if (it->second < 0 || static_cast<std::size_t>(it->second) >= model.accessors.size() ||
      model.accessors[it->second].type != TINYGLTF_TYPE_VEC3)
    throw InputError(file.path, "POSITION must be a VEC3 accessor", where);
  return &model.accessors[it->second];
}

// Adds `count` vertices to the running total, throwing beyond limits.max_vertices. Limits are
// checked from the accessor counts alone, before anything is allocated. (Running totals, not
// scene.vertex_count(): that is a loop over the primitives, quadratic here.)
void count_vertices(std::size_t count, const SceneLimits& limits, BuildState& state, const std::string& file,
                    const std::string& where) {
  if (count > limits.max_vertices - std::min(state.vertices_so_far, limits.max_vertices))
    throw InputError(file, limit_message("vertices", limits.max_vertices), where);
  state.vertices_so_far += count;
}

// Adds the triangle corners of a primitive drawing `draw_count` indices in `mode` to the running
// total, throwing beyond kCornersPerVertex x max_vertices.
void count_corners(std::size_t draw_count, int mode, const SceneLimits& limits, BuildState& state, const std::string& file,
                   const std::string& where) {
  const std::size_t max_corners =
      limits.max_vertices > SIZE_MAX / (3 * SceneLimits::kCornersPerVertex) ? SIZE_MAX / 3
                                                                            : limits.max_vertices * SceneLimits::kCornersPerVertex;
  if (draw_count > max_corners) throw InputError(file, limit_message("triangle corners", max_corners), where);
  // A strip or a fan of n indices makes n - 2 triangles.
  const std::size_t corners = mode == TINYGLTF_MODE_TRIANGLES ? draw_count : 3 * draw_count;
  if (corners > max_corners - std::min(state.corners_so_far, max_corners))
    throw InputError(file, limit_message("triangle corners", max_corners), where);
  state.corners_so_far += corners;
}

// The accessor's positions (3 doubles each) in world space, non-finite ones included.
std::vector<Vec3d> world_positions(const std::vector<double>& pos, const Affine& world) {
  std::vector<Vec3d> out(pos.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = world.apply_point(vec3_at(pos, i));
  return out;
}

// An emissive LINES / LINE_STRIP / LINE_LOOP primitive: one linear light per segment; a segment
// with a non-finite end makes no light.
void read_emissive_lines(const GltfFile& file, const tinygltf::Primitive& prim, int mode, const std::string& where,
                         const Affine& world, const Material& material, const SceneLimits& limits, BuildState& state) {
  const tinygltf::Accessor* pos_acc = position_accessor(file, prim, where);
  if (!pos_acc) return;
  count_vertices(pos_acc->count, limits, state, file.path, where);
  const std::vector<double> pos = read_accessor_as_doubles(file.model, prim.attributes.at("POSITION"), file.path);
  const std::vector<Vec3d> positions = world_positions(pos, world);
  const std::vector<std::uint32_t> draw_order = draw_order_of(file.model, prim, positions.size(), file.path);
  auto lights = emissive_line_lights(positions, line_segments(mode, draw_order), material, file.path + ": " + where);
  for (auto& l : lights)
    if (is_finite(l.from) && is_finite(l.to)) state.emissive_lights.add(std::move(l));
}

// Non-finite positions set to the origin; returns which vertices they were (empty when none).
std::vector<bool> zero_non_finite(std::vector<Vec3d>& positions) {
  std::vector<bool> bad;
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!is_finite(positions[i])) {
      if (bad.empty()) bad.assign(positions.size(), false);
      bad[i] = true;
      positions[i] = {};
    }
  return bad;
}

// Keeps the triangles (3 indices each) none of whose corners is `bad`.
void drop_triangles_touching(std::vector<std::uint32_t>& triangles, const std::vector<bool>& bad) {
  std::vector<std::uint32_t> kept;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
    if (!bad[triangles[t]] && !bad[triangles[t + 1]] && !bad[triangles[t + 2]])
      kept.insert(kept.end(), triangles.begin() + t, triangles.begin() + t + 3);
  triangles = std::move(kept);
}

// World-space unit normals of `out` (whose positions and triangles are set): the NORMAL
// attribute transformed by the world transform, a zero or non-finite one replaced by the
// angle-weighted normal of the triangles (with a warning); all computed without the attribute.
void set_normals(const GltfFile& file, const tinygltf::Primitive& prim, const std::string& where, const Affine& world,
                 ScenePrimitive& out, std::vector<std::string>& warnings) {
  const tinygltf::Model& model = file.model;
  const std::size_t vertex_count = out.positions.size();
  const auto normal_it = prim.attributes.find("NORMAL");
  if (normal_it == prim.attributes.end()) {
    out.normals = angle_weighted_normals(out.positions, out.triangles);
    return;
  }
  // Compare counts before reading: a NORMAL accessor without a bufferView could be huge.
  if (normal_it->second >= 0 && static_cast<std::size_t>(normal_it->second) < model.accessors.size() &&
      model.accessors[normal_it->second].count != vertex_count)
    throw InputError(file.path, "NORMAL and POSITION counts differ", where);
  const std::vector<double> nrm = read_accessor_as_doubles(model, normal_it->second, file.path);
  if (nrm.size() != 3 * vertex_count) throw InputError(file.path, "NORMAL and POSITION counts differ", where);
  std::vector<Vec3d> computed;
  out.normals.resize(vertex_count);
  std::size_t repaired = 0;
  for (std::size_t i = 0; i < vertex_count; ++i) {
    const Vec3d n = normalize(world.apply_normal(vec3_at(nrm, i)));
    if (length_squared(n) == 0 || !is_finite(n)) {
      if (computed.empty()) computed = angle_weighted_normals(out.positions, out.triangles);
      out.normals[i] = computed[i];
      ++repaired;
    } else {
      out.normals[i] = n;
    }
  }
  if (repaired > 0)
    warnings.push_back(file.path + ": " + where + ": " + std::to_string(repaired) +
                       " zero or non-finite normals replaced by normals computed from the triangles");
}

void read_primitive(const GltfFile& file, int node_index, int mesh_index, int prim_index, const Affine& world,
                    Scene& scene, std::vector<std::string>& warnings, const SceneLimits& limits, BuildState& state) {
  const tinygltf::Model& model = file.model;
  const tinygltf::Primitive& prim = model.meshes[mesh_index].primitives[prim_index];
  const std::string where = "meshes[" + std::to_string(mesh_index) + "].primitives[" + std::to_string(prim_index) + "]";
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  const Material* material = material_at(scene, prim.material);
  if (is_line_mode(mode) && state.file_lights && material && emits_light(*material)) {
    read_emissive_lines(file, prim, mode, where, world, *material, limits, state);
    return;
  }
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    warnings.push_back(file.path + ": " + where + ": skipped (mode " + std::to_string(mode) + " is not triangles)");
    return;
  }
  const tinygltf::Accessor* pos_acc = position_accessor(file, prim, where);
  if (!pos_acc) {
    warnings.push_back(file.path + ": " + where + ": skipped (no POSITION attribute)");
    return;
  }
  count_vertices(pos_acc->count, limits, state, file.path, where);
  const std::size_t draw_count = prim.indices >= 0 && static_cast<std::size_t>(prim.indices) < model.accessors.size()
                                     ? model.accessors[prim.indices].count : pos_acc->count;
  count_corners(draw_count, mode, limits, state, file.path, where);

  ScenePrimitive out;
  out.node = node_index;
  out.mesh = mesh_index;
  out.primitive = prim_index;
  out.material = prim.material;
  out.positions = world_positions(read_accessor_as_doubles(model, prim.attributes.at("POSITION"), file.path), world);
  out.triangles = triangle_list(mode, draw_order_of(model, prim, out.positions.size(), file.path));
  if (world.determinant() < 0)  // a mirroring transform flips winding: restore counter-clockwise front faces
    for (std::size_t t = 0; t + 2 < out.triangles.size(); t += 3) std::swap(out.triangles[t + 1], out.triangles[t + 2]);
  // Triangles touching a vertex with a non-finite position are dropped; those vertices get no light.
  const std::vector<bool> bad = zero_non_finite(out.positions);
  if (!bad.empty()) {
    warnings.push_back(file.path + ": " + where + ": " + std::to_string(std::count(bad.begin(), bad.end(), true)) +
                       " vertices have non-finite positions; they receive no light");
    drop_triangles_touching(out.triangles, bad);
  }
  if (const auto color_it = prim.attributes.find("COLOR_0"); state.vertex_colors && color_it != prim.attributes.end())
    out.colors = read_vertex_colors(file, color_it->second, out.positions.size(), where);
  set_normals(file, prim, where, world, out, warnings);
  // A vertex whose position was not finite sits at the origin with a zero normal: every light
  // model gives zero for a zero normal, so it receives no light, as the warning says.
  for (std::size_t i = 0; i < bad.size(); ++i)
    if (bad[i]) out.normals[i] = {};
  if (state.file_lights && material && emits_light(*material)) {
    state.emissive_lights.add_triangles(out, scene.primitives.size(), *material,
                                        file.path + ": nodes[" + std::to_string(node_index) + "] " + where);
  }
  scene.primitives.push_back(std::move(out));
}

Material read_material(const GltfFile& file, std::size_t index, std::vector<std::string>& warnings) {
  const tinygltf::Material& m = file.model.materials[index];
  const std::string where = "materials[" + std::to_string(index) + "]";
  Material out;
  if (m.emissiveFactor.size() == 3) out.emissive_factor = {m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]};
  if (!is_finite(out.emissive_factor) || out.emissive_factor.x < 0 || out.emissive_factor.y < 0 || out.emissive_factor.z < 0)
    throw InputError(file.path, "emissiveFactor must be finite and >= 0", where);
  if (const auto ext = m.extensions.find("KHR_materials_emissive_strength"); ext != m.extensions.end()) {
    ExtensionObject strength(ext->second, file.path, where + ".extensions.KHR_materials_emissive_strength");
    out.emissive_strength = strength.number("emissiveStrength", 1.0);
    if (out.emissive_strength < 0) strength.fail("emissiveStrength", "must be >= 0");
  }
  out.emissive_texture = m.emissiveTexture.index >= 0;
  const Vec3d e = out.emission();
  if (out.emissive_texture && (e.x > 0 || e.y > 0 || e.z > 0))
    warnings.push_back(file.path + ": " + where + ": emission comes from a texture, which vlit does not sample; "
                       "the material is not used as a light");
  const auto& f = m.pbrMetallicRoughness.baseColorFactor;
  if (f.size() >= 3) out.base_color = {f[0], f[1], f[2]};
  out.base_color_texture = m.pbrMetallicRoughness.baseColorTexture.index >= 0;
  out.metallic = m.pbrMetallicRoughness.metallicFactor;
  out.roughness = m.pbrMetallicRoughness.roughnessFactor;
  out.double_sided = m.doubleSided;
  out.name = m.name;
  for (double* v : {&out.base_color.x, &out.base_color.y, &out.base_color.z, &out.metallic, &out.roughness})
    if (!std::isfinite(*v)) *v = 1;
  return out;
}

std::optional<SceneCamera> read_camera(const tinygltf::Camera& cam, const Affine& world) {
  SceneCamera c;
  c.position = world.apply_point({0, 0, 0});
  c.right = normalize(world.apply_vector({1, 0, 0}));
  c.up = normalize(world.apply_vector({0, 1, 0}));
  c.back = normalize(cross(c.right, c.up));
  c.up = cross(c.back, c.right);
  if (cam.type == "orthographic") {
    c.orthographic = true;
    c.xmag = cam.orthographic.xmag;
    c.ymag = cam.orthographic.ymag;
    c.znear = cam.orthographic.znear;
    c.zfar = cam.orthographic.zfar;
    if (!(c.xmag != 0 && c.ymag != 0 && *c.zfar > c.znear)) return std::nullopt;
  } else {
    c.yfov = cam.perspective.yfov;
    if (cam.perspective.aspectRatio > 0) c.aspect = cam.perspective.aspectRatio;
    c.znear = cam.perspective.znear;
    if (cam.perspective.zfar > 0) c.zfar = cam.perspective.zfar;
    if (!(c.yfov > 0 && c.yfov < M_PI && c.znear > 0)) return std::nullopt;
  }
  if (!is_finite(c.position) || !is_finite(c.right) || !is_finite(c.up) || length_squared(c.back) == 0) return std::nullopt;
  return c;
}

// KHR_lights_punctual light `index`, placed by the node's world transform (the light sits at the
// node's origin and points down its local -Z). glTF units map directly onto our kernels:
// point and spot intensity in candela with inverse-square falloff, directional in lux.
std::optional<LightSource> read_punctual_light(const GltfFile& file, int node_index, int index, const Affine& world,
                                               std::vector<std::string>& warnings) {
  const tinygltf::Model& model = file.model;
  const std::string where = "nodes[" + std::to_string(node_index) + "]";
  if (index < 0 || static_cast<std::size_t>(index) >= model.lights.size()) {
    warnings.push_back(file.path + ": " + where + ": KHR_lights_punctual light " + std::to_string(index) +
                       " does not exist; ignored");
    return std::nullopt;
  }
  const tinygltf::Light& l = model.lights[index];
  LightSource out;
  out.name = l.name.empty() ? file.path + ": lights[" + std::to_string(index) + "]" : l.name;
  if (l.color.size() == 3) out.color = {l.color[0], l.color[1], l.color[2]};
  out.intensity = l.intensity;
  out.falloff = 2;
  if (l.range > 0) out.range = l.range;
  out.position = world.apply_point({0, 0, 0});
  out.direction = normalize(world.apply_vector({0, 0, -1}));
  if (l.type == "point") {
    out.type = LightType::kPoint;
  } else if (l.type == "directional") {
    out.type = LightType::kDirectional;
  } else if (l.type == "spot") {
    out.type = LightType::kSpot;
    const double outer = std::clamp(l.spot.outerConeAngle, 0.0, M_PI / 2);
    const double inner = std::clamp(l.spot.innerConeAngle, 0.0, outer);
    out.cos_inner = std::cos(inner);
    out.cos_outer = std::cos(outer);
  } else {
    warnings.push_back(file.path + ": lights[" + std::to_string(index) + "]: unknown type \"" + l.type + "\"; ignored");
    return std::nullopt;
  }
  const bool finite = std::isfinite(out.intensity) && out.intensity >= 0 && is_finite(out.color) && is_finite(out.position);
  if (!finite || (out.type != LightType::kPoint && length_squared(out.direction) == 0)) {
    warnings.push_back(file.path + ": lights[" + std::to_string(index) + "]: invalid intensity, colour or transform; ignored");
    return std::nullopt;
  }
  return out;
}

}  // namespace

std::vector<std::uint32_t> triangle_list(int mode, const std::vector<std::uint32_t>& idx) {
  std::vector<std::uint32_t> tris;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    tris.assign(idx.begin(), idx.begin() + static_cast<long>(idx.size() - idx.size() % 3));
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 2; i < idx.size(); ++i) {
      // glTF spec: triangle i uses {i, i+1, i+2} for even i and {i+1, i, i+2} for odd i (0-based i = i-2 here).
      if ((i - 2) % 2 == 0) tris.insert(tris.end(), {idx[i - 2], idx[i - 1], idx[i]});
      else tris.insert(tris.end(), {idx[i - 1], idx[i - 2], idx[i]});
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (std::size_t i = 2; i < idx.size(); ++i) tris.insert(tris.end(), {idx[i - 1], idx[i], idx[0]});
  }
  return tris;
}

std::vector<std::uint32_t> line_segments(int mode, const std::vector<std::uint32_t>& idx) {
  std::vector<std::uint32_t> out;
  if (mode == 1) {  // LINES
    for (std::size_t i = 0; i + 1 < idx.size(); i += 2) out.insert(out.end(), {idx[i], idx[i + 1]});
  } else if (mode == 3 || mode == 2) {  // LINE_STRIP, LINE_LOOP
    for (std::size_t i = 0; i + 1 < idx.size(); ++i) out.insert(out.end(), {idx[i], idx[i + 1]});
    if (mode == 2 && idx.size() > 2) out.insert(out.end(), {idx.back(), idx.front()});
  }
  return out;
}

SceneLimits default_scene_limits() { return SceneLimits{}; }

Scene build_scene(const GltfFile& file, std::vector<std::string>& warnings, const SceneOptions& options) {
  const tinygltf::Model& model = file.model;
  const bool file_lights = options.file_lights;
  const SceneLimits& limits = options.limits;
  BuildState state(limits);
  state.file_lights = file_lights;
  state.vertex_colors = options.vertex_colors;
  Scene scene;
  for (std::size_t m = 0; m < model.materials.size(); ++m) scene.materials.push_back(read_material(file, m, warnings));
  std::vector<AreaLightDefinition> area_lights;
  std::vector<LinearLightDefinition> linear_lights;
  if (file_lights) {
    area_lights = read_area_light_definitions(file, warnings);
    linear_lights = read_linear_light_definitions(file);
  }

  // Roots: the default scene's nodes; without scenes, every node that is nobody's child.
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const int s = model.defaultScene >= 0 && static_cast<std::size_t>(model.defaultScene) < model.scenes.size()
                      ? model.defaultScene : 0;
    roots = model.scenes[s].nodes;
  } else {
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const auto& n : model.nodes)
      for (int c : n.children)
        if (c >= 0 && static_cast<std::size_t>(c) < model.nodes.size()) is_child[c] = true;
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
      if (!is_child[i]) roots.push_back(static_cast<int>(i));
  }

  // Depth first, parents before children, in file order, with an explicit stack: a chain of nodes
  // as deep as the file is long must not overflow the call stack (a recursive walk did, on a
  // chain of 10^5 nodes: tests/robustness/limits_test.cpp).
  std::vector<int> visits(model.nodes.size(), 0);
  std::vector<std::pair<int, Affine>> stack;
  for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.emplace_back(*r, Affine{});
  while (!stack.empty()) {
    const int index = stack.back().first;
    const Affine parent = stack.back().second;
    stack.pop_back();
    if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size())
      throw InputError(file.path, "node " + std::to_string(index) + " does not exist");
    if (visits[index]++ > 0)
      throw InputError(file.path, "node " + std::to_string(index) + " is reached twice (a cycle or a node with two parents)");
    const tinygltf::Node& node = model.nodes[index];
    const Affine world = parent * local_transform(node);
    if (!world.is_finite()) throw InputError(file.path, "transform is not finite", "nodes[" + std::to_string(index) + "]");
    if (node.mesh >= 0) {
      if (static_cast<std::size_t>(node.mesh) >= model.meshes.size())
        throw InputError(file.path, "mesh " + std::to_string(node.mesh) + " does not exist", "nodes[" + std::to_string(index) + "]");
      for (std::size_t p = 0; p < model.meshes[node.mesh].primitives.size(); ++p)
        read_primitive(file, index, node.mesh, static_cast<int>(p), world, scene, warnings, limits, state);
    }
    if (node.camera >= 0 && static_cast<std::size_t>(node.camera) < model.cameras.size() &&
        std::none_of(scene.cameras.begin(), scene.cameras.end(), [&](const SceneCamera& c) { return c.index == node.camera; }))
      if (auto camera = read_camera(model.cameras[node.camera], world)) {
        camera->index = node.camera;
        camera->name = model.cameras[node.camera].name.empty() ? node.name : model.cameras[node.camera].name;
        scene.cameras.push_back(std::move(*camera));
      }
    if (file_lights && node.extensions.count(kExtLightsArea))
      if (auto light = place_area_light(file, area_lights, index, world, warnings)) scene.lights.push_back(*light);
    if (file_lights && node.extensions.count(kVlitLightsLinear))
      if (auto light = place_linear_light(file, linear_lights, index, world, warnings)) scene.lights.push_back(*light);
    if (const auto ext = node.extensions.find("KHR_lights_punctual"); file_lights && ext != node.extensions.end() &&
                                                                   ext->second.Has("light")) {
      const tinygltf::Value& light_ref = ext->second.Get("light");
      if (light_ref.IsInt())
        if (auto light = read_punctual_light(file, index, light_ref.Get<int>(), world, warnings))
          scene.lights.push_back(*light);
    }
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.emplace_back(*child, world);
  }

  for (auto& p : scene.primitives)
    if (p.material >= static_cast<int>(scene.materials.size())) {
      warnings.push_back(file.path + ": material " + std::to_string(p.material) + " does not exist; using the default material");
      p.material = -1;
    }

  // Emissive geometry: the brightest max_emissive_lights lights, by luminous flux.
  state.emissive_lights.finish(file.path, scene.lights, warnings);
  return scene;
}

}  // namespace vlit
