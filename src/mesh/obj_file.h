// Wavefront OBJ with its materials (docs/mesh-files.md): one scene primitive per material used
// by `usemtl`, in the order of first use, materials from the `mtllib` files (mesh/mtl_file.h).
//
// Read: `v x y z` (a fourth number or a vertex colour is ignored), `vn`, `f` with corners
// `v`, `v/vt`, `v//vn`, `v/vt/vn` (negative indices count back from the last vertex), `mtllib`
// (one or more file names, relative to the OBJ's folder), `usemtl`. Everything else (vt, o, g, s,
// l, p, curves) is ignored. Polygons are split into a fan of triangles from their first corner.
//
// Vertices are the distinct (position, normal) pairs each primitive uses, so a hard edge written
// with two normals stays hard. A corner without a normal gets the angle-weighted normal of its
// position over all faces of the file (mesh/vertex_normals.h), so a smooth surface stays smooth
// across a change of material.
//
// Why not OpenMesh's OBJ reader (used for PLY, OFF and STL): it tells a face's material only
// through a face colour taken from Kd, so the faces of an emitter (Ke) cannot be found, and it
// keeps one normal per position.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace vlit {

// Throws InputError naming the file and line for a malformed statement or an index out of range,
// naming the .mtl file and line for a malformed material library, and when the file has no faces
// or more than max_vertices vertices. A missing .mtl or an unknown material is a warning (the
// faces get the grey material of docs/conventions.md).
Scene load_obj_file(const std::string& path, std::vector<std::string>& warnings, std::size_t max_vertices);

}  // namespace vlit
