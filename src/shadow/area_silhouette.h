// Which part of an area light a point P sees, from the silhouettes of what hides it (Picott 1992
// eq. 10), at a cost that follows the silhouette edges instead of the occluder triangles.
//
// Method. Project every occluder triangle (clipped to the slab between P and the light,
// area_visibility.h) from P onto the light's plane; the number of projections covering a point x
// of the light is its depth d(x), the number of occluder triangles the segment P -> x crosses,
// and x is visible exactly when d(x) = 0. Each projected triangle is a counter-clockwise (front
// face) or clockwise (back face) polygon; summed as oriented boundaries, the sides shared by two
// triangles that face P the same way cancel, and what is left is the silhouette seen from P: the
// edges between a triangle facing P and one facing away (weight +-2), boundary and non-manifold
// edges (+-1 per triangle), and the chords where a triangle leaves the slab. d(x) is the winding
// number of that weighted cycle (soft shadow volumes: Laine, Aila, Assarsson, Lehtinen and
// Akenine-Moller, "Soft Shadow Volumes for Ray Tracing", SIGGRAPH 2005, count the same depth
// from silhouette edges with one shadow ray as reference).
//  1. The silhouette segments are clipped in 3D to the slab and to the pyramid from P over a
//     rectangle R slightly larger than the horizon-clipped light L, then projected to (u, v), the
//     sweep's axes (sweep_axes.h: along an edge of the light, so R hugs a rectangular panel).
//     L's own edges join them with weight -1, so the count t(x) = d(x) + 1 - [x in L] is 0
//     exactly on the visible part of L.
//  2. A sweep in v cuts R into slabs at every endpoint and crossing; inside a slab no two
//     segments cross, so sorted by u at the slab's middle they split it into trapezoids, and t
//     changes by each segment's weight from one trapezoid to the next.
//  3. t in one trapezoid comes from one shadow ray (it counts the triangles crossed, and says
//     so when a crossing is too close to an edge to count; another point is then tried); t in
//     the leftmost trapezoid of the other slabs follows from the segments that end on R's left
//     side.
//  4. The trapezoids with t = 0 are the visible pieces; vertically adjacent ones between the
//     same two segments are merged (and, with SilhouettePieces::kChains, those whose segments
//     continue one another). The kernels run on them as on the pieces of visible_area_pieces.
// With a cluster (silhouette_cluster.h) that holds P, the silhouette comes from the cluster's
// lists instead of a search of the BVH.
// Checks: t >= 0 everywhere and t >= 1 outside L; when one fails (or no shadow ray could be
// counted) the answer is kUndecided and the caller uses visible_area_pieces, the triangle-by-
// triangle cutting, which is also the reference of the tests (tests/shadow/silhouette_test.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "shadow/area_visibility.h"
#include "shadow/silhouette_rule.h"

