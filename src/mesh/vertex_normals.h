// Vertex normals for meshes that have none: each vertex gets the angle-weighted sum of the
// normals of the triangles that use it (Thürmer & Wüthrich 1998), so the result does not depend
// on how a face is triangulated. Vertices are never welded: a vertex split in the file (a hard
// edge) stays split, and each copy gets the normal of its own triangles only.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace vlit {

// Unit normals, one per position. A vertex used by no non-degenerate triangle gets (0, 0, 0),
// which every kernel treats as "receives no light" (no NaN).
std::vector<Vec3d> angle_weighted_normals(const std::vector<Vec3d>& positions,
                                          const std::vector<std::uint32_t>& triangles);

}  // namespace vlit
