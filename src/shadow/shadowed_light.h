// One light at one point with its shadows: the existing kernels (shaders_cpu/) evaluated on the
// part of the light the point sees (Picott 1992 eq. 10). Unit intensity, kd = ks = 1, without
// the glTF range window (as shade_kernel in src/shading/prepared_light.h).
//
// Per model:
// - point, spot: one shadow ray from P to the light's position;
// - directional: one shadow ray from P against the light, past every occluder;
// - linear: the visible sub-segments [t_a, t_b], from the silhouette edges crossing the plane of
//   P and the segment (linear_silhouette.h; ShadeOptions::linear_shadows) or, where its checks
//   fail or when asked, from every occluder's hidden interval (linear_visibility.h). Intensity
//   is per unit of t (docs/lights-json.md), so a sub-segment shaded as a light of its own is
//   scaled by (t_b - t_a) to keep the same emission density: diffuse and exact specular sum over the
//   pieces with that weight; the peak specular is the largest peak over the pieces (a maximum,
//   not an integral); the neighbourhood specular keeps the whole light's K samples and counts
//   only the visible ones (so it never exceeds the unshadowed value);
// - area: the visible pieces of the light, from the occluders' silhouette edges
//   (area_silhouette.h; ShadeOptions::area_shadows) or, where that method's checks fail or when
//   asked, by cutting the light with every occluder (area_visibility.h); diffuse and exact specular are
//   sums over the pieces (both are integrals over the light: contour sums are additive over a
//   partition), the peak is the largest peak over the pieces, the neighbourhood keeps the whole
//   light's peak direction and ring and counts only the directions that reach a visible piece;
// - disk: the visible pieces of its circumscribed regular 64-gon, each intersected with the disk
//   for the diffuse (straight edges and rim arcs, disk_pieces.h: exact, continuous with the
//   unshadowed disk kernel), and with its equal-area 64-gon for the specular methods; unshadowed
//   points use the disk kernel unchanged.
// When no occluder reaches between P and the light the unshadowed kernel is called, so a light
// nothing hides gives bit-identical results with shadows on or off.
#pragma once

#include <span>

#include "shading/prepared_light.h"
#include "shadow/area_silhouette.h"
#include "shadow/area_visibility.h"
#include "shadow/crease_wedges.h"
#include "shadow/occluder_bvh.h"

namespace vlit {

struct SilhouetteCluster;

// What an area or disk light's polygon (shadowed_polygon) shows above one horizon from one
// position, found once for the vertices there whose horizon clips the polygon alike: a mesh
// splits a vertex wherever its normals or texture coordinates are discontinuous (a seam, a hard
// edge), and copies whose horizons leave the polygon whole, or that have the same normal, ask
// the same question. Their answers are the same bits as their own searches'.
struct SharedVisibility {
  enum class State {
    kUnlit,       // the position is behind the light (or in its plane), or the light below the horizon
    kUnoccluded,  // nothing reaches between the position and the light
    kPieces,      // `pieces` is the visible part (possibly empty)
    kUndecided,   // the silhouette method's checks failed: each vertex finds its own part
  };
  State state = State::kUnlit;
  LightPieces pieces;
};

// How the silhouette method cuts the visible part for these options (area_silhouette.h): into
// chains where only the diffuse reads the pieces, else into trapezoids: with specular, for a disk
// (disk_pieces.h intersects convex pieces with the circle) and where crease wedges are cut from
// the pieces (subtract_cone clips each piece by the wedge's planes into a fixed-size polygon,
// which a long non-convex piece could outgrow).
SilhouettePieces silhouette_pieces_for(const ShadeOptions& options, bool disk, bool wedged);

// Fills `out` for sp (its position and horizon) by silhouettes (area_silhouette.h), with the
// cluster's lists when the cluster holds sp (as shade_kernel_shadowed), cut as `cut` says.
void see_light_above_horizon(const PreparedAreaLight<double>& polygon, const ShadingPoint<double>& sp,
                             const OccluderBvh& occluders, const SilhouetteCluster* cluster, SilhouettePieces cut,
                             SharedVisibility& out);

// cluster: for area and disk lights by silhouettes, a cluster holding sp (silhouette_cluster.h,
// prepared for shadowed_polygon(kernel)) whose lists replace the per-vertex search; ignored
// otherwise.
// wedges: the cones that triangles across a crease hide from sp when it is a mesh vertex
// (crease_wedges.h); empty for other points.
// seen: for area and disk lights by silhouettes, see_light_above_horizon's answer for a point at
// sp.p whose horizon clips the polygon as sp's does (then no search is made unless it is
// undecided); ignored otherwise.
template <class K>
Response<double> shade_kernel_shadowed(const K& kernel, const ShadingPoint<double>& sp, const ShadeOptions& options,
                                       const OccluderBvh& occluders, const SilhouetteCluster* cluster = nullptr,
                                       std::span<const WedgeCone> wedges = {},
                                       const SharedVisibility* seen = nullptr);

// The polygon whose visible part is computed: the light itself, or the regular 64-gon
// circumscribed about a disk (its visible pieces are then intersected with the disk:
// disk_pieces.h).
inline const PreparedAreaLight<double>& shadowed_polygon(const PreparedAreaLight<double>& area) { return area; }
inline const PreparedAreaLight<double>& shadowed_polygon(const PreparedDiskLight<double>& disk) { return disk.circumscribed; }


// Dispatching form, range window included (as shade() in prepared_light.h); wedges as above.
Response<double> shade_shadowed(const PreparedLight<double>& light, const ShadingPoint<double>& sp,
                                const ShadeOptions& options, const OccluderBvh& occluders,
                                std::span<const WedgeCone> wedges = {});

}  // namespace vlit
