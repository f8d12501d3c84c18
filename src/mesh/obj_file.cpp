#include "mesh/obj_file.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <unordered_map>

#include "core/input_error.h"
#include "io/read_file.h"
#include "mesh/mtl_file.h"
#include "mesh/vertex_normals.h"
#include "mesh/wavefront_statements.h"

namespace vlit {
namespace {

constexpr std::uint32_t kNoNormal = UINT32_MAX;

struct Corner {
  std::uint32_t position;
  std::uint32_t normal;  // kNoNormal when the face gives none
};

// The faces of one `usemtl` name ("" before any usemtl), fan-triangulated.
struct FaceGroup {
  std::string material;
  std::vector<Corner> corners;  // 3 per triangle
};

// An OBJ index (1-based, or negative counting back from the last element read so far) as a
// 0-based index; throws naming the line when it is 0, out of range or not an integer.
std::uint32_t resolve_index(std::string_view token, std::size_t count, const char* what, const char* what_plural,
                            const std::string& path, std::size_t line) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (token.empty() || ec != std::errc() || end != token.data() + token.size())
    throw InputError(path, std::string("f: ") + what + " index '" + std::string(token) + "' is not an integer",
                     wavefront_line(line));
  const long long n = static_cast<long long>(count);
  const long long index = value > 0 ? value - 1 : n + value;
  if (value == 0 || index < 0 || index >= n)
    throw InputError(path, std::string("f: ") + what + " index " + std::string(token) + " is out of range (" +
                               std::to_string(count) + " " + what_plural + " so far)",
                     wavefront_line(line));
  return static_cast<std::uint32_t>(index);
}

// `v`, `v/vt`, `v//vn` or `v/vt/vn`.
Corner read_corner(const std::string& token, std::size_t positions, std::size_t normals, const std::string& path,
                   std::size_t line) {
  const std::string_view t = token;
  const std::size_t slash = t.find('/');
  Corner c{resolve_index(t.substr(0, slash), positions, "vertex", "vertices", path, line), kNoNormal};
  if (slash == std::string_view::npos) return c;
  const std::size_t slash2 = t.find('/', slash + 1);
  if (slash2 == std::string_view::npos) return c;  // v/vt: texture coordinates are not used
  const std::string_view normal = t.substr(slash2 + 1);
  if (!normal.empty()) c.normal = resolve_index(normal, normals, "normal", "normals", path, line);
  return c;
}

Vec3d read_vec3(const WavefrontStatement& s, const std::string& path, bool finite_only) {
  if (s.arguments.size() < 3)
    throw InputError(path, s.keyword + " needs 3 numbers, got " + std::to_string(s.arguments.size()),
                     wavefront_line(s.line));
  return {parse_wavefront_number(s.arguments[0], s.keyword, path, s.line, finite_only),
          parse_wavefront_number(s.arguments[1], s.keyword, path, s.line, finite_only),
          parse_wavefront_number(s.arguments[2], s.keyword, path, s.line, finite_only)};
}

// The materials of every `mtllib` file (later definitions of a name replace earlier ones). A file
// that does not exist is a warning naming the OBJ and the .mtl; a malformed one is an error.
std::map<std::string, MtlMaterial> read_libraries(const std::string& obj_path, const std::vector<std::string>& names,
                                                  std::vector<std::string>& warnings) {
  std::map<std::string, MtlMaterial> materials;
  std::set<std::string> read;
  const std::filesystem::path folder = std::filesystem::path(obj_path).parent_path();
  for (const std::string& name : names) {
    const std::string mtl_path = (folder / name).lexically_normal().string();
    if (!read.insert(mtl_path).second) continue;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(mtl_path, ec)) {
      warnings.push_back(obj_path + ": mtllib " + name + ": cannot open " + mtl_path +
                         "; the faces that use its materials are grey");
      continue;
    }
    for (MtlMaterial& m : read_mtl_file(mtl_path, warnings)) {
      const std::string key = m.name;
      materials.insert_or_assign(key, std::move(m));
    }
  }
  return materials;
}

}  // namespace

