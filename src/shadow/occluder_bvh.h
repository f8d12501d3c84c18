// A bounding volume hierarchy over the occluder triangles (our own; no Embree), and the two
// queries the shadows need:
// - segment_occluded: does any triangle cross the open segment a -> b (a shadow ray; any hit);
// - triangles_in_volume: which triangles reach into a convex volume (the volume between a vertex
//   and a light), sorted by triangle index.
// Both skip the triangles that touch a given vertex position (occluder_triangles.h, "touches").
//
// triangles_in_volume skips a node whose box lies wholly outside one of the volume's half-spaces.
// Build: binary tree, median split of the triangles' centroids along the widest axis of their
// bounds, leaves of ≤ kLeafSize triangles; O(n log n). Nodes are stored depth-first in one array.
// The brute-force mode tests every triangle with the same per-triangle tests and gives identical
// results (tests/shadow/bvh_test.cpp): a node is visited whenever its box could contain a
// triangle that passes, so the BVH only skips triangles that would fail.
#pragma once

#include <cstdint>
#include <vector>

#include "shadow/convex_volume.h"
#include "shadow/occluder_edges.h"
#include "shadow/occluder_triangles.h"

namespace vlit {

class OccluderBvh {
 public:
  static constexpr int kLeafSize = 4;

  // brute_force: no tree, every query tests every triangle (the reference for the tests).
  explicit OccluderBvh(OccluderTriangles triangles, bool brute_force = false);

  const OccluderTriangles& triangles() const { return triangles_; }
  const OccluderEdges& edges() const { return edges_; }  // shared edges and their triangles
  bool brute_force() const { return brute_force_; }
  std::size_t node_count() const { return nodes_.size(); }
  const Aabb& bounds() const { return bounds_; }  // of every triangle

  // True if a triangle not touching `skip` crosses the segment a + t (b - a), t in (t_min, t_max).
  bool segment_occluded(const Vec3d& a, const Vec3d& b, const Vec3d& skip, double t_min = 1e-9,
                        double t_max = 1.0 - 1e-9) const;

  // Indices (into triangles()) of the triangles not touching `skip` that reach into the volume,
  // ascending. `out` is cleared first.
  void triangles_in_volume(const ConvexVolume& volume, const Vec3d& skip, std::vector<std::uint32_t>& out) const;

 private:
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  // leaf: first index into order_; inner: index of the right child
    std::uint32_t count = 0;  // leaf: number of triangles; inner: 0 (left child is the next node)
  };
  std::uint32_t build(std::uint32_t begin, std::uint32_t end, std::vector<Vec3d>& centroids, int depth);

  OccluderTriangles triangles_;
  OccluderEdges edges_;
  Aabb bounds_;
  std::vector<Aabb> boxes_;           // per triangle
  std::vector<std::uint32_t> order_;  // triangle indices, grouped by leaf
  std::vector<Node> nodes_;
  bool brute_force_;
};

// Segment a -> b against one triangle (Moller-Trumbore), hit parameter in (t_min, t_max).
// Barycentric bounds are inclusive with a relative slack of 1e-12, so a ray through the shared
// edge of two triangles hits at least one of them (watertight occluders do not leak).
bool segment_hits_triangle(const Vec3d& a, const Vec3d& b, const std::array<Vec3d, 3>& tri, double t_min, double t_max);

}  // namespace vlit
