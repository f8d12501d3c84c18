// What a triangle that has a corner at a vertex's position, but is not one of the vertex's own
// triangles, hides from that vertex: the wedge it subtends across a crease or a seam.
//
// A vertex is shaded as the limit of the points of its own fan (the triangles of its primitive
// that use it) as they approach it. Seen from such a point P' = P + e d (e -> 0, d the direction
// into the fan), a triangle T with a corner at P, whose two sides leave P along the unit
// directions e1 and e2, hides exactly the directions toward the points of T near P:
// a e1 + b e2 - e d with a, b >= 0, that is the convex cone spanned by e1, e2 and -d. From P
// itself T lies in a plane through P and hides nothing, which is why the occluder searches leave
// out every triangle touching P (occluder_triangles.h, "touches"); the wedge puts back what T
// hides from the fan's side:
// - across a concave crease (a floor vertex at the foot of a wall modelled as another primitive,
//   or split normals at a hard edge) the wall's wedge covers the directions behind the wall's
//   plane: the light behind the wall is hidden, as it is for every point of the floor near P;
// - the wedge is cut to the front side of the plane of the fan's face that d runs along (of the
//   fan's faces, the one whose plane is nearest to d; the vertex normal's plane where d is the
//   normal): a part behind that plane is reached from the fan's points only through the fan,
//   which hides nothing from its own vertex. So across a convex edge, or past a seam of a convex
//   surface (split normals or texture coordinates), where the rest of the surface bends away
//   behind the fan, there is no wedge, and a smooth surface split at a seam is shaded as if it
//   were not; a sheet that crosses the surface at the vertex does hide what rises above it;
// - across a flat seam (the same plane continued by another vertex or primitive) e1, e2 and -d
//   are coplanar and the wedge has no volume: it is dropped.
// d is the sum of the unit bisectors of the fan's corners at P, normalized: the limit is taken
// along the fan's own surface (not along the vertex normal's tangent plane, which leaves the
// surface: under it where the fan is tilted against the normal, and other faces then hide what
// the fan's points see); where the fan is closed around P (each of its sides from P shared by two of its
// triangles: a vertex inside its surface that another object touches) or empty, d is the vertex
// normal (the limit from just above the surface). A position shared by more than 64 vertices gets no
// wedges (the work grows with the square of their number). Tests:
// tests/shadow/crease_wedges_test.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "scene/scene.h"

namespace vlit {

// A convex cone with its apex at the vertex: the directions w with dot(inward[j], w) >= 0 for
// every j (three sides and the fan's plane).
struct WedgeCone {
  std::array<Vec3d, 4> inward;
  bool contains(const Vec3d& w) const {
    for (const Vec3d& k : inward)
      if (dot(k, w) < 0) return false;
    return true;
  }
};

// The wedges of every vertex of one primitive (empty for most vertices).
struct CreaseWedges {
  std::vector<std::uint32_t> first;  // vertex v's wedges are cones[first[v] .. first[v + 1])
  std::vector<WedgeCone> cones;
  std::span<const WedgeCone> of(std::size_t v) const {
    if (first.empty()) return {};
    return {cones.data() + first[v], cones.data() + first[v + 1]};
  }
};

// The vertices of the scene that share their position with another vertex (of any primitive),
// built once per scene.
class SharedPositions {
 public:
  explicit SharedPositions(const Scene& scene);
  // The wedges of the vertices of scene.primitives[primitive].
  CreaseWedges wedges_of(std::size_t primitive) const;

 private:
  struct VertexId {
    std::uint32_t primitive, vertex;
  };
  const Scene& scene_;
  std::vector<std::vector<std::uint32_t>> member_of_vertex_;  // per primitive and vertex: index into members_
  std::vector<VertexId> members_;             // the vertices that share a position, grouped by it
  std::vector<std::uint32_t> group_of_member_;
  std::vector<std::uint32_t> group_first_;    // group g is members_[group_first_[g] .. group_first_[g + 1])
  std::vector<std::uint32_t> fan_first_;      // member m's triangles are fans_[fan_first_[m] .. fan_first_[m + 1])
  std::vector<std::uint32_t> fans_;           // triangle indices within the member's primitive
};

}  // namespace vlit
