// Which part of an area light a point P sees (Picott 1992 eq. 10: the hidden part of the light
// contributes nothing, so clip the light against the silhouettes of what hides it).
//
// Method. The light, clipped to P's horizon (area_polygon.h), is cut into convex-or-chain
// pieces that no occluder hides:
//  1. query the occluders that reach into the pyramid from P over the light's bounding
//     rectangle, between the light's plane and P (OccluderBvh::triangles_in_volume);
//  2. clip each occluder triangle to the slab strictly between the light's plane and P
//     (occluder parts beyond the light or behind P hide nothing), and skip it if P sees it
//     edge-on (it hides a set of zero area);
//  3. subtract the cone from P over the clipped occluder from every piece: the cone is convex,
//     bounded by one plane through P per occluder edge, so "piece minus cone" is the union of
//     the parts of the piece outside each plane in turn (Sutherland-Hodgman cuts only, no
//     general polygon boolean). A plane through P and an occluder edge meets the light's plane
//     in the line of that edge's central projection from P, so this is exactly "project the
//     occluder from P onto the light's plane and subtract the union of the projections".
// Watertightness: the plane of an edge shared by two occluder triangles is formed as
// ±cross(x_j - P, x_k - P) from the same corners, so both triangles use bit-identical
// (negated) planes and the cut points on the light are the same: no light leaks between
// them (tests/shadow/area_shadow_test.cpp "watertight occluder never leaks").
// Degenerate occluders (zero area, edge-on, zero-length edges, coincident with the light's
// plane) hide nothing; pieces of area below 1e-12 of the light's are dropped.
// Occluder parts within 1e-7 (h + light radius) of the light's plane are ignored: a fixture
// mesh lying on the light must not hide it (docs/shadows.md).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "area_polygon.h"
#include "shadow/occluder_bvh.h"

