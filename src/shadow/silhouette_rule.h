// The one rule that decides which occluder triangles count from a point P, shared by everything
// that counts depth from silhouettes (area_silhouette.h, linear_silhouette.h): a triangle's
// facing from P, an edge's weight, and the shadow ray that fixes the depth at one point of the
// light. The silhouette's winding number equals the number of triangles a ray from P crosses only
// when the edges and the ray read the same facings: a triangle that touches P, is a culled back
// face, a needle or seen edge-on hides nothing for both.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "shadow/area_visibility.h"
#include "shadow/occluder_bvh.h"

namespace vlit {

// A shadow ray whose crossing lies within this fraction of a triangle's edge (in barycentric
// terms) or of the slab's planes is not counted: another point is tried.
inline constexpr double kRayAmbiguity = 1e-9;
// The most points a query tries before it gives up on its shadow rays (kUndecided).
inline constexpr int kMaxReferenceRays = 8;

// Per occluder triangle its facing from P, and per edge whether this query weighed it already;
// both valid for the query whose stamp they carry, so a query clears nothing.
struct SilhouetteFacings {
  struct Facing {
    std::uint32_t stamp;
    std::int8_t facing;
  };
  std::vector<Facing> facing;
  std::vector<std::uint32_t> edge_stamp;
  std::uint32_t stamp = 0;

  // Starts a query (sizes the tables for these occluders the first time).
  void begin(const OccluderBvh& occluders) {
    const std::size_t triangle_count = occluders.triangles().size();
    if (facing.size() != triangle_count || edge_stamp.size() != occluders.edges().size()) {
      facing.assign(triangle_count, {0, 0});
      edge_stamp.assign(occluders.edges().size(), 0);
      stamp = 0;
    }
    if (++stamp == 0) {  // wrapped: forget every stamp
      std::fill(facing.begin(), facing.end(), Facing{0, 0});
      std::fill(edge_stamp.begin(), edge_stamp.end(), 0);
      stamp = 1;
    }
  }

  // +1: triangle t faces P (its projection from P is counter-clockwise), -1: it faces away, 0: it
  // hides nothing (is_occluder, or it touches P).
  int facing_of(const OccluderBvh& occluders, std::uint32_t t, const Vec3d& p) {
    Facing& cached = facing[t];
    if (cached.stamp == stamp) return cached.facing;
    bool front = false;
    int f = 0;
    if (!touches(occluders.triangles().corners[t], p) && is_occluder(occluders, t, p, &front)) f = front ? 1 : -1;
    cached = {stamp, static_cast<std::int8_t>(f)};
    return f;
  }

  // True the first time this query asks about edge e.
  bool first_visit(std::uint32_t e) {
    if (edge_stamp[e] == stamp) return false;
    edge_stamp[e] = stamp;
    return true;
  }

  // The weight of edge e seen from P: the facings of its triangles, each signed by its direction
  // (+1 where the triangle runs from the edge's first endpoint to its second).
  int edge_weight(const OccluderBvh& occluders, std::uint32_t e, const Vec3d& p) {
    const OccluderEdges& edges = occluders.edges();
    int weight = 0;
    for (std::uint32_t k = edges.first_incident[e]; k < edges.first_incident[e + 1]; ++k) {
      const std::uint32_t code = edges.incident[k];
      weight += facing_of(occluders, code / 3, p) * edges.direction_of[code / 3][code % 3];
    }
    return weight;
  }
};

// The point where the side x -> y of a triangle crosses the plane h, computed from the side's
// endpoints in lexicographic order so that every triangle (and edge) sharing the side gets the
// same bits.
inline Vec3d slab_crossing(const Vec3d& x, const Vec3d& y, const HalfSpace& h) {
  const bool x_first = lexicographic_less(x, y);
  const Vec3d& a = x_first ? x : y;
  const Vec3d& b = x_first ? y : x;
  const double sa = h.signed_distance(a), sb = h.signed_distance(b);
  return a + (b - a) * (sa / (sa - sb));
}

// The part [ca, cb] of the edge a -> b (its endpoints in lexicographic order, as OccluderEdges
// stores them) inside both planes; false if nothing is left. The cut points have the bits of
// slab_crossing, so they are the corners of the triangles' chords.
inline bool clip_edge_to_slab(const Vec3d& a, const Vec3d& b, const HalfSpace (&slab)[2], Vec3d& ca, Vec3d& cb) {
  ca = a, cb = b;
  for (const HalfSpace& h : slab) {
    const double sa = h.signed_distance(a), sb = h.signed_distance(b);
    if (sa < 0 && sb < 0) return false;
    if (sa < 0) ca = a + (b - a) * (sa / (sa - sb));
    if (sb < 0) cb = a + (b - a) * (sa / (sa - sb));
  }
  return true;
}

// Chords: where triangle c leaves the slab through one of its planes, the part kept is closed
// along that plane from the exit point to the entry point: chord(exit, entry) for each.
template <class Chord>
void for_each_slab_chord(const std::array<Vec3d, 3>& c, const HalfSpace (&slab)[2], const Chord& chord) {
  for (const HalfSpace& h : slab) {
    const double d[3] = {h.signed_distance(c[0]), h.signed_distance(c[1]), h.signed_distance(c[2])};
    const bool in[3] = {d[0] >= 0, d[1] >= 0, d[2] >= 0};
    if (in[0] == in[1] && in[1] == in[2]) continue;
    Vec3d exit, entry;
    for (int j = 0; j < 3; ++j) {
      const int k = (j + 1) % 3;
      if (in[j] && !in[k]) exit = slab_crossing(c[j], c[k], h);
      if (!in[j] && in[k]) entry = slab_crossing(c[j], c[k], h);
    }
    chord(exit, entry);
  }
}

// The slab in which occluders count: inside both half-spaces (unit normals), the one next to the
// light and the one next to P. A ray's crossing within plane_tol of the first or apex_tol of the
// second is too close to count.
struct CountingSlab {
  HalfSpace beyond_light, before_p;
  double plane_tol = 0, apex_tol = 0;
};

// The number of occluder triangles (those facing_of counts, inside the slab) that the segment
// P -> x crosses, or -1 if a crossing is too close to an edge of a triangle or to a plane of the
// slab to be counted. ray_candidates is the BVH query's scratch.
int shadow_ray_depth(const OccluderBvh& occluders, const Vec3d& p, const Vec3d& x, const CountingSlab& slab,
                     SilhouetteFacings& facings, std::vector<std::uint32_t>& ray_candidates);

}  // namespace vlit
