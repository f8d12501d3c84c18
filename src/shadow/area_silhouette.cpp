#include "shadow/area_silhouette.h"

#include <algorithm>
#include <cmath>

#include <boost/sort/pdqsort/pdqsort.hpp>

#include "core/robust_math.h"
#include "shadow/silhouette_cluster.h"
#include "shadow/silhouette_rule.h"
#include "shadow/sweep_axes.h"

namespace vlit {
namespace {

constexpr double kThinSlab = 1e-12;

struct Frame {
  Vec3d p, center, u, v, normal;
  double height = 0, foot_u = 0, foot_v = 0;
  Rect2 rect;
  HalfSpace side[4];  // pyramid from P over R: bottom (v = y0), right (u = x1), top (v = y1), left (u = x0)
  AreaSlab slab;
};

struct ClippedPoint {
  Vec3d x;
  int side = -1;  // the pyramid side that produced it, or -1
};

// Clips the 3D segment a -> b to the pyramid's four sides; false if nothing is left.
bool clip_to_pyramid(const Frame& f, ClippedPoint& a, ClippedPoint& b) {
  for (int k = 0; k < 4; ++k) {
    const double sa = f.side[k].signed_distance(a.x), sb = f.side[k].signed_distance(b.x);
    if (sa < 0 && sb < 0) return false;
    if (sa >= 0 && sb >= 0) continue;
    const Vec3d cut = a.x + (b.x - a.x) * (sa / (sa - sb));
    if (sa < 0) a = {cut, k};
    else b = {cut, k};
  }
  return true;
}

// Central projection from P onto the light's plane, in (u, v) relative to the light's centre; a
// point made by a pyramid side is put exactly on R's side.
void project(const Frame& f, const ClippedPoint& c, double& pu, double& pv) {
  const Vec3d w = c.x - f.p;
  const double scale = f.height / -dot(f.normal, w);
  pu = f.foot_u + dot(f.u, w) * scale;
  pv = f.foot_v + dot(f.v, w) * scale;
  switch (c.side) {
    case 0: pv = f.rect.y0; break;
    case 1: pu = f.rect.x1; break;
    case 2: pv = f.rect.y1; break;
    case 3: pu = f.rect.x0; break;
    default: break;
  }
}

void add_segment(const Frame& f, ClippedPoint a, ClippedPoint b, int weight, std::vector<SilhouetteSegment>& out) {
  if (!clip_to_pyramid(f, a, b)) return;
  SilhouetteSegment s;
  project(f, a, s.u0, s.v0);
  project(f, b, s.u1, s.v1);
  s.weight = weight;
  if (s.u0 == s.u1 && s.v0 == s.v1) return;
  if (!std::isfinite(s.u0) || !std::isfinite(s.v0) || !std::isfinite(s.u1) || !std::isfinite(s.v1)) return;
  out.push_back(s);
}

// Edge e of the occluders, clipped to the slab, as a silhouette segment of the given weight.
void add_edge(const Frame& f, const OccluderEdges& edges, std::uint32_t e, int weight, AreaSilhouetteScratch& s) {
  const HalfSpace slab[2] = {f.slab.beyond_light, f.slab.before_p};
  ClippedPoint ca, cb;
  if (!clip_edge_to_slab(edges.endpoints[e][0], edges.endpoints[e][1], slab, ca.x, cb.x)) return;
  add_segment(f, ca, cb, weight, s.segments);
}

// Chords where triangle c (facing ft, not 0) leaves the slab, as silhouette segments of weight ft.
void add_chords(const Frame& f, const std::array<Vec3d, 3>& c, int ft, AreaSilhouetteScratch& s) {
  const HalfSpace slab[2] = {f.slab.beyond_light, f.slab.before_p};
  for_each_slab_chord(c, slab, [&](const Vec3d& exit, const Vec3d& entry) {
    add_segment(f, ClippedPoint{exit}, ClippedPoint{entry}, ft, s.segments);
  });
}

// The silhouette segments: weighted edges, and chords where a triangle leaves the slab; of the
// candidates of P's own search, or of a cluster's lists (silhouette_cluster.h), whose facings and
// edge weights that are the same from all of its points are read, not recomputed.
void collect_silhouette(const Frame& f, const OccluderBvh& occluders, const SilhouetteCluster* cluster,
                        AreaSilhouetteScratch& s) {
  const OccluderTriangles& triangles = occluders.triangles();
  const OccluderEdges& edges = occluders.edges();
  constexpr int kVariable = SilhouetteCluster::kVariable;
  if (cluster) {
    // In the cluster's leaves that P reaches (s.leaves), the edges whose weight over the cluster
    // is not 0 and the triangles that may leave P's slab (silhouette_cluster.h); a triangle whose
    // facing varies over the cluster is faced from P once, from its slot's plane.
    constexpr std::int8_t kUnknown = 2;
    s.slot_facing.assign(cluster->slots.size(), kUnknown);
    auto facing = [&](std::uint32_t k) {
      const SilhouetteCluster::Slot& slot = cluster->slots[k];
      if (slot.facing != kVariable) return static_cast<int>(slot.facing);
      if (s.slot_facing[k] == kUnknown) {
        int ft = 0;
        if (!(slot.may_touch && touches(triangles.corners[slot.triangle], f.p)) &&
            !(slot.in_solid && culled_back_face(triangles, slot.triangle, f.p, slot.normal)))
          ft = facing_from_plane(slot.normal, slot.normal_length, slot.corner, f.p);
        s.slot_facing[k] = static_cast<std::int8_t>(ft);
      }
      return static_cast<int>(s.slot_facing[k]);
    };
    for (std::uint32_t i : s.leaves) {
      for (std::uint32_t k = cluster->edges_begin[i]; k < cluster->edges_begin[i + 1]; ++k) {
        int weight = cluster->listed_weight[k];
        if (weight == kVariable) {
          weight = 0;
          for (std::uint32_t j = cluster->incidence_begin[k]; j < cluster->incidence_begin[k + 1]; ++j)
            weight += facing(cluster->incident_slot[j]) * cluster->incident_direction[j];
        }
        if (weight != 0) add_edge(f, edges, cluster->weighed_edges[k], weight, s);
      }
      for (std::uint32_t k = cluster->chords_begin[i]; k < cluster->chords_begin[i + 1]; ++k) {
        const int ft = facing(cluster->chord_slots[k]);
        if (ft != 0) add_chords(f, triangles.corners[cluster->slots[cluster->chord_slots[k]].triangle], ft, s);
      }
    }
    return;
  }
  for (std::size_t i = 0; i < s.candidates.size(); ++i) {
    // A candidate that hides nothing itself (it touches P, is a culled back face, a needle) still
    // weighs its edges: its neighbours may lie in subtrees the search skipped.
    const std::uint32_t t = s.candidates[i];
    const int ft = s.facings.facing_of(occluders, t, f.p);
    for (int j = 0; j < 3; ++j) {
      const std::uint32_t e = edges.edge_of[t][j];
      if (!s.facings.first_visit(e)) continue;
      const int weight = s.facings.edge_weight(occluders, e, f.p);
      if (weight != 0) add_edge(f, edges, e, weight, s);
    }
    // A candidate whose leaf the search found inside both planes of the slab has no chord.
    if (ft != 0 && !s.candidate_in_slab[i]) add_chords(f, triangles.corners[t], ft, s);
  }
}

// Number of occluder triangles (clipped to the slab) that the segment P -> x crosses, or -1 if a
// crossing is too close to an edge of a triangle or to a plane of the slab to be counted.
int depth_at(const Frame& f, const Vec3d& x, const OccluderBvh& occluders, AreaSilhouetteScratch& s) {
  CountingSlab slab{f.slab.beyond_light, f.slab.before_p};
  slab.plane_tol = kRayAmbiguity * (f.height + (f.rect.x1 - f.rect.x0) + (f.rect.y1 - f.rect.y0));
  // The slab's plane before P lies kApexMargin h from P, less than plane_tol: with plane_tol there,
  // a triangle through P (a corner of another mesh a rounding error off P, which `touches` does
  // not see) was ambiguous for every ray, and the light went to the triangle cuts. Half the apex
  // margin keeps a hit at P itself clearly outside the slab, and is still far above the rounding
  // of d1.
  slab.apex_tol = std::min(slab.plane_tol, 0.5 * kApexMargin * f.height);
  return shadow_ray_depth(occluders, f.p, x, slab, s.facings, s.ray_candidates);
}

// The segment has a part strictly inside the convex polygon `uv` (turning `turn`), deeper than
// `tolerance` from every edge (Cyrus-Beck clipping against the edges' half-planes).
bool enters_convex(const SilhouetteSegment& g, const std::vector<std::pair<double, double>>& uv, int turn,
                   double tolerance) {
  double t0 = 0, t1 = 1;
  const int n = static_cast<int>(uv.size());
  for (int i = 0; i < n; ++i) {
    const auto& [ax, ay] = uv[i];
    const auto& [bx, by] = uv[(i + 1) % n];
    const double ex = bx - ax, ey = by - ay;
    const double margin = tolerance * std::sqrt(ex * ex + ey * ey);
    const double f0 = turn * orient2(ax, ay, bx, by, g.u0, g.v0) - margin;
    const double f1 = turn * orient2(ax, ay, bx, by, g.u1, g.v1) - margin;
    if (f0 <= 0 && f1 <= 0) return false;
    if (f0 < 0) t0 = std::max(t0, f0 / (f0 - f1));
    if (f1 < 0) t1 = std::min(t1, f0 / (f0 - f1));
    if (!(t1 > t0)) return false;
  }
  return true;
}

double u_at(const SilhouetteSegment& s, double v) {  // s stored with v0 <= v1
  if (v <= s.v0) return s.u0;
  if (v >= s.v1) return s.u1;
  return s.u0 + (s.u1 - s.u0) * ((v - s.v0) / (s.v1 - s.v0));
}

}  // namespace

SilhouetteVisibility visible_area_by_silhouettes(const PreparedAreaLight<double>& light,
                                                 const AreaView<double>& light_view,
                                                 const ClipPolygon<double>& horizon_clipped, const Vec3d& p,
                                                 const OccluderBvh& occluders, AreaSilhouetteScratch& s,
                                                 const SilhouetteCluster* cluster, SilhouettePieces cut) {
  ++s.queries;
  // The sweep works in its own axes (sweep_axes.h); the pieces' rectangles are in the light's.
  const AreaView<double> view = in_sweep_axes(light_view, sweep_axes(light));
  Frame f;
  f.p = p;
  f.center = light.center;
  f.u = view.u;
  f.v = view.v;
  f.normal = view.normal;
  f.height = view.height;
  f.foot_u = dot(view.u, -view.D);
  f.foot_v = dot(view.v, -view.D);
  const Rect2 tight = light_rectangle(view, horizon_clipped);
  f.rect = silhouette_rectangle(tight, light.radius);
  f.slab = area_slab(light, view, p);

  const bool clustered = cluster && cluster->state != SilhouetteCluster::State::kPerVertex && cluster->box.contains(p);
  const ConvexVolume volume = area_shadow_volume(light, view, f.rect, p);
  const HalfSpace slab[2] = {f.slab.beyond_light, f.slab.before_p};
  if (clustered && cluster->leaves.size() <= SilhouetteCluster::kFlatLeaves) {
    occluders.leaves_reached(cluster->leaf_bounds, volume, s.leaves);
  } else if (clustered) {
    // P's own search, kept to the cluster's leaves: a leaf the cluster's search did not reach lies
    // outside the cluster's hull (so outside P's volume) or faces P uniformly.
    occluders.silhouette_leaves(volume, slab, 2, p, 0, s.candidates);
    s.leaves.clear();
    for (std::uint32_t node : s.candidates)
      if (cluster->node_stamp[node] == cluster->stamp) s.leaves.push_back(cluster->leaf_position[node]);
  } else {
    occluders.silhouette_candidates(volume, slab, 2, p, s.candidates, s.candidate_in_slab);
  }
  // The pyramid's sides, inward, in the order bottom, right, top, left (project() relies on it).
  const Vec3d corner[4] = {f.center + f.u * f.rect.x0 + f.v * f.rect.y0, f.center + f.u * f.rect.x1 + f.v * f.rect.y0,
                           f.center + f.u * f.rect.x1 + f.v * f.rect.y1, f.center + f.u * f.rect.x0 + f.v * f.rect.y1};
  const Vec3d middle = f.center + f.u * (0.5 * (f.rect.x0 + f.rect.x1)) + f.v * (0.5 * (f.rect.y0 + f.rect.y1));
  for (int k = 0; k < 4; ++k) {
    Vec3d normal = cross(corner[k] - p, corner[(k + 1) % 4] - p);
    if (dot(normal, middle - p) < 0) normal = -normal;
    f.side[k] = {normal, p};
  }

  s.facings.begin(occluders);
  s.segments.clear();
  collect_silhouette(f, occluders, clustered ? cluster : nullptr, s);
  s.silhouette_segments += static_cast<long>(s.segments.size());
  LightPieces& pieces = s.pieces;
  pieces.clear();
  // L in (u, v) and its orientation.
  double twice_area = 0;
  const int n_light = horizon_clipped.count;
  std::vector<std::pair<double, double>>& light_uv = s.light_uv;
  light_uv.resize(n_light);
  for (int i = 0; i < n_light; ++i)
    light_uv[i] = {dot(view.u, horizon_clipped.d[i]), dot(view.v, horizon_clipped.d[i])};
  for (int i = 0; i < n_light; ++i) {
    const auto& [ax, ay] = light_uv[i];
    const auto& [bx, by] = light_uv[(i + 1) % n_light];
    twice_area += ax * by - bx * ay;
  }
  const int light_turn = twice_area > 0 ? 1 : -1;

  // When no silhouette segment enters L (L convex), the depth is the same all over L: one shadow
  // ray to a point inside L decides (a few points are tried in case a ray grazes an edge).
  bool convex = true;
  for (int i = 0; i < n_light && convex; ++i) {
    const auto& [ax, ay] = light_uv[i];
    const auto& [bx, by] = light_uv[(i + 1) % n_light];
    const auto& [cx, cy] = light_uv[(i + 2) % n_light];
    convex = light_turn * orient2(ax, ay, bx, by, cx, cy) >= 0;
  }
  bool uniform = s.segments.empty();
  if (!uniform && convex) {
    const double tolerance = 1e-12 * (f.rect.x1 - f.rect.x0 + f.rect.y1 - f.rect.y0);
    uniform = true;
    for (const SilhouetteSegment& g : s.segments)
      if (enters_convex(g, light_uv, light_turn, tolerance)) {
        uniform = false;
        break;
      }
  }
  if (uniform) {
    double cu = 0, cv = 0;
    for (const auto& [u, v] : light_uv) cu += u, cv += v;
    cu /= n_light;
    cv /= n_light;
    static constexpr double kToward[kMaxReferenceRays] = {0, 0.31, 0.53, 0.17, 0.71, 0.43, 0.29, 0.61};
    for (int k = 0; k < kMaxReferenceRays; ++k) {
      // From L's vertex mean toward one of its vertices (inside L when L is convex; any point of
      // R serves when no segment is left at all).
      const auto& [vu, vv] = light_uv[k % n_light];
      const double u = cu + kToward[k] * (vu - cu), v = cv + kToward[k] * (vv - cv);
      const int d = depth_at(f, f.center + f.u * u + f.v * v, occluders, s);
      if (d >= 0) return d == 0 ? SilhouetteVisibility::kUnoccluded : SilhouetteVisibility::kPieces;
    }
    return ++s.undecided, SilhouetteVisibility::kUndecided;
  }

  // L's edges, weight -1 for each turn of L around a point (so t = d + 1 - [x in L]).
  for (int i = 0; i < n_light; ++i) {
    const auto& [ax, ay] = light_uv[i];
    const auto& [bx, by] = light_uv[(i + 1) % n_light];
    if (ax != bx || ay != by) s.segments.push_back({ax, ay, bx, by, -light_turn});
  }

  // Steps of t along R's left side, and segments stored bottom-up with their step across.
  std::vector<SilhouetteSegment>& seg = s.segments;
  std::vector<int>& step = s.step;
  step.resize(seg.size());
  s.left_steps.clear();
  for (std::size_t i = 0; i < seg.size(); ++i) {
    SilhouetteSegment& g = seg[i];
    const bool start_left = g.u0 == f.rect.x0, end_left = g.u1 == f.rect.x0;
    if (start_left && !end_left) s.left_steps.push_back({g.v0, g.weight});
    if (end_left && !start_left) s.left_steps.push_back({g.v1, -g.weight});
    // Crossing an upward segment from left to right leaves its left side: t drops by its weight.
    step[i] = g.v1 > g.v0 ? -g.weight : g.weight;
    if (g.v1 < g.v0) {
      std::swap(g.u0, g.u1);
      std::swap(g.v0, g.v1);
    }
  }

  // Events: R's bottom and top, every endpoint, every proper crossing, every left step, each
  // clamped to R. The segments' lower ends come sorted with `order`; the other events are sorted
  // on their own and merged with them.
  auto clamped = [&](double v) { return std::min(std::max(v, f.rect.y0), f.rect.y1); };
  // (This array, the crossing search's list and the slabs' order below are sized once per query
  // and written by index: a push_back per element was a call, not inlined in this function.)
  std::vector<std::pair<double, int>>& by_start = s.by_start;
  by_start.resize(seg.size());
  std::size_t rising = 0;
  for (std::size_t i = 0; i < seg.size(); ++i) {
    by_start[rising] = {seg[i].v0, static_cast<int>(i)};
    rising += seg[i].v1 > seg[i].v0;
  }
  by_start.resize(rising);
  std::sort(by_start.begin(), by_start.end());  // by v0, ties by index
  std::vector<int>& order = s.order;
  order.clear();
  std::vector<double>& starts = s.starts;
  starts.clear();
  std::vector<double>& other_events = s.other_events;
  other_events.assign({f.rect.y0, f.rect.y1});
  auto add_event = [&](double v) { other_events.push_back(clamped(v)); };
  for (const auto& [v0, i] : by_start) {
    order.push_back(i);
    starts.push_back(clamped(v0));
    add_event(seg[i].v1);
  }
  for (const auto& [v, w] : s.left_steps) add_event(v);
  {
    // The segments whose v-range is still open, with what the first test reads, in arrays: the
    // test (still open, and the u-ranges overlap) runs without branches over all of them and
    // lists the ones that pass, which alone are tested for a crossing.
    // Segments that ended stay in the list (skipped) until they are a quarter of it: dropping
    // them at every insertion rewrote the whole list each time. (The segments come in order of
    // v0, so one that ended before this one's start has ended for every later one.)
    AreaSilhouetteScratch::ActiveSegments& active = s.active;
    active.clear();
    s.meets.resize(order.size());
    for (int i : order) {
      const SilhouetteSegment& a = seg[i];
      const double a_lo = std::min(a.u0, a.u1), a_hi = std::max(a.u0, a.u1);
      const std::size_t held = active.index.size();
      std::size_t ended = 0, meets = 0;
      for (std::size_t j = 0; j < held; ++j) {
        const bool open = active.v1[j] > a.v0;
        ended += !open;
        s.meets[meets] = static_cast<int>(j);
        meets += open & (active.u_lo[j] <= a_hi) & (a_lo <= active.u_hi[j]);
      }
      for (std::size_t k = 0; k < meets; ++k) {
        const SilhouetteSegment& b = seg[active.index[s.meets[k]]];
        // A proper crossing: b's ends strictly on both sides of a, and a's of b. The four signs
        // from plain products first, all of them (a branch per sign is mispredicted half the
        // time); orient2_sign where one of them is too close to 0 for its products to decide.
        const int fast[4] = {fast_orient2_sign(a.u0, a.v0, a.u1, a.v1, b.u0, b.v0),
                             fast_orient2_sign(a.u0, a.v0, a.u1, a.v1, b.u1, b.v1),
                             fast_orient2_sign(b.u0, b.v0, b.u1, b.v1, a.u0, a.v0),
                             fast_orient2_sign(b.u0, b.v0, b.u1, b.v1, a.u1, a.v1)};
        if ((fast[0] == 0) | (fast[1] == 0) | (fast[2] == 0) | (fast[3] == 0)) {
          if (orient2_sign(a.u0, a.v0, a.u1, a.v1, b.u0, b.v0) * orient2_sign(a.u0, a.v0, a.u1, a.v1, b.u1, b.v1) >= 0) continue;
          if (orient2_sign(b.u0, b.v0, b.u1, b.v1, a.u0, a.v0) * orient2_sign(b.u0, b.v0, b.u1, b.v1, a.u1, a.v1) >= 0) continue;
        } else if ((fast[0] == fast[1]) | (fast[2] == fast[3])) {
          continue;
        }
        const double o1 = orient2(a.u0, a.v0, a.u1, a.v1, b.u0, b.v0), o2 = orient2(a.u0, a.v0, a.u1, a.v1, b.u1, b.v1);
        add_event(b.v0 + (b.v1 - b.v0) * (o1 / (o1 - o2)));
      }
      if (4 * ended > held) active.keep_open_after(a.v0);
      active.push(a.v1, a_lo, a_hi, i);
    }
  }
  boost::sort::pdqsort_branchless(other_events.begin(), other_events.end());
  std::vector<double>& events = s.events;
  events.resize(starts.size() + other_events.size());
  std::merge(starts.begin(), starts.end(), other_events.begin(), other_events.end(), events.begin());
  events.erase(std::unique(events.begin(), events.end()), events.end());
  const int slabs = static_cast<int>(events.size()) - 1;

  // Left steps summed per event line: t in slab k's leftmost trapezoid is t0 + prefix[k].
  std::vector<int>& prefix = s.prefix;
  prefix.assign(slabs, 0);
  for (const auto& [v, w] : s.left_steps) {
    const int k = static_cast<int>(std::lower_bound(events.begin(), events.end(), v) - events.begin());
    if (k >= 1 && k < slabs) prefix[k] += w;
  }
  for (int k = 1; k < slabs; ++k) prefix[k] += prefix[k - 1];

  // The segments spanning slab k (v0 <= its bottom, v1 >= its top) with their u at its middle,
  // sorted by u, ties by index, into `members`.
  std::vector<std::pair<double, int>>& members = s.slab_segments;
  auto segments_of_slab = [&](int k) {
    const double lo = events[k], hi = events[k + 1], mid = 0.5 * (lo + hi);
    members.clear();
    for (std::size_t next = 0; next < order.size() && seg[order[next]].v0 <= lo; ++next)
      if (seg[order[next]].v1 >= hi) members.push_back({u_at(seg[order[next]], mid), order[next]});
    std::sort(members.begin(), members.end());
  };

  // Reference: t at a point inside L, from one shadow ray; tall slabs and wide trapezoids first
  // (the slabs are taken tallest first, ties lowest first; one or two are usually enough, so each
  // is picked from the rest instead of sorting them all).
  std::vector<int>& by_height = s.by_height;
  by_height.resize(slabs);
  for (int k = 0; k < slabs; ++k) by_height[k] = k;
  auto taller = [&](int a, int b) {
    return events[a + 1] - events[a] > events[b + 1] - events[b] || (events[a + 1] - events[a] == events[b + 1] - events[b] && a < b);
  };
  bool have_reference = false;
  int t0 = 0;
  int rays = 0;
  for (int next_slab = 0; next_slab < slabs; ++next_slab) {
    if (rays >= kMaxReferenceRays || have_reference) break;
    std::iter_swap(by_height.begin() + next_slab, std::min_element(by_height.begin() + next_slab, by_height.end(), taller));
    const int k = by_height[next_slab];
    const double mid = 0.5 * (events[k] + events[k + 1]);
    segments_of_slab(k);
    const int n = static_cast<int>(members.size());
    std::vector<std::pair<double, int>>& gaps = s.sorted;  // (width, index of the segment on its left)
    gaps.clear();
    for (int i = 0; i + 1 < n; ++i) {
      const double a = members[i].first, b = members[i + 1].first;
      if (b > a) gaps.push_back({b - a, i});
    }
    std::sort(gaps.begin(), gaps.end(), [](const auto& x, const auto& y) { return x.first > y.first || (x.first == y.first && x.second < y.second); });
    for (const auto& [width, i] : gaps) {
      if (rays >= kMaxReferenceRays) break;
      const double u = members[i].first + 0.5 * width;
      const Vec3d x = f.u * u + f.v * mid;  // relative to the light's centre
      if (winding_number(horizon_clipped, view, x) == 0) continue;
      ++rays;
      const int d = depth_at(f, f.center + x, occluders, s);
      if (d < 0) continue;
      int left = 0;
      for (int j = 0; j <= i; ++j) left += step[members[j].second];
      t0 = d - left - prefix[k];  // t inside L is d; t in the leftmost trapezoid of slab 0
      have_reference = true;
      break;
    }
  }
  if (!have_reference) {
    ++s.undecided;
    return SilhouetteVisibility::kUndecided;
  }

  // The trapezoids with t = 0, merged upward while the same two segments bound them (with
  // SilhouettePieces::kChains, also while the segments that bound them continue one another).
  std::vector<AreaSilhouetteScratch::Open>& open = s.open;
  std::vector<AreaSilhouetteScratch::Open>& now = s.now;
  std::vector<AreaSilhouetteScratch::ChainVertex>& chain = s.chain;
  open.clear();
  chain.clear();
  using Open = AreaSilhouetteScratch::Open;
  auto close = [&](const Open& o, double v_end) {
    const SilhouetteSegment& a = seg[o.a];
    const SilhouetteSegment& b = seg[o.b];
    double a0 = o.a0, b0 = o.b0, a1 = u_at(a, v_end), b1 = u_at(b, v_end);
    if (b0 < a0) a0 = b0 = 0.5 * (a0 + b0);
    if (b1 < a1) a1 = b1 = 0.5 * (a1 + b1);
    // Counter-clockwise in (u, v): the lower corners, the right chain upward, the upper corners,
    // the left chain downward.
    double corner_uv[kMaxChainPiece + 4][2];
    int corners = 0;
    auto corner = [&](double u, double v) { corner_uv[corners][0] = u, corner_uv[corners++][1] = v; };
    corner(a0, o.v_start);
    corner(b0, o.v_start);
    const int right_first = corners;
    for (int k = o.right; k >= 0; k = chain[k].below) corner(chain[k].u, chain[k].v);
    std::reverse(corner_uv + right_first, corner_uv + corners);
    corner(b1, v_end);
    corner(a1, v_end);
    for (int k = o.left; k >= 0; k = chain[k].below) corner(chain[k].u, chain[k].v);
    Vec3d points[kMaxChainPiece + 4];
    int n = 0;
    for (int i = 0; i < corners; ++i) {
      const Vec3d x = f.u * corner_uv[i][0] + f.v * corner_uv[i][1];
      if (n == 0 || !(x == points[n - 1])) points[n++] = x;
    }
    if (n > 1 && points[n - 1] == points[0]) --n;
    if (n < 3) return;
    if (light_turn < 0) std::reverse(points, points + n);
    pieces.add(points, n, light_view.u, light_view.v);
  };
  // Segment q starts where segment p ends, on the line v = lo.
  auto continues = [&](int p, int q, double lo) {
    return seg[p].v1 == lo && seg[q].v0 == lo && seg[p].u1 == seg[q].u0;
  };
  // A slab thinner than this fraction of R (a nearly horizontal segment makes one an ulp high)
  // cannot order its segments: it is left out (its area is below that fraction of R's).
  const double thin = kThinSlab * (f.rect.y1 - f.rect.y0);
  // Per segment, the open trapezoid it bounds on the left (a segment has one right neighbour in
  // a slab), so a trapezoid of the next slab finds the one it continues in one look.
  std::vector<int>& open_at = s.open_at;
  std::vector<char>& continued = s.continued;
  open_at.assign(seg.size(), -1);
  auto forget_open = [&] {
    for (const Open& o : open) open_at[o.a] = -1;
  };
  // The slabs bottom-up, each with its segments in order of u at its middle (ties by index): the
  // order changes little from one slab to the next (only at its events), so the previous one is
  // kept and repaired by insertion; then t is walked across the slab.
  std::vector<std::pair<double, int>>& sorted = s.sorted;  // sorted[0, held)
  sorted.resize(order.size());
  std::size_t held = 0, next = 0;
  for (int k = 0; k < slabs; ++k) {
    const double lo = events[k], hi = events[k + 1], mid = 0.5 * (lo + hi);
    // The segments still open (the others ended: v1 is an event) and those starting here, each
    // with its u at the slab's middle.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < held; ++i) {
      const int j = sorted[i].second;
      if (seg[j].v1 > lo) sorted[kept++] = {u_at(seg[j], mid), j};
    }
    held = kept;
    while (next < order.size() && seg[order[next]].v0 <= lo) {
      const int j = order[next++];
      if (seg[j].v1 >= hi) sorted[held++] = {u_at(seg[j], mid), j};
    }
    for (std::size_t i = 1; i < held; ++i)
      for (std::size_t j = i; j > 0 && sorted[j] < sorted[j - 1]; --j) std::swap(sorted[j], sorted[j - 1]);

    now.clear();
    if (hi - lo < thin) {
      for (const Open& o : open) close(o, lo);
      forget_open();
      open.clear();
      continue;
    }
    int t = t0 + prefix[k];
    if (t < 1) return ++s.undecided, SilhouetteVisibility::kUndecided;
    const int n = static_cast<int>(held);
    continued.assign(open.size(), 0);
    for (int i = 0; i < n; ++i) {
      t += step[sorted[i].second];
      if (t < 0) return ++s.undecided, SilhouetteVisibility::kUndecided;
      if (t == 0 && i + 1 < n) {
        const int a = sorted[i].second, b = sorted[i + 1].second;
        const int j = open_at[a];
        if (j >= 0 && open[j].b == b) {  // the same two segments: the piece below grows on
          now.push_back(open[j]);
          continued[j] = 1;
          continue;
        }
        Open o{a, b, lo, u_at(seg[a], lo), u_at(seg[b], lo)};  // a new piece, unless a chain continues
        if (cut == SilhouettePieces::kChains && o.a0 < o.b0) {
          // A piece below whose bounding segments are a and b or end where they start: it
          // grows on, with a vertex where a side turns from one segment to the next.
          for (std::size_t k = 0; k < open.size(); ++k) {
            if (continued[k]) continue;
            const bool same_left = open[k].a == a, same_right = open[k].b == b;
            if (!(same_left || continues(open[k].a, a, lo)) || !(same_right || continues(open[k].b, b, lo))) continue;
            const int turns = !same_left + !same_right;
            if (open[k].chain_vertices + turns > kMaxChainPiece) break;
            Open grown = open[k];
            grown.a = a;
            grown.b = b;
            grown.chain_vertices += turns;
            if (!same_left) {
              chain.push_back({o.a0, lo, grown.left});
              grown.left = static_cast<int>(chain.size()) - 1;
            }
            if (!same_right) {
              chain.push_back({o.b0, lo, grown.right});
              grown.right = static_cast<int>(chain.size()) - 1;
            }
            o = grown;
            continued[k] = 1;
            break;
          }
        }
        now.push_back(o);
      }
    }
    if (t < 1) return ++s.undecided, SilhouetteVisibility::kUndecided;
    for (std::size_t j = 0; j < open.size(); ++j)
      if (!continued[j]) close(open[j], lo);
    forget_open();
    std::swap(open, now);
    for (std::size_t j = 0; j < open.size(); ++j) open_at[open[j].a] = static_cast<int>(j);
  }
  for (const Open& o : open) close(o, events[slabs]);
  s.visible_pieces += static_cast<long>(pieces.size());
  return SilhouetteVisibility::kPieces;
}

}  // namespace vlit
