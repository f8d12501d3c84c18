// The visible part of a disk light, exactly: the visible pieces that the silhouettes (or the
// triangle cuts) find on the disk's circumscribed polygon, each intersected with the disk itself,
// their diffuse from Lambert's contour integral over straight edges and rim arcs (Picott 1992
// eq. 9 with the disk's arc term of disk_diffuse_contour.h). So a shadowed disk is the disk, not a
// polygon standing for it: where an occluder begins to reach, the value is continuous with the
// unshadowed disk kernel's.
//
// Method. A piece is convex (a trapezoid, or a trapezoid cut by wedge cones): the disk is clipped
// by each of its edges' half-planes in turn, the region kept as a counter-clockwise boundary of
// rim arcs (explicit angle intervals [a0, a1], a1 > a0, so no arc is ever mistaken for its
// complement) and straight segments; where a clip removes part of the boundary, the cut is closed
// along the clipping line. A piece whose corners all lie inside the disk is the piece itself.
// The exact specular integrates disk_specular_exact.h's contour integrand over the same boundary
// after clipping it to the lobe's half-space; peak and neighbourhood specular stay on the disk's
// equal-area polygon (shadowed_light.cpp).
// Tests: tests/shadow/disk_shadow_test.cpp.
#pragma once

#include "area_polygon.h"
#include "disk_diffuse_contour.h"
#include "disk_light.h"
#include "disk_specular_exact.h"

namespace vlit {

// The exact specular's constants for one point P, the same for every piece: the unit mirror
// direction, the lobe's half-space as a line in the disk's plane, the choice of the contour form
// (tail when Rv is far from the whole disk, as disk_specular_exact.h decides) and the rim's cuts.
struct DiskPieceLobe {
  Vec3d rv;
  double m = 0, tolerance = 0, lobe_width = 1;
  bool misses = false;  // Rv along the disk's normal, pointing away from it: the lobe misses the plane
  bool clips = false;   // the lobe's line nx x + ny y >= c (unit n) cuts the plane
  double nx = 0, ny = 0, c = 0;
  bool tail = false;
  disk_exact_detail::RimCuts<double> cuts;
};

// `n` is P's normal, rv its mirror direction, m the shininess, `tolerance` the relative tolerance
// of the quadrature.
DiskPieceLobe disk_piece_lobe(const AreaView<double>& view, double radius, const Vec3d& n, const Vec3d& rv, double m,
                              double tolerance);

// Unit intensity, kd = ks = 1.
struct DiskPieceLight {
  double diffuse = 0;
  double specular = 0;  // the exact specular; 0 without a lobe
};

// The diffuse and (with `lobe`) the exact specular of piece ∩ disk, from one boundary of rim arcs
// and straight edges. `view` is the disk's view from P (the frame of disk.inscribed and
// disk.circumscribed), `piece` a convex polygon relative to the disk's centre in the disk's plane,
// above P's horizon; `frame` is disk_frame(view, radius, n) and `lobe` disk_piece_lobe(...), the
// same for every piece seen from P. The specular is the lobe's contour integral
// (disk_specular_exact.h) over the boundary clipped to the lobe's half-space; a piece inside the
// disk takes the polygon kernels (area_specular_exact_dispatch).
DiskPieceLight disk_piece_light(const AreaView<double>& view, const DiskFrame<double>& frame, const Vec3d& n,
                                const DiskPieceLobe* lobe, const ClipPolygon<double>& piece);

// piece ∩ polygon (both convex, relative to the light's centre, in its plane), in `out`.
void clip_piece_to_polygon(const ClipPolygon<double>& piece, const PreparedAreaLight<double>& polygon,
                           const AreaView<double>& view, ClipPolygon<double>& out);

}  // namespace vlit
