// The crease wedges (crease_wedges.h) of points that stand exactly on a mesh vertex: a probe point
// moved onto a vertex by snap_to_vertices is shaded as that vertex is in a bake, wedges included.
//
// Several vertices can share a position (a hard edge, a seam, a wall's foot on a floor), each with
// its own fan and so its own wedges. The point takes the vertex whose normal is closest to its own
// normal (largest dot product; the first in scene order on a tie): a renderer's face-corner normal
// names the side of a hard edge it belongs to. Points on no vertex get no wedges, as before.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "scene/scene.h"
#include "shadow/crease_wedges.h"

namespace vlit {

class PointWedges {
 public:
  // positions[i], normals[i]: the points (normals need not be unit). The scene must outlive the
  // call only; the wedges are copied.
  PointWedges(const Scene& scene, std::span<const Vec3d> positions, std::span<const Vec3d> normals);
  std::span<const WedgeCone> of(std::size_t point) const;
  std::size_t on_vertex() const { return on_vertex_; }  // points standing on some vertex

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<CreaseWedges> of_primitive_;    // computed only for primitives some point stands on
  std::vector<std::uint32_t> primitive_, vertex_;  // per point, kNone when on no vertex
  std::size_t on_vertex_ = 0;
};

}  // namespace vlit
