// OBJ, PLY, OFF and STL meshes, read with OpenMesh's readers, as a one-primitive Scene (no
// transform, default material). Polygons are triangulated by OpenMesh; normals come from the file
// when it has them, otherwise from OpenMesh's vertex normals.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace vlit {

// True for .obj, .ply, .off, .stl (case-insensitive).
bool is_mesh_path(const std::string& path);

// Throws InputError(path, ...) when the file cannot be read or has no triangles.
Scene load_mesh_file(const std::string& path, std::vector<std::string>& warnings);
// Same with an explicit vertex limit instead of default_scene_limits().max_vertices.
Scene load_mesh_file(const std::string& path, std::vector<std::string>& warnings, std::size_t max_vertices);

}  // namespace vlit
