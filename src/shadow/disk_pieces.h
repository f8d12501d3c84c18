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

namespace vlit {

// The diffuse (unit intensity, kd = 1) of piece ∩ disk. `view` is the disk's view from P (the
// frame of disk.inscribed and disk.circumscribed), `piece` a convex polygon relative to the
// disk's centre in the disk's plane, above P's horizon.
// `frame` is disk_frame(view, radius, n), the same for every piece seen from P.
double disk_piece_diffuse(const AreaView<double>& view, const DiskFrame<double>& frame, const Vec3d& n,
                          const ClipPolygon<double>& piece);

// The exact specular (unit intensity, ks = 1) of piece ∩ disk, same arguments as
// disk_piece_diffuse, the disk's radius and P's normal n, mirror direction rv and shininess m: the
// lobe's contour integral (disk_specular_exact.h) over the boundary's rim arcs and straight
// edges, clipped to the lobe's half-space, to the relative `tolerance`. A piece inside the disk
// takes the polygon kernels (area_specular_exact_dispatch).
double disk_piece_specular_exact(const AreaView<double>& view, double radius, const Vec3d& n, const Vec3d& rv,
                                 double m, double tolerance, const ClipPolygon<double>& piece);

// piece ∩ polygon (both convex, relative to the light's centre, in its plane), in `out`.
void clip_piece_to_polygon(const ClipPolygon<double>& piece, const PreparedAreaLight<double>& polygon,
                           const AreaView<double>& view, ClipPolygon<double>& out);

}  // namespace vlit
