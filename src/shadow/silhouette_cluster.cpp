#include "shadow/silhouette_cluster.h"

#include <algorithm>
#include <cmath>

#include "shadow/area_silhouette.h"
#include "shadow/sweep_axes.h"

namespace vlit {
namespace {

constexpr std::int8_t kVariableFacing = SilhouetteCluster::kVariable;
// Relative margin of the classification over B: far above the rounding of the per-vertex
// facing test (is_occluder's kEdgeOn is 1e-12), so a constant class never disagrees with it.
constexpr double kClassMargin = 1e-9;
// The widest cluster, relative to the light's diameter (2 x its radius, which does not depend on
// the axes of R): the diagonal of the square around the light's circumscribed circle.
constexpr double kWidestCluster = 1.4142135623730951;
// too_wide(): a cluster whose search reaches more than kProbedClusterLeaves leaves per vertex has
// one vertex's search run to compare with, and is not prepared when it reached more than
// kWideClusterLeaves times that search's leaves per vertex. Chosen on shadow_bench part 3 (the
// refined sphere), the bowling lane, DamagedHelmet and MetalRoughSpheres (docs/shadows.md).
constexpr double kProbedClusterLeaves = 64;
constexpr double kWideClusterLeaves = 0.5;

std::array<Vec3d, 8> corners_of(const Aabb& b) {
  std::array<Vec3d, 8> c;
  for (int i = 0; i < 8; ++i) c[i] = {i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z};
  return c;
}

bool contains(const Aabb& outer, const Aabb& inner) {
  return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z && inner.hi.x <= outer.hi.x &&
         inner.hi.y <= outer.hi.y && inner.hi.z <= outer.hi.z;
}

// The facing of triangle t (SilhouetteFacings::facing_of in silhouette_rule.h: +1 faces P, -1
// faces away, 0 hides nothing) if it is the same for every P of the box b, else kVariableFacing.
std::int8_t facing_over_box(const OccluderBvh& occluders, std::uint32_t t, const Aabb& b) {
  const OccluderTriangles& triangles = occluders.triangles();
  const auto& c = triangles.corners[t];
  const OccluderBvh::TrianglePlane& plane = occluders.plane(t);
  const Vec3d& n = plane.normal;
  if (!(plane.normal_length > kSliver * plane.longest_squared)) return 0;  // a needle hides nothing from anywhere
  // The triangle and B in one plane of constant x, y or z (a flat floor around a cluster of its
  // own vertices): n is exactly along that axis and n.(c0 - P) is exactly 0 for every P of B, so
  // is_occluder sees it edge-on from all of them.
  for (int a = 0; a < 3; ++a)
    if (b.lo[a] == b.hi[a] && c[0][a] == b.lo[a] && c[1][a] == b.lo[a] && c[2][a] == b.lo[a]) return 0;
  for (const Vec3d& x : c)
    if (b.contains(x)) return kVariableFacing;  // it may touch a vertex of the cluster
  // side(P) = n.(c0 - P) is linear in P: over the box it spans side(centre) -+ sum |n_i| h_i
  // (h the box's half extent). reach bounds |c0 - P| over the box.
  const Vec3d middle = b.center(), half = (b.hi - b.lo) * 0.5;
  const double at_middle = dot(n, c[0] - middle);
  const double spread = std::abs(n.x) * half.x + std::abs(n.y) * half.y + std::abs(n.z) * half.z;
  const double lo = at_middle - spread, hi = at_middle + spread;
  const double reach = length(c[0] - middle) + length(half);
  const double margin = kClassMargin * plane.normal_length * reach;
  if (hi < -margin) return 1;  // faces every P of the box
  // Seen edge-on from every P of the box (its plane holds the box, e.g. a floor around a cluster of
  // its own vertices): |side| stays below half of is_occluder's kEdgeOn bound at P's distance.
  const Vec3d gap = max(b.lo - c[0], max(Vec3d{}, c[0] - b.hi));
  if (std::max(std::abs(lo), std::abs(hi)) < 0.5 * kEdgeOn * plane.normal_length * length(gap)) return 0;
  if (!(lo > margin)) return kVariableFacing;
  // Faces away from every P: hidden unless it is a back face of a closed surface culled from P
  // (culled_back_face: P outside the surface's box).
  if (triangles.solid.empty() || triangles.solid[t] < 0) return -1;
  const Aabb& solid = triangles.solid_bounds[triangles.solid[t]];
  if (contains(solid, b)) return -1;  // never culled
  if (!solid.overlaps(b)) return 0;   // always culled
  return kVariableFacing;
}

// Whether the cluster is too wide to pay: its search reached more than kWideClusterLeaves times
// the leaves its vertices' own searches would reach together. Preparing it (classifying every
// triangle of those leaves over B) would then cost more than the searches it saves, and its
// vertices search alone. This happens where B is wide against the curvature of a finely
// tessellated surface between it and the light: the band of triangles whose facing varies over B
// grows with B and with the number of triangles, while each vertex's silhouette grows only with
// its square root. The search of the lit vertex nearest B's centre, over the whole light's
// rectangle r (its view's frame is the cluster's), stands for each vertex's; it is run only when
// the cluster reached more than kProbedClusterLeaves leaves per vertex (below that, preparing
// costs little).
bool too_wide(const PreparedAreaLight<double>& light, const ShadingPoint<double>* points, const Vec3d& center,
              const Rect2& r, const OccluderBvh& occluders, SilhouetteCluster& cluster) {
  const double vertices = static_cast<double>(cluster.lit.size());
  const double reached = static_cast<double>(cluster.leaves.size());
  if (reached <= kProbedClusterLeaves * vertices) return false;
  std::uint32_t nearest = cluster.lit[0];
  double nearest_distance = length_squared(points[nearest].p - center);
  for (std::uint32_t v : cluster.lit) {
    const double d = length_squared(points[v].p - center);
    if (d < nearest_distance) nearest = v, nearest_distance = d;
  }
  const Vec3d& p = points[nearest].p;
  const AreaView<double> view = in_sweep_axes(make_area_view(light, p), sweep_axes(light));
  const AreaSlab slab = area_slab(light, view, p);
  const HalfSpace planes[2] = {slab.beyond_light, slab.before_p};
  occluders.silhouette_leaves(area_shadow_volume(light, view, r, p), planes, 2, p, 0, cluster.probe);
  return reached > kWideClusterLeaves * vertices * static_cast<double>(cluster.probe.size());
}

}  // namespace

void prepare_silhouette_cluster(const PreparedAreaLight<double>& light, const ShadingPoint<double>* points,
                                const std::uint32_t* index, int count, const OccluderBvh& occluders,
                                SilhouetteCluster& cluster) {
  using State = SilhouetteCluster::State;
  cluster.state = State::kPerVertex;
  cluster.box = Aabb{};
  if (occluders.brute_force()) return;
  // B: the vertices the light reaches, all on one side of it.
  Aabb box;
  cluster.lit.clear();
  int side = 0;
  double h_min = 1e300, h_max = 0;
  for (int i = 0; i < count; ++i) {
    const ShadingPoint<double>& sp = points[index[i]];
    const AreaView<double> view = make_area_view(light, sp.p);
    if (!view.lit) continue;
    bool above_horizon = false;  // some corner of the light above P's tangent plane
    for (int k = 0; k < light.count && !above_horizon; ++k) above_horizon = dot(sp.n, light.d[k] + view.D) > 0;
    if (!above_horizon) continue;
    const int s = view.orient > 0 ? 1 : -1;
    if (side != 0 && s != side) return;  // both sides of a two-sided light
    side = s;
    box.grow(sp.p);
    cluster.lit.push_back(index[i]);
    h_min = std::min(h_min, view.height);
    h_max = std::max(h_max, view.height);
  }
  if (side == 0) return;  // no vertex is lit: nothing to search
  const Vec3d normal = side > 0 ? light.normal : -light.normal;
  const SweepAxes axes = sweep_axes(light);  // R in the sweep's axes, as area_silhouette's
  const Vec3d u = axes.u, v = side > 0 ? axes.v : -axes.v;
  const std::array<Vec3d, 8> corner = corners_of(box);
  for (const Vec3d& q : corner)
    if (!(dot(normal, q - light.center) > 0)) return;  // B reaches the light's plane

  // R: the whole light's rectangle, grown as area_silhouette grows a view's (a view's clipped
  // rectangle is inside the whole one, and its growth is not larger).
  Rect2 tight;
  for (int k = 0; k < light.count; ++k) tight.grow(dot(u, light.d[k]), dot(v, light.d[k]));
  const Rect2 r = silhouette_rectangle(tight, light.radius);
  // A cluster wider than the light sweeps a hull much larger than any of its vertices' pyramids:
  // its lists would hold far more than each vertex needs. Its vertices search alone.
  if (length(box.hi - box.lo) > kWidestCluster * 2 * light.radius) return;
  const Vec3d rect[4] = {light.center + u * r.x0 + v * r.y0, light.center + u * r.x1 + v * r.y0,
                         light.center + u * r.x1 + v * r.y1, light.center + u * r.x0 + v * r.y1};
  const Vec3d middle = light.center + u * (0.5 * (r.x0 + r.x1)) + v * (0.5 * (r.y0 + r.y1));

  // The hull of B and R: its box, one plane through each side of R leaning out to hold all of B
  // (the supporting plane through that side and one corner of B), and the slab planes of the
  // lowest and highest vertex.
  ConvexVolume volume;
  volume.box = box;
  for (const Vec3d& x : rect) volume.box.grow(x);
  const double scale = length(volume.box.hi - volume.box.lo);
  for (int k = 0; k < 4; ++k) {
    const Vec3d& a = rect[k];
    const Vec3d& b = rect[(k + 1) % 4];
    for (const Vec3d& q : corner) {
      Vec3d n = cross(b - a, q - a);
      const double len = length(n);
      if (!(len > 0)) continue;
      n = n / len;
      if (dot(n, middle - a) < 0) n = -n;
      bool holds = true;
      for (const Vec3d& other : corner) holds = holds && dot(n, other - a) >= -1e-9 * scale;
      if (!holds) continue;
      volume.planes.push_back({n, a - n * (2e-9 * scale)});  // moved out past the tolerance
      break;
    }
  }
  const double margin_lo = kLightPlaneMargin * (h_min + light.radius), margin_hi = kLightPlaneMargin * (h_max + light.radius);
  volume.planes.push_back({normal, light.center + normal * margin_lo});
  volume.planes.push_back({-normal, light.center + normal * (h_max * (1 - kApexMargin))});
  // A subtree must lie inside the slab of every vertex to be skipped as uniform.
  const HalfSpace inside[2] = {{normal, light.center + normal * margin_hi},
                               {-normal, light.center + normal * (h_min * (1 - kApexMargin))}};
  const Vec3d center = box.center();
  const double radius = 0.5 * length(box.hi - box.lo);
  occluders.silhouette_leaves(volume, inside, 2, center, radius, cluster.leaves, &cluster.held_planes);
  if (too_wide(light, points, center, r, occluders, cluster)) return;  // its vertices search alone
  cluster.candidates.clear();
  std::vector<std::uint32_t>& candidates_begin = cluster.candidates_begin;
  candidates_begin.clear();
  for (std::size_t i = 0; i < cluster.leaves.size(); ++i) {
    candidates_begin.push_back(static_cast<std::uint32_t>(cluster.candidates.size()));
    const auto [first, end] = occluders.leaf_triangles(cluster.leaves[i]);
    for (std::uint32_t t = first; t < end; ++t)
      if (occluders.near_volume(t, volume, cluster.held_planes[i])) cluster.candidates.push_back(t);
  }
  candidates_begin.push_back(static_cast<std::uint32_t>(cluster.candidates.size()));
  cluster.box = box;
  // No candidate is not "nothing hides the light": a closed surface wider than the light's
  // pyramids has no silhouette in them. The vertex's shadow ray decides, as after its own search.
  cluster.state = State::kLists;

  const OccluderTriangles& triangles = occluders.triangles();
  const OccluderEdges& edges = occluders.edges();
  if (cluster.facing.size() != triangles.size() || cluster.edge_stamp.size() != edges.size() ||
      cluster.node_stamp.size() != occluders.node_count()) {
    cluster.facing.assign(triangles.size(), 0);
    cluster.facing_stamp.assign(triangles.size(), 0);
    cluster.slot_of.assign(triangles.size(), 0);
    cluster.slot_stamp.assign(triangles.size(), 0);
    cluster.edge_stamp.assign(edges.size(), 0);
    cluster.leaf_position.assign(occluders.node_count(), 0);
    cluster.node_stamp.assign(occluders.node_count(), 0);
    cluster.stamp = 0;
  }
  if (++cluster.stamp == 0) {
    for (auto* stamps : {&cluster.facing_stamp, &cluster.slot_stamp, &cluster.edge_stamp, &cluster.node_stamp})
      std::fill(stamps->begin(), stamps->end(), 0);
    cluster.stamp = 1;
  }
  auto facing = [&](std::uint32_t t) {
    if (cluster.facing_stamp[t] != cluster.stamp) {
      cluster.facing_stamp[t] = cluster.stamp;
      cluster.facing[t] = facing_over_box(occluders, t, box);
    }
    return cluster.facing[t];
  };
  // Wholly inside every vertex's slab, with a margin above the rounding of the per-vertex planes.
  const double slab_margin = 1e-9 * (h_max + light.radius);
  auto inside_every_slab = [&](std::uint32_t t) {
    for (const HalfSpace& h : inside)
      for (const Vec3d& x : triangles.corners[t])
        if (!(h.signed_distance(x) > slab_margin * length(h.normal))) return false;
    return true;
  };
  // The weight over B of edge e, or kVariable.
  auto weight_over_box = [&](std::uint32_t e) {
    int weight = 0;
    for (std::uint32_t k = edges.first_incident[e]; k < edges.first_incident[e + 1]; ++k) {
      const std::uint32_t code = edges.incident[k];
      const std::int8_t f = facing(code / 3);
      if (f == kVariableFacing) return SilhouetteCluster::kVariable;
      weight += f * edges.direction_of[code / 3][code % 3];
    }
    return std::abs(weight) >= SilhouetteCluster::kVariable ? SilhouetteCluster::kVariable : weight;
  };
  // The slot of triangle t, made on first use.
  cluster.slots.clear();
  auto slot = [&](std::uint32_t t) {
    if (cluster.slot_stamp[t] != cluster.stamp) {
      cluster.slot_stamp[t] = cluster.stamp;
      cluster.slot_of[t] = static_cast<std::uint32_t>(cluster.slots.size());
      const auto& c = triangles.corners[t];
      SilhouetteCluster::Slot s;
      s.normal = occluders.plane(t).normal;
      s.corner = c[0];
      s.normal_length = occluders.plane(t).normal_length;
      s.triangle = t;
      s.facing = facing(t);
      s.may_touch = box.contains(c[0]) || box.contains(c[1]) || box.contains(c[2]);
      s.in_solid = !triangles.solid.empty() && triangles.solid[t] >= 0;
      cluster.slots.push_back(s);
    }
    return cluster.slot_of[t];
  };
  cluster.weighed_edges.clear();
  cluster.listed_weight.clear();
  cluster.incidence_begin.assign(1, 0);
  cluster.incident_slot.clear();
  cluster.incident_direction.clear();
  cluster.chord_slots.clear();
  cluster.edges_begin.clear();
  cluster.chords_begin.clear();
  // A leaf with neither kind of item adds nothing for any vertex of B: it is dropped, so the
  // vertices do not test it.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < cluster.leaves.size(); ++i) {
    const std::uint32_t edges_before = static_cast<std::uint32_t>(cluster.weighed_edges.size());
    const std::uint32_t chords_before = static_cast<std::uint32_t>(cluster.chord_slots.size());
    for (std::uint32_t c = candidates_begin[i]; c < candidates_begin[i + 1]; ++c) {
      const std::uint32_t t = cluster.candidates[c];
      if (facing(t) != 0 && !inside_every_slab(t)) cluster.chord_slots.push_back(slot(t));
      for (int j = 0; j < 3; ++j) {
        const std::uint32_t e = edges.edge_of[t][j];
        if (cluster.edge_stamp[e] == cluster.stamp) continue;  // weighed in this or an earlier leaf
        cluster.edge_stamp[e] = cluster.stamp;
        const int weight = weight_over_box(e);
        if (weight == 0) continue;
        cluster.weighed_edges.push_back(e);
        cluster.listed_weight.push_back(static_cast<std::int8_t>(weight));
        if (weight == SilhouetteCluster::kVariable)
          for (std::uint32_t k = edges.first_incident[e]; k < edges.first_incident[e + 1]; ++k) {
            const std::uint32_t code = edges.incident[k];
            cluster.incident_slot.push_back(slot(code / 3));
            cluster.incident_direction.push_back(static_cast<std::int8_t>(edges.direction_of[code / 3][code % 3]));
          }
        cluster.incidence_begin.push_back(static_cast<std::uint32_t>(cluster.incident_slot.size()));
      }
    }
    if (cluster.weighed_edges.size() == edges_before && cluster.chord_slots.size() == chords_before) continue;
    cluster.edges_begin.push_back(edges_before);
    cluster.chords_begin.push_back(chords_before);
    cluster.leaf_position[cluster.leaves[i]] = static_cast<std::uint32_t>(kept);
    cluster.node_stamp[cluster.leaves[i]] = cluster.stamp;
    cluster.leaves[kept++] = cluster.leaves[i];
  }
  cluster.leaves.resize(kept);
  // The vertices read the leaves' bounds only when they do not search the tree themselves.
  if (cluster.leaves.size() <= SilhouetteCluster::kFlatLeaves) {
    occluders.leaf_bounds(cluster.leaves, cluster.leaf_bounds);
  } else {
    cluster.leaf_bounds.leaf.clear();
    cluster.leaf_bounds.block.clear();
  }
  cluster.edges_begin.push_back(static_cast<std::uint32_t>(cluster.weighed_edges.size()));
  cluster.chords_begin.push_back(static_cast<std::uint32_t>(cluster.chord_slots.size()));
}

}  // namespace vlit
