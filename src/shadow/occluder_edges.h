// The edges of the occluder triangles, shared between triangles by corner position (so split
// vertices and seams still join), with every edge's incident triangles. The silhouette search
// (area_silhouette.h) weighs an edge by the triangles on both of its sides.
//
// Build: one record per triangle side keyed by its endpoints in lexicographic order, sorted (on
// all threads: Boost.Sort's block_indirect_sort), and equal keys merged; O(n log n). Zero-length
// sides get an edge of their own (they project to a point and never bound anything).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shadow/occluder_triangles.h"

namespace vlit {

struct OccluderEdges {
  // Per triangle t and side j (corner j to corner (j + 1) % 3): the edge's index, and whether the
  // side runs from the edge's first endpoint to its second (+1) or back (-1).
  std::vector<std::array<std::uint32_t, 3>> edge_of;
  std::vector<std::array<std::int8_t, 3>> direction_of;
  // Per edge e: endpoints in lexicographic order (first < second), and its incident sides
  // incident[first_incident[e] .. first_incident[e + 1]), each coded as 3 * triangle + side.
  std::vector<std::array<Vec3d, 2>> endpoints;
  std::vector<std::uint32_t> first_incident;
  std::vector<std::uint32_t> incident;
  // Per triangle: true if one of its edges is not shared by exactly two triangles of opposite
  // directions (a boundary, a non-manifold edge or an inconsistently wound neighbour).
  std::vector<std::uint8_t> has_open_edge;
  std::size_t size() const { return endpoints.size(); }
};

OccluderEdges edges_of(const OccluderTriangles& triangles);

}  // namespace vlit
