// A bounding volume hierarchy over the occluder triangles (our own; no Embree), and the two
// queries the shadows need:
// - segment_occluded: does any triangle cross the open segment a -> b (a shadow ray; any hit);
// - triangles_in_volume: which triangles reach into a convex volume (the volume between a vertex
//   and a light), sorted by triangle index.
// Both skip the triangles that touch a given vertex position (occluder_triangles.h, "touches").
//
// triangles_in_volume skips a node whose box lies wholly outside one of the volume's half-spaces.
// Build: binary tree, median split of the triangles' centroids along the widest axis of their
// bounds, leaves of ≤ kLeafSize triangles; O(n log n), large subtrees side by side on OpenMP
// tasks. Nodes are stored depth-first in one array, the same whatever the number of threads.
// The brute-force mode tests every triangle with the same per-triangle tests and gives identical
// results (tests/shadow/bvh_test.cpp): a node is visited whenever its box could contain a
// triangle that passes, so the BVH only skips triangles that would fail.
#pragma once

#include <cstdint>
#include <utility>
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

  // The triangles, in the tree's leaf order (not the order given to the constructor; ids says
  // where each came from).
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

  // The triangles that may carry a silhouette edge seen from p inside the volume, ascending: the
  // triangles not wholly outside one of the volume's half-spaces (a superset of those that reach
  // into it), less the subtrees that provably carry none: a subtree
  // whose triangles and their edge neighbours all face p the same way (normal cone, Sander et
  // al., "Silhouette Clipping", SIGGRAPH 2000), that lies wholly inside every half-space of
  // `inside` (no triangle is cut there), holds no open edge (occluder_edges.h) and, if its
  // triangles face away from p, belong all to one closed solid or all to none (back faces are
  // culled per solid, so they are then all culled or all kept).
  // Such a subtree adds nothing to the silhouette: each of its edges has two triangles facing p
  // the same way, whose projections' boundaries cancel.
  // p_radius > 0 asks for every point within p_radius of p at once (a cluster of vertices,
  // silhouette_cluster.h): a subtree is skipped only if it faces all of them uniformly.
  // held_inside[i] is 1 when out[i]'s leaf lies inside every half-space of `inside` with the
  // tests' margin (so the triangle does not cross their planes), 0 when that was not proven.
  void silhouette_candidates(const ConvexVolume& volume, const HalfSpace* inside, int inside_count, const Vec3d& p,
                             std::vector<std::uint32_t>& out, std::vector<std::uint8_t>& held_inside,
                             double p_radius = 0) const;

  // The same search, returning the leaves it reaches (node indices, ascending by their first
  // triangle) instead of their triangles: a cluster's search (silhouette_cluster.h). held_planes,
  // if given, receives per leaf the bits of the volume's planes proven to hold it (near_volume).
  void silhouette_leaves(const ConvexVolume& volume, const HalfSpace* inside, int inside_count, const Vec3d& p,
                         double p_radius, std::vector<std::uint32_t>& leaves,
                         std::vector<std::uint32_t>* held_planes = nullptr) const;

  // A ball that holds a box (its centre, half its diagonal), and the part of the margin of a test
  // against a plane that does not depend on the plane (ball_side()).
  struct Ball {
    Vec3d center;
    double radius = 0, margin = 0;
  };
  // The bounds of a cluster's leaves, copied where the vertices of the cluster read them in
  // order (leaves_reached), and of runs of kLeafBlock consecutive leaves, so that leaves_reached
  // decides a whole run with one test where it lies wholly outside one of the volume's planes or
  // wholly inside all of them.
  struct Bounds {
    Aabb box;
    Ball ball;
  };
  struct LeafBounds {
    std::vector<Bounds> leaf, block;  // block b holds leaves [b kLeafBlock, (b + 1) kLeafBlock)
  };
  static constexpr std::size_t kLeafBlock = 8;
  void leaf_bounds(const std::vector<std::uint32_t>& leaves, LeafBounds& out) const;

  // Of a cluster's leaves (from silhouette_leaves; their bounds from leaf_bounds), the positions i
  // of those not wholly outside one of `volume`'s planes or its box. Ascending. Unlike the
  // searches, it does not ask whether a leaf faces the vertex uniformly: a cluster lists only
  // leaves with edges of non-zero weight over the cluster, of which few pass that test from one of
  // its vertices, and reading a leaf that does costs little (its edges weigh 0 from there, and it
  // leaves no chord).
  void leaves_reached(const LeafBounds& leaves, const ConvexVolume& volume, std::vector<std::uint32_t>& out) const;

  // A triangle's plane as the shadow tests read it (is_occluder, area_visibility.h; the normal
  // cones): n = cross(c1 - c0, c2 - c0), its length, and the triangle's longest edge squared.
  // Computed once here rather than at every test of the triangle.
  struct TrianglePlane {
    Vec3d normal;
    double normal_length = 0, longest_squared = 0;
  };
  const TrianglePlane& plane(std::uint32_t triangle) const { return planes_[triangle]; }

  // The triangles of a leaf node: indices [first, second) (triangles are stored in leaf order).
  std::pair<std::uint32_t, std::uint32_t> leaf_triangles(std::uint32_t node) const {
    return {nodes_[node].first, nodes_[node].first + nodes_[node].count};
  }
  // The triangle is not wholly outside one of the volume's planes, and its box meets the volume's.
  // Bit k of `held` (k < 16) says that plane k holds the triangle's leaf (visit_volume): not tested.
  bool near_volume(std::uint32_t triangle, const ConvexVolume& volume, std::uint32_t held = 0) const;

  // The node's box lies wholly inside the half-space h, whose normal has unit length, beyond a
  // margin far above rounding; origin_margin is 2e-9 times the max-norm of h's origin.
  bool inside(std::uint32_t node, const HalfSpace& h, double origin_margin) const;
  // -1: the node's box lies wholly outside h (beyond the same margin), 1: wholly inside, 0: neither.
  int side_of(std::uint32_t node, const HalfSpace& h, double origin_margin) const;

  // Every triangle whose (padded) box the segment a -> b meets, unsorted (the caller tests them).
  void triangles_near_segment(const Vec3d& a, const Vec3d& b, std::vector<std::uint32_t>& out) const;

 private:
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  // leaf: first index into order_; inner: index of the right child
    std::uint32_t count = 0;  // leaf: number of triangles; inner: 0 (left child is the next node)
  };
  // Directions of the normals of a subtree's triangles and of their edge neighbours: within
  // `half_angle` of `axis` (half_angle >= pi: unbounded).
  struct NormalCone {
    Vec3d axis;
    double half_angle = 4;
    double cos_half_angle = 0, sin_half_angle = 1;  // set when half_angle < pi / 2
    bool open = false;   // holds a triangle with an open edge
    int solid = -1;      // the closed solid all its triangles belong to, -1 for none, -2 if mixed
  };
  static Ball ball_of(const Aabb& box);
  // -1: the ball lies wholly outside h (unit normal) beyond its margin, 1: wholly inside, 0: neither.
  static int ball_side(const Ball& ball, const HalfSpace& h, double origin_margin);
  // Appends the subtree over order_[begin, end) to `out`, depth-first; its inner nodes' indices
  // count from the start of `out`.
  void build(std::vector<Node>& out, std::uint32_t begin, std::uint32_t end, const std::vector<Vec3d>& centroids,
             int depth);
  void build_cones();
  bool faces_uniformly(std::uint32_t node, const Vec3d& p, double p_radius) const;
  // Calls leaf(node, held) for every leaf whose box meets the volume, skipping the subtrees for
  // which prune(node, held) is true. held carries the bits of the planes proven to hold the node
  // on the way down (kSlabBit in the .cpp); a plane that holds a node is not tested below it.
  template <class Prune, class Leaf>
  void visit_volume(const ConvexVolume& volume, const Prune& prune, const Leaf& leaf) const;

  OccluderTriangles triangles_;
  OccluderEdges edges_;
  Aabb bounds_;
  std::vector<Aabb> boxes_;           // per triangle
  std::vector<TrianglePlane> planes_;  // per triangle
  std::vector<std::uint32_t> order_;  // triangle indices, grouped by leaf
  std::vector<Node> nodes_;
  std::vector<NormalCone> cones_;  // per node
  std::vector<Ball> balls_;        // per node
  bool brute_force_;
};

// Segment a -> b against one triangle (Moller-Trumbore), hit parameter in (t_min, t_max).
// Barycentric bounds are inclusive with a relative slack of 1e-12, so a ray through the shared
// edge of two triangles hits at least one of them (watertight occluders do not leak).
bool segment_hits_triangle(const Vec3d& a, const Vec3d& b, const std::array<Vec3d, 3>& tri, double t_min, double t_max);

}  // namespace vlit