Scene load_obj_file(const std::string& path, std::vector<std::string>& warnings, std::size_t max_vertices) {
  const std::string text = read_text_file(path);
  std::vector<Vec3d> positions, normals;
  std::vector<std::string> libraries;
  std::vector<FaceGroup> groups;
  std::map<std::string, std::size_t> group_of;
  std::size_t current = SIZE_MAX;  // index into groups; created on the first face
  std::string current_material;
  std::vector<Corner> polygon;
  for_each_wavefront_statement(text, [&](const WavefrontStatement& s) {
    if (s.keyword == "v") {
      if (positions.size() >= max_vertices)
        throw InputError(path, "the mesh has more than " + std::to_string(max_vertices) +
                                   " vertices (the limit that protects the machine; raise it with --max-vertices)");
      positions.push_back(read_vec3(s, path, false));
    } else if (s.keyword == "vn") {
      if (normals.size() >= max_vertices)
        throw InputError(path, "the mesh has more than " + std::to_string(max_vertices) +
                                   " normals (the limit that protects the machine; raise it with --max-vertices)");
      normals.push_back(read_vec3(s, path, false));
    } else if (s.keyword == "f") {
      if (s.arguments.size() < 3)
        throw InputError(path, "f needs at least 3 corners, got " + std::to_string(s.arguments.size()),
                         wavefront_line(s.line));
      polygon.clear();
      for (const std::string& token : s.arguments)
        polygon.push_back(read_corner(token, positions.size(), normals.size(), path, s.line));
      if (current == SIZE_MAX) {
        auto [it, added] = group_of.try_emplace(current_material, groups.size());
        if (added) groups.push_back(FaceGroup{current_material, {}});
        current = it->second;
      }
      auto& corners = groups[current].corners;
      for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
        corners.insert(corners.end(), {polygon[0], polygon[k], polygon[k + 1]});
    } else if (s.keyword == "usemtl") {
      if (s.rest.empty()) throw InputError(path, "usemtl needs a material name", wavefront_line(s.line));
      current_material = s.rest;
      current = SIZE_MAX;
    } else if (s.keyword == "mtllib") {
      if (s.arguments.empty()) throw InputError(path, "mtllib needs a file name", wavefront_line(s.line));
      libraries.insert(libraries.end(), s.arguments.begin(), s.arguments.end());
    }
    // Every other statement is ignored (the header's list).
  });
  if (groups.empty()) throw InputError(path, "the mesh has no faces");

  // Non-finite positions: at the origin with a zero normal, so they receive no light.
  std::vector<bool> bad_position(positions.size(), false);
  std::size_t non_finite = 0;
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!is_finite(positions[i])) { positions[i] = {}; bad_position[i] = true; ++non_finite; }
  if (non_finite > 0)
    warnings.push_back(path + ": " + std::to_string(non_finite) + " vertices have non-finite positions; they receive no light");

  // Normals for corners without one (or with a zero or non-finite one): over the whole file.
  std::vector<Vec3d> computed;
  auto computed_normal = [&](std::uint32_t position) {
    if (computed.empty()) {
      std::vector<std::uint32_t> triangles;
      for (const FaceGroup& g : groups)
        for (const Corner& c : g.corners) triangles.push_back(c.position);
      computed = angle_weighted_normals(positions, triangles);
    }
    return computed[position];
  };

  const std::map<std::string, MtlMaterial> library = read_libraries(path, libraries, warnings);
  Scene scene;
  std::size_t vertices = 0;
  std::set<std::string> unknown;
  for (const FaceGroup& g : groups) {
    Material material;
    if (const auto it = library.find(g.material); it != library.end()) {
      material = material_from_mtl(it->second);
    } else {
      // No usemtl, or a material no library defines: the grey of docs/conventions.md.
      if (!g.material.empty() && unknown.insert(g.material).second)
        warnings.push_back(path + ": usemtl " + g.material + ": no mtllib file defines it; its faces are grey");
      material.name = g.material;
      material.base_color = {0.8, 0.8, 0.8};
      material.metallic = 0;
      material.roughness = 0.5;
    }
    ScenePrimitive prim;
    prim.material = static_cast<int>(scene.materials.size());
    scene.materials.push_back(std::move(material));
    std::unordered_map<std::uint64_t, std::uint32_t> vertex_of;
    prim.triangles.reserve(g.corners.size());
    for (const Corner& c : g.corners) {
      const std::uint64_t key = (std::uint64_t(c.position) << 32) | c.normal;
      auto [it, added] = vertex_of.try_emplace(key, static_cast<std::uint32_t>(prim.positions.size()));
      if (added) {
        if (++vertices > max_vertices)
          throw InputError(path, "the mesh has more than " + std::to_string(max_vertices) +
                                     " vertices (the limit that protects the machine; raise it with --max-vertices)");
        Vec3d n = c.normal == kNoNormal ? Vec3d{} : normals[c.normal];
        const double len = length(n);
        n = len > 0 && std::isfinite(len) ? n / len : computed_normal(c.position);
        if (bad_position[c.position] || !is_finite(n)) n = {};
        prim.positions.push_back(positions[c.position]);
        prim.normals.push_back(n);
      }
      prim.triangles.push_back(it->second);
    }
    scene.primitives.push_back(std::move(prim));
  }
  return scene;
}

}  // namespace vlit