namespace vlit {

// Pieces of a light, relative to the light's centre c, each a closed polygon or chain.
// Each piece carries its bounding rectangle in the light's in-plane frame (u, v), so a piece
// and an occluder whose projections' rectangles are disjoint are skipped without clipping.
struct Rect2 {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  void grow(double x, double y) { x0 = std::min(x0, x); x1 = std::max(x1, x); y0 = std::min(y0, y); y1 = std::max(y1, y); }
  bool overlaps(const Rect2& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

struct LightPieces {
  std::vector<Vec3d> points;
  std::vector<int> start;  // piece i is points[start[i] .. start[i+1]); start has size() + 1 entries
  std::vector<Rect2> rect;  // per piece, in (u, v) relative to the light's centre
  std::size_t size() const { return start.empty() ? 0 : start.size() - 1; }
  void clear() { points.clear(); start.assign(1, 0); rect.clear(); }
  void add(const Vec3d* p, int n, const Vec3d& u, const Vec3d& v) {
    Rect2 r;
    for (int i = 0; i < n; ++i) r.grow(dot(u, p[i]), dot(v, p[i]));
    add(p, n, r);
  }
  void add(const Vec3d* p, int n, const Rect2& r) {
    points.insert(points.end(), p, p + n);
    start.push_back(static_cast<int>(points.size()));
    rect.push_back(r);
  }
};

// The cone from P over one occluder (clipped to the slab): inside is dot(normal[j], x - P) >= 0
// for every j < planes; `shadow` bounds its projection on the light's plane.
struct OccluderCone {
  std::array<Vec3d, 16> normal;
  int planes = 0;
  Rect2 shadow;
  bool front = false;  // the occluder faces P
  double size = 0;     // area of `shadow`
  std::uint32_t index = 0;
};

struct AreaShadowScratch {
  std::vector<std::uint32_t> candidates;
  std::vector<OccluderCone> cones;
  LightPieces pieces, next;
};

enum class AreaVisibility {
  kUnoccluded,  // no occluder reaches between P and the light: use the light as is
  kPieces,      // scratch.pieces holds the visible part (possibly empty: fully hidden)
};

// horizon_clipped: the light clipped to P's horizon (count >= 3). P is the ShadingPoint's p.
AreaVisibility visible_area_pieces(const PreparedAreaLight<double>& light, const AreaView<double>& view,
                                   const ClipPolygon<double>& horizon_clipped, const Vec3d& p,
                                   const OccluderBvh& occluders, AreaShadowScratch& scratch);

// Replaces `pieces` minus the cone from P whose inside is dot(cone_normal[j], x - P) >= 0 for
// j < planes (planes through P) into `next` (cleared first); `shadow` bounds the cone's trace on
// the light's plane in the view's (u, v) (an unbounded Rect2 when unknown). Parts of area below
// area_floor (twice the area) are dropped. True if some piece was cut; otherwise `next` holds
// the same pieces.
bool subtract_cone(const LightPieces& pieces, const Vec3d* cone_normal, int planes, const Rect2& shadow,
                   const AreaView<double>& view, double area_floor, LightPieces& next);

// Twice the area below which a visible piece of the light is dropped.
inline double piece_area_floor(const PreparedAreaLight<double>& light) { return 1e-12 * 2 * light.area; }

// The volume that the BVH is asked about (exposed for tests and the plan): the pyramid from P
// over the rectangle `rect` (in the view's (u, v) relative to the light's centre; the bounding
// rectangle of the horizon-clipped light in the second form), cut to the slab.
ConvexVolume area_shadow_volume(const PreparedAreaLight<double>& light, const AreaView<double>& view,
                                const ClipPolygon<double>& horizon_clipped, const Vec3d& p);
ConvexVolume area_shadow_volume(const PreparedAreaLight<double>& light, const AreaView<double>& view,
                                const Rect2& rect, const Vec3d& p);

// The slab strictly between the light's plane and P in which occluders count: parts within
// kLightPlaneMargin (h + light radius) of the light's plane (a fixture lying on the light) and
// within kApexMargin h of P's level are left out.
inline constexpr double kLightPlaneMargin = 1e-7;
inline constexpr double kApexMargin = 1e-9;
struct AreaSlab {
  HalfSpace beyond_light;  // height above the light's plane >= margin
  HalfSpace before_p;      // height <= h (1 - apex margin)
};
AreaSlab area_slab(const PreparedAreaLight<double>& light, const AreaView<double>& view, const Vec3d& p);

// The bounding rectangle of the horizon-clipped light in the view's (u, v).
Rect2 light_rectangle(const AreaView<double>& view, const ClipPolygon<double>& horizon_clipped);

// Whether a triangle hides anything from P (not a culled back face of a closed surface, not seen
// edge-on, not of zero area; triangles touching P are left out by the BVH queries already), and
// if so whether it faces P (then its central projection onto the light is counter-clockwise in
// the view's (u, v), whose normal points toward P).
// A triangle whose area is below kSliver times its longest edge squared (a needle, e.g. two
// corners 1e-18 apart) is no occluder either: it hides a set of negligible area, and its plane,
// hence any crossing with it, is rounding noise.
inline constexpr double kEdgeOn = 1e-12;
inline constexpr double kSliver = 1e-10;
bool is_occluder(const OccluderBvh& occluders, std::uint32_t index, const Vec3d& p, bool* front);

// is_occluder's test of the plane alone, for a triangle that is not a needle and not culled from
// P: n = cross(c1 - c0, c2 - c0), n_length = length(n). +1: it faces P, -1: it faces away, 0: P
// sees it edge-on.
inline int facing_from_plane(const Vec3d& n, double n_length, const Vec3d& c0, const Vec3d& p) {
  const double side = dot(n, c0 - p);
  if (!(std::abs(side) > kEdgeOn * n_length * length(c0 - p))) return 0;
  return side < 0 ? 1 : -1;
}

}  // namespace vlit
