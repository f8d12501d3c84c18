// Coherence across vertices for the silhouette visibility of area lights (area_silhouette.h):
// neighbouring vertices of a mesh see nearly the same occluders, so the BVH is searched once for
// a cluster of vertices instead of once per vertex.
//
// For a cluster B (the box of its vertices) and a light L, every segment from a vertex of B to
// L lies in the convex hull of B and L's rectangle R (the rectangle of the whole light, which
// holds the rectangle of every horizon-clipped view of it), between the light's plane and the
// highest level of B. One search of that volume returns the triangles that can carry a
// silhouette edge seen from any point of B: the BVH skips a subtree only if it faces every point
// of B the same way (the normal cone test of OccluderBvh::silhouette_candidates, widened by B's
// radius) and no slab plane of any vertex cuts it. Then each triangle is classified over B:
// - facing every point of B (+1), or facing away from all (-1), or hiding nothing from any (0:
//   a needle, or a back face of a closed surface whose box B lies wholly outside of);
// - variable otherwise (its plane meets B, it has a corner in B, or B straddles its solid's box).
// An edge whose incident triangles are all constant has the same weight from every point of B:
// its weight is not computed again per vertex; an edge with a variable triangle is weighed per
// vertex, from the planes of its triangles stored with the cluster (the lists a vertex reads are
// the cluster's own arrays, in the order it reads them, not lookups into the scene's tables).
// A vertex of B keeps only the cluster's leaves that reach its own volume (OccluderBvh::
// leaves_reached, which reads the leaves' bounds from the cluster and decides runs of 8 leaves
// at once where it can; its own search, which also skips leaves facing it uniformly, when the
// cluster has many leaves) and in each of them reads only the edges whose weight over B is not 0
// and the triangles that may leave its slab; the rest of the leaf adds nothing to its silhouette
// (an edge between two triangles that face B the same way weighs 0 from every point of B).
//
// The candidates hold every triangle the per-vertex search could return for any vertex of B (a
// superset, whose extra edges and chords clip to nothing in the vertex's pyramid or weigh 0;
// every edge is weighed by all of its triangles, not only the candidates), so the visible pieces
// are the same: tests/shadow/silhouette_test.cpp compares clustered, per-vertex and triangle-cut answers.
// A cluster whose box reaches the light's plane (or both sides of a two-sided light), or whose
// search reaches far more leaves than its vertices' own searches would (too_wide in the .cpp),
// is not clustered: its vertices search alone.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "shading/prepared_light.h"
#include "shadow/occluder_bvh.h"

namespace vlit {

struct SilhouetteCluster {
  enum class State {
    kPerVertex,  // each vertex searches the BVH alone
    kLists,      // leaves and candidates hold every triangle a vertex of the cluster needs
  };
  State state = State::kPerVertex;
  Aabb box;  // B; a vertex outside it (the light barely above its horizon) searches alone
  // A facing or an edge weight that is not the same from every point of B.
  static constexpr int kVariable = 100;
  std::vector<std::uint32_t> leaves;  // the BVH leaves the cluster's search reached that hold an item (below)
  OccluderBvh::LeafBounds leaf_bounds;  // of `leaves` (OccluderBvh::leaf_bounds), up to kFlatLeaves leaves
  // Scratch of prepare_silhouette_cluster: the triangles that may carry a silhouette edge or a
  // chord seen from some point of B, per leaf its search reached (before the leaves without items
  // are dropped from `leaves`): the i-th leaf's are [candidates_begin[i], candidates_begin[i + 1]).
  std::vector<std::uint32_t> candidates, candidates_begin;
  std::vector<std::uint32_t> lit, probe;  // scratch: the vertices in B; one vertex's leaves (too_wide)
  std::vector<std::uint32_t> held_planes;  // scratch: per leaf of the search, the hull's planes that hold it
  // A triangle a vertex of B reads: its facing over B, and for kVariable what the vertex needs to
  // find its own (facing_from_plane): its plane, and whether it may touch the vertex or be a
  // culled back face of a closed surface.
  struct Slot {
    Vec3d normal, corner;  // cross(c1 - c0, c2 - c0) and c0
    double normal_length;
    std::uint32_t triangle;
    std::int8_t facing;  // over B: +1, -1, 0 or kVariable
    bool may_touch, in_solid;
  };
  std::vector<Slot> slots;
  // What a vertex of B reads instead of its candidates, per leaf (leaves[i]'s items are
  // [edges_begin[i], edges_begin[i + 1]) and the same for chords):
  // - the edges of the leaf's candidates whose weight over B is not 0, each listed once, in the
  //   first leaf that holds one of its triangles: from a vertex whose search does not reach that
  //   leaf the edge adds nothing (it lies outside the vertex's volume, or its triangles face the
  //   vertex the same way); with its weight over B (listed_weight), and for kVariable the slots
  //   and directions of its triangles ([incidence_begin[k], incidence_begin[k + 1]));
  // - the slots of the candidates that may leave some vertex's slab (facing not 0 and not wholly
  //   inside the slab of every vertex): their chords.
  std::vector<std::uint32_t> weighed_edges, chord_slots;
  std::vector<std::int8_t> listed_weight;
  std::vector<std::uint32_t> incidence_begin, incident_slot;
  std::vector<std::int8_t> incident_direction;
  std::vector<std::uint32_t> edges_begin, chords_begin;
  // Per BVH node, its position in `leaves` where node_stamp is the cluster's stamp: a vertex of a
  // cluster with more than kFlatLeaves leaves finds the ones it reaches by its own search, which
  // prunes whole subtrees, instead of testing every leaf of the cluster.
  static constexpr std::size_t kFlatLeaves = 4096;
  std::vector<std::uint32_t> leaf_position, node_stamp;
  // Per triangle: its facing over B and its slot; per edge: weighed for this cluster (valid where
  // the stamp is the cluster's).
  std::vector<std::int8_t> facing;
  std::vector<std::uint32_t> facing_stamp, slot_of, slot_stamp, edge_stamp;
  std::uint32_t stamp = 0;
};

// Prepares `cluster` for the vertices points[index[0 .. count)] and one area light. Vertices the
// light cannot reach (behind a one-sided light, light below their horizon) are left out of B.
void prepare_silhouette_cluster(const PreparedAreaLight<double>& light, const ShadingPoint<double>* points,
                                const std::uint32_t* index, int count, const OccluderBvh& occluders,
                                SilhouetteCluster& cluster);

}  // namespace vlit
