// Points given in single precision moved onto the occluders' vertices they stand for.
//
// A vertex of a transformed asset has a world position in double (node transforms are applied in
// double). A point written by another program in single precision (a renderer's bake, a CSV
// exported from a float buffer, transformed in float) misses it by a few rounding errors. Such a
// point is not the vertex: the vertex's own triangles no longer contain it, and one of them can
// hide the light from it (docs/shadows.md, "Self-shadowing"). snap_to_vertices moves each point
// that lies within kSnapTolerance of the occluders' size of exactly one distinct occluder corner
// onto that corner; a point near several distinct corners is left alone.
#pragma once

#include <cstddef>
#include <vector>

#include "core/vec3.h"
#include "shadow/occluder_triangles.h"

namespace vlit {

// Relative to the diagonal of the occluders' bounding box: far above single-precision rounding
// (6e-8 of a coordinate), far below the spacing of the vertices of any mesh one would light.
inline constexpr double kSnapTolerance = 1e-6;

struct SnapCount {
  std::size_t snapped = 0;    // moved onto a corner (or already on it)
  std::size_t ambiguous = 0;  // left alone: several distinct corners within the tolerance
};

SnapCount snap_to_vertices(const OccluderTriangles& triangles, std::vector<Vec3d>& points);

}  // namespace vlit