namespace vlit {

struct SilhouetteCluster;

// The rectangle R is the light's bounding rectangle grown by this fraction of its size (plus a
// floor), so that L's edges never lie on R's sides.
inline constexpr double kSilhouetteRectangleGrowth = 0.01171875;  // 3/256

// R for a light of the given radius whose (horizon-clipped) bounding rectangle is `tight`.
inline Rect2 silhouette_rectangle(const Rect2& tight, double light_radius) {
  const double grow = kSilhouetteRectangleGrowth * std::max({tight.x1 - tight.x0, tight.y1 - tight.y0, 1e-3 * light_radius});
  return {tight.x0 - grow, tight.x1 + grow, tight.y0 - grow, tight.y1 + grow};
}

struct SilhouetteSegment {
  double u0, v0, u1, v1;  // as oriented: from (u0, v0) to (u1, v1)
  int weight;             // t is larger by `weight` on the segment's left than on its right
};

struct AreaSilhouetteScratch {
  std::vector<std::uint32_t> candidates, ray_candidates;
  std::vector<std::uint8_t> candidate_in_slab;  // per candidate: its leaf lies inside the slab (no chords)
  std::vector<std::uint32_t> leaves;  // positions in a cluster's leaves that P reaches
  SilhouetteFacings facings;  // the triangles' facings from P and the edges already weighed
  std::vector<std::int8_t> slot_facing;   // per slot of a cluster (silhouette_cluster.h) from P, or 2: not yet
  std::vector<SilhouetteSegment> segments;
  std::vector<double> events, starts, other_events;
  std::vector<std::pair<double, int>> left_steps;
  // The segments the sweep's crossing search holds: upper v, u-range, index.
  struct ActiveSegments {
    std::vector<double> v1, u_lo, u_hi;
    std::vector<int> index;
    void clear() { v1.clear(), u_lo.clear(), u_hi.clear(), index.clear(); }
    void push(double top, double lo, double hi, int i) { v1.push_back(top), u_lo.push_back(lo), u_hi.push_back(hi), index.push_back(i); }
    void keep_open_after(double v) {  // drops the segments with v1 <= v, keeping the others' order
      std::size_t kept = 0;
      for (std::size_t j = 0; j < index.size(); ++j)
        if (v1[j] > v) v1[kept] = v1[j], u_lo[kept] = u_lo[j], u_hi[kept] = u_hi[j], index[kept++] = index[j];
      v1.resize(kept), u_lo.resize(kept), u_hi.resize(kept), index.resize(kept);
    }
  } active;
  std::vector<int> meets;  // the crossing search's list of held segments that pass its first test
  std::vector<int> order, step, prefix, by_height;
  std::vector<std::pair<double, int>> slab_segments;  // (u, segment) spanning the reference ray's slab, by u
  std::vector<std::pair<double, int>> by_start;  // (v0, segment), for the events and the crossing search
  std::vector<std::pair<double, int>> sorted;    // the reference ray's gaps; then a slab's (u, segment)
  std::vector<std::pair<double, double>> light_uv;
  // A piece still growing upward: bounded on the left by segment a and on the right by b in the
  // slab being swept, from v_start (where its lower corners a0, b0 lie) up. With chains merged,
  // the segments that bounded it lower down end where a and b start, at the vertices of its
  // left and right chains (`chain`, from the highest down; -1: none).
  struct Open {
    int a, b;
    double v_start, a0, b0;
    int left = -1, right = -1, chain_vertices = 0;
  };
  std::vector<Open> open, now;
  struct ChainVertex {
    double u, v;
    int below;  // the chain's next vertex down, or -1
  };
  std::vector<ChainVertex> chain;
  std::vector<int> open_at;     // per segment: the index in `open` of the trapezoid it bounds on the left, or -1
  std::vector<char> continued;  // per trapezoid of `open`: the slab being swept continues it
  LightPieces pieces;
  // Counters for benchmarks and tests.
  long queries = 0, undecided = 0, silhouette_segments = 0, visible_pieces = 0;
};

enum class SilhouetteVisibility {
  kUnoccluded,  // no occluder reaches between P and the light
  kPieces,      // scratch.pieces holds the visible part (possibly empty: fully hidden)
  kUndecided,   // a consistency check failed: use visible_area_pieces
};

// How the visible part is cut into pieces. kTrapezoids: convex pieces, each bounded by two
// segments (and two lines of constant v). kChains: a piece also continues upward where the
// segment bounding one of its sides ends and another starts at the same point (along a
// silhouette made of many short edges), so the pieces are far fewer, simple and monotone in v
// but not always convex, with at most kMaxChainPiece corners besides their four: for kernels
// whose result is a sum over a piece's edges (the diffuse, eq. 9), to which the cuts between
// trapezoids only add terms.
enum class SilhouettePieces { kTrapezoids, kChains };
inline constexpr int kMaxChainPiece = 32;

SilhouetteVisibility visible_area_by_silhouettes(const PreparedAreaLight<double>& light,
                                                 const AreaView<double>& view,
                                                 const ClipPolygon<double>& horizon_clipped, const Vec3d& p,
                                                 const OccluderBvh& occluders, AreaSilhouetteScratch& scratch,
                                                 const SilhouetteCluster* cluster = nullptr,
                                                 SilhouettePieces cut = SilhouettePieces::kTrapezoids);

}  // namespace vlit
