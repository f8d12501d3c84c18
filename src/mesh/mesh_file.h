// Mesh files as a Scene (no transform): OBJ with its .mtl materials (mesh/obj_file.h, one
// primitive per material); PLY, OFF and STL read with OpenMesh's readers as one primitive with the
// grey material of docs/conventions.md. Polygons are triangulated; normals come from the file when
// it has them, otherwise they are angle-weighted (mesh/vertex_normals.h).
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
