// The in-plane axes in which the silhouette visibility (area_silhouette.h) sweeps an area light,
// and in which a cluster (silhouette_cluster.h) bounds it.
//
// The sweep orders the silhouette segments inside the rectangle R around the light, axis-aligned
// in these axes; every segment inside R is sorted and walked, whether or not it reaches the light.
// The light's own frame (PreparedAreaLight::u, toward its farthest vertex) runs along a diagonal
// of a square panel, where R holds twice the light's area (docs/shadows.md, "The sweep's axes",
// has the times). Here u runs along the light's edge whose direction gives the light the
// smallest bounding rectangle (for a convex polygon the smallest of all bounding rectangles has a
// side on an edge: Freeman and Shapira, "Determining the minimum-area encasing rectangle for an
// arbitrary closed curve", CACM 1975), and v = normal x u, so u x v = normal as in the light's
// own frame. Where that rectangle is not at least kSweepAxesMinGain smaller than the light's own
// frame's, the own frame is kept: a regular 64-gon (a disk's, disk_pieces.h) would gain 0.1 %, and
// the sweep along its edge ran 2–4 % slower on the demo's disks (docs/shadows.md, "The sweep's
// axes").
#pragma once

#include "shadow/area_visibility.h"

namespace vlit {

inline constexpr double kSweepAxesMinGain = 0.05;

struct SweepAxes {
  Vec3d u, v;
};

// Pure function of the light; the last light's answer is kept per thread (a light's queries come
// in runs), so a call costs a comparison of the polygon after the first.
SweepAxes sweep_axes(const PreparedAreaLight<double>& light);

// The view with its frame turned to the axes (v follows the view's orientation: for the back of a
// two-sided light v is -axes.v, as the view's own frame flips the light's v).
inline AreaView<double> in_sweep_axes(const AreaView<double>& view, const SweepAxes& axes) {
  AreaView<double> turned = view;
  turned.u = axes.u;
  turned.v = view.orient > 0 ? axes.v : -axes.v;
  return turned;
}

}  // namespace vlit
