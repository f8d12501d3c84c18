// Merging triangles into planar polygons: the emissive triangles of a primitive become as few
// area lights as possible. Edge-adjacent triangles with the same plane and facing form a region;
// a region whose boundary is one simple loop becomes one polygon (its boundary, collinear
// vertices dropped). A region with holes, a pinched boundary (two parts touching at a vertex) or
// more than `max_vertices` boundary vertices is not merged: each of its triangles becomes its
// own polygon (exact, since the area-light integrals are additive over pieces; only slower).
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace vlit {

struct PlanarMergeStats {
  std::size_t triangles = 0;       // non-degenerate input triangles
  std::size_t regions = 0;         // coplanar edge-connected regions
  std::size_t merged_regions = 0;  // regions that became a single polygon
};

// `triangles`: 3 indices per triangle into `positions`, counter-clockwise seen from the front.
// Vertices are matched by exact position (a file's vertex split does not stop a merge).
// Returns polygons counter-clockwise seen from the front, each with 3..max_vertices vertices and
// planar within 1e-7 of its size. Degenerate (zero-area) triangles are dropped.
std::vector<std::vector<Vec3d>> merge_coplanar_triangles(const std::vector<Vec3d>& positions,
                                                         const std::vector<std::uint32_t>& triangles,
                                                         std::size_t max_vertices,
                                                         PlanarMergeStats* stats = nullptr);

}  // namespace vlit
