#include "shadow/occluder_bvh.h"

#include <omp.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace vlit {

bool segment_hits_triangle(const Vec3d& a, const Vec3d& b, const std::array<Vec3d, 3>& tri, double t_min,
                           double t_max) {
  const Vec3d dir = b - a;
  const Vec3d e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
  const Vec3d pvec = cross(dir, e2);
  const double det = dot(e1, pvec);
  if (!(std::abs(det) > 0)) return false;  // segment parallel to the plane, or a degenerate triangle
  const double inv = 1.0 / det;
  const Vec3d tvec = a - tri[0];
  const double u = dot(tvec, pvec) * inv;
  constexpr double kSlack = 1e-12;
  if (u < -kSlack || u > 1 + kSlack) return false;
  const Vec3d qvec = cross(tvec, e1);
  const double v = dot(dir, qvec) * inv;
  if (v < -kSlack || u + v > 1 + kSlack) return false;
  const double t = dot(e2, qvec) * inv;
  return t > t_min && t < t_max;
}

namespace {

// Slab test of the segment a + t d, t in [t0, t1], against boxes: the reciprocals of d are taken
// once per segment, so a node costs products, not divisions. Their rounding (an ulp or two of t)
// lies far inside the nodes' padding (padded(), 1e-9 of the scene's scale).
struct SegmentSlabs {
  Vec3d a;
  double inverse[3], t0, t1;
  bool along[3];  // d has no component on that axis: a's coordinate must lie in the box's range
  SegmentSlabs(const Vec3d& origin, const Vec3d& d, double t_min, double t_max) : a(origin), t0(t_min), t1(t_max) {
    for (int axis = 0; axis < 3; ++axis) {
      along[axis] = d[axis] == 0;
      inverse[axis] = along[axis] ? 0 : 1 / d[axis];
    }
  }
  bool meets(const Aabb& box) const {
    double lo_t = t0, hi_t = t1;
    for (int axis = 0; axis < 3; ++axis) {
      const double o = a[axis], lo = box.lo[axis], hi = box.hi[axis];
      if (along[axis]) {
        if (o < lo || o > hi) return false;
        continue;
      }
      const double ta = (lo - o) * inverse[axis], tb = (hi - o) * inverse[axis];
      lo_t = std::max(lo_t, std::min(ta, tb));
      hi_t = std::min(hi_t, std::max(ta, tb));
    }
    return lo_t <= hi_t;
  }
};

// Boxes are grown by a relative margin so that rounding in the slab test never drops a
// triangle the exact per-triangle test would accept.
Aabb padded(Aabb b) {
  const Vec3d size = b.hi - b.lo;
  const double scale = std::max({std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.lo.z), std::abs(b.hi.x),
                                 std::abs(b.hi.y), std::abs(b.hi.z), size.x, size.y, size.z});
  const double m = 1e-9 * scale;
  b.lo = b.lo - Vec3d{m, m, m};
  b.hi = b.hi + Vec3d{m, m, m};
  return b;
}

// The signed distance to the half-space's plane (unit normal) of the box's corner farthest along
// the normal (or, with farthest false, the one least far), and the margin that the rounding of the
// per-triangle tests could explain. The margin uses max-norms (within sqrt(3) of the Euclidean
// ones; it is widened by 2 for that).
struct BoxReach {
  double distance, margin;
};
BoxReach box_reach(const Aabb& box, const HalfSpace& h, bool farthest) {
  auto pick = [&](double n, double lo, double hi) { return (n >= 0) == farthest ? hi : lo; };
  const Vec3d corner{pick(h.normal.x, box.lo.x, box.hi.x), pick(h.normal.y, box.lo.y, box.hi.y),
                     pick(h.normal.z, box.lo.z, box.hi.z)};
  const Vec3d w = corner - h.origin;
  const Vec3d e = box.hi - box.lo;
  const double scale = std::max({std::abs(w.x), std::abs(w.y), std::abs(w.z)}) + std::max({e.x, e.y, e.z});
  return {dot(h.normal, w), 2e-9 * scale};
}

// The box lies wholly outside the half-space (unit normal): its corner farthest along the normal
// is behind the plane by more than the margin.
bool box_outside_unit(const Aabb& box, const HalfSpace& h) {
  const BoxReach r = box_reach(box, h, true);
  return r.distance < -r.margin;
}

// The box lies wholly inside the half-space (unit normal): its nearest corner is in front by more
// than the margin.
bool box_inside_unit(const Aabb& box, const HalfSpace& h) {
  const BoxReach r = box_reach(box, h, false);
  return r.distance > r.margin;
}

// A half-space with a unit normal, and the part of the ball tests' margin that its origin brings
// (OccluderBvh::ball_side).
struct UnitPlane {
  HalfSpace h;
  double origin_margin = 0;
};
UnitPlane unit_plane(const HalfSpace& plane) {
  const double len = length(plane.normal);
  const Vec3d& o = plane.origin;
  return {{len > 0 ? plane.normal / len : Vec3d{}, o}, 2e-9 * std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)})};
}

// The planes of a convex volume with unit normals; a volume with more than 16 is culled by its
// first 16.
struct UnitPlanes {
  UnitPlane plane[16];
  int count = 0;
  explicit UnitPlanes(const std::vector<HalfSpace>& planes) {
    for (const HalfSpace& h : planes)
      if (count < 16) plane[count++] = unit_plane(h);
  }
  std::uint32_t all_bits() const { return (1u << count) - 1; }
};

// Bits of the planes proven to hold a node during a walk down the tree (OccluderBvh::visit_volume):
// bit k for the volume's plane k (k < 16), bit kSlabBit + k for the plane k of a search's `inside`.
// A node's triangles lie in its box, and a child's box in its parent's, so a plane that holds a
// node with the tests' margin holds every triangle below it with that margin: the child is not
// tested again.
constexpr int kSlabBit = 16;

// The `inside` planes of the silhouette searches with unit normals; more than 4 are never held
// (no subtree is skipped as uniform: conservative). A plane that is also one of the volume's (the
// same normal and origin: the area searches pass the slab's two planes, which bound the volume too)
// takes that plane's bit, which visit_volume has already decided for the node.
struct UnitHalfSpaces {
  UnitPlane h[4];
  std::uint32_t bit[4] = {};
  bool decided[4] = {};  // bit[k] is a volume plane's
  std::uint32_t bits = 0;  // every plane's bit
  int count = 0;
  bool too_many = false;
  UnitHalfSpaces(const HalfSpace* planes, int n, const std::vector<HalfSpace>& volume_planes) : too_many(n > 4) {
    for (int k = 0; k < n && k < 4; ++k) {
      h[count] = unit_plane(planes[k]);
      bit[count] = 1u << (kSlabBit + k);
      for (std::size_t j = 0; j < volume_planes.size() && j < kSlabBit; ++j) {
        const HalfSpace& v = volume_planes[j];
        if (v.normal == planes[k].normal && v.origin == planes[k].origin) {
          bit[count] = 1u << j;
          decided[count] = true;
          break;
        }
      }
      bits |= bit[count++];
    }
  }
};

// The node lies inside every half-space of `slab`; the planes proven on the way are added to `held`.
bool holds(const OccluderBvh& bvh, const UnitHalfSpaces& slab, std::uint32_t node, std::uint32_t& held) {
  if (slab.too_many) return false;
  if ((held & slab.bits) == slab.bits) return true;
  for (int k = 0; k < slab.count; ++k) {
    if (held & slab.bit[k]) continue;
    if (slab.decided[k] || !bvh.inside(node, slab.h[k].h, slab.h[k].origin_margin)) return false;
    held |= slab.bit[k];
  }
  return true;
}

}  // namespace

OccluderBvh::OccluderBvh(OccluderTriangles triangles, bool brute_force)
    : triangles_(std::move(triangles)), brute_force_(brute_force) {
  const long n = static_cast<long>(triangles_.size());
  boxes_.resize(n);
  std::vector<Vec3d> centroids(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    boxes_[i] = box_of(triangles_.corners[i]);
    centroids[i] = boxes_[i].center();
  }
  for (const Aabb& box : boxes_) bounds_.grow(box);
  order_.resize(n);
  for (long i = 0; i < n; ++i) order_[i] = static_cast<std::uint32_t>(i);
  if (n > 0) {
    nodes_.reserve(2 * (n / kLeafSize + 1));
#pragma omp parallel
#pragma omp single
    build(nodes_, 0, static_cast<std::uint32_t>(n), centroids, 0);
  }
  // The triangles are stored in leaf order (the brute-force mode too, so that both number them
  // alike): a query reads neighbouring triangles, and their edges, from neighbouring memory.
  OccluderTriangles sorted;
  sorted.corners.resize(n);
  sorted.ids.resize(n);
  if (!triangles_.solid.empty()) sorted.solid.resize(n);
  sorted.solid_bounds = triangles_.solid_bounds;
  std::vector<Aabb> boxes(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    sorted.corners[i] = triangles_.corners[order_[i]];
    sorted.ids[i] = triangles_.ids[order_[i]];
    if (!sorted.solid.empty()) sorted.solid[i] = triangles_.solid[order_[i]];
    boxes[i] = boxes_[order_[i]];
    order_[i] = static_cast<std::uint32_t>(i);
  }
  triangles_ = std::move(sorted);
  boxes_ = std::move(boxes);
  edges_ = edges_of(triangles_);
  planes_.resize(n);
#pragma omp parallel for schedule(static)
  for (long t = 0; t < n; ++t) {
    const auto& c = triangles_.corners[t];
    TrianglePlane& plane = planes_[t];
    plane.normal = cross(c[1] - c[0], c[2] - c[0]);
    plane.normal_length = length(plane.normal);
    plane.longest_squared =
        std::max({length_squared(c[1] - c[0]), length_squared(c[2] - c[1]), length_squared(c[0] - c[2])});
  }
  if (brute_force_) nodes_.clear();
  else if (n > 0) build_cones();
}

namespace {

double angle_between(const Vec3d& a, const Vec3d& b) {  // unit vectors; stable near 0 and pi
  const double d = dot(a, b);
  if (d < 0) return M_PI - 2 * std::asin(std::min(1.0, length(a + b) / 2));
  return 2 * std::asin(std::min(1.0, length(a - b) / 2));
}


// Depth first over the tree from the root (children of a node pushed in one fixed order): a node
// is entered when enter(node) is true; leaf(node) is called for every entered leaf and ends the
// walk by returning true. Returns whether a leaf ended it.
template <class Nodes, class Enter, class Leaf>
bool descend(const Nodes& nodes, const Enter& enter, const Leaf& leaf) {
  std::uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t self = stack[--top];
    if (!enter(self)) continue;
    const auto& node = nodes[self];
    if (node.count > 0) {
      if (leaf(self)) return true;
    } else {
      stack[top++] = node.first;
      stack[top++] = self + 1;
    }
  }
  return false;
}

}  // namespace

void OccluderBvh::build_cones() {
  const long n = static_cast<long>(triangles_.size());
  std::vector<Vec3d> unit(n);
  std::vector<char> degenerate(n);
#pragma omp parallel for schedule(static)
  for (long t = 0; t < n; ++t) {
    const TrianglePlane& plane = planes_[t];
    const double len = plane.normal_length;
    // Needles (is_occluder's kSliver, area_visibility.h) hide nothing: their neighbours' edges
    // may be silhouettes whatever the facing, so no cone holding them is bounded.
    degenerate[t] = !(len > 1e-10 * plane.longest_squared) || !std::isfinite(len);
    unit[t] = degenerate[t] ? Vec3d{0, 0, 1} : plane.normal / len;
  }
  // The cone of a triangle and its edge neighbours (t itself, then the triangles of each of its
  // edges, t among them), then of the subtrees, bottom-up (children are stored after their parent).
  auto cone_of_triangle = [&](std::uint32_t t) {
    NormalCone cone;
    cone.open = edges_.has_open_edge[t] != 0;
    cone.solid = triangles_.solid.empty() ? -1 : triangles_.solid[t];
    auto for_members = [&](const auto& f) {
      f(t);
      for (int j = 0; j < 3; ++j) {
        const std::uint32_t e = edges_.edge_of[t][j];
        for (std::uint32_t k = edges_.first_incident[e]; k < edges_.first_incident[e + 1]; ++k) f(edges_.incident[k] / 3);
      }
    };
    Vec3d sum{};
    bool unbounded = false;
    for_members([&](std::uint32_t m) {
      sum += unit[m];
      unbounded = unbounded || degenerate[m];
    });
    if (unbounded || !(length(sum) > 1e-6)) return cone;
    cone.axis = normalize(sum);
    cone.half_angle = 0;
    for_members([&](std::uint32_t m) { cone.half_angle = std::max(cone.half_angle, angle_between(cone.axis, unit[m])); });
    return cone;
  };
  auto merge = [](const NormalCone& a, const NormalCone& b) {
    NormalCone m;
    m.open = a.open || b.open;
    m.solid = a.solid == b.solid ? a.solid : -2;
    if (a.half_angle >= M_PI || b.half_angle >= M_PI) return m;
    const Vec3d sum = a.axis + b.axis;
    if (!(length(sum) > 1e-6)) return m;
    m.axis = normalize(sum);
    m.half_angle = std::max(angle_between(m.axis, a.axis) + a.half_angle, angle_between(m.axis, b.axis) + b.half_angle);
    if (m.half_angle >= M_PI) m.half_angle = 4;
    return m;
  };
  auto finish = [](NormalCone& c) {
    if (c.half_angle < M_PI / 2) {
      c.cos_half_angle = std::cos(c.half_angle);
      c.sin_half_angle = std::sin(c.half_angle);
    }
  };
  const long node_count = static_cast<long>(nodes_.size());
  cones_.assign(node_count, NormalCone{});
  // The leaves first, side by side; then the inner nodes, bottom-up.
#pragma omp parallel for schedule(static)
  for (long i = 0; i < node_count; ++i) {
    const Node& node = nodes_[i];
    if (node.count == 0) continue;
    NormalCone cone = cone_of_triangle(order_[node.first]);
    for (std::uint32_t k = node.first + 1; k < node.first + node.count; ++k) cone = merge(cone, cone_of_triangle(order_[k]));
    finish(cone);
    cones_[i] = cone;
  }
  for (long i = node_count; i-- > 0;) {
    const Node& node = nodes_[i];
    if (node.count > 0) continue;
    cones_[i] = merge(cones_[i + 1], cones_[node.first]);
    finish(cones_[i]);
  }
  // The ball test's margin (ball_side()) must be at least the box test's, 2e-9 (max |w| + max
  // extent) with w = corner - origin: |w| <= |centre| + |origin| + radius and the extent is at most
  // 2 radius (max-norms); 1e-12 |centre| more covers the rounding of the centre itself.
  balls_.resize(node_count);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < node_count; ++i) balls_[i] = ball_of(nodes_[i].box);
}

OccluderBvh::Ball OccluderBvh::ball_of(const Aabb& box) {
  Ball ball;
  ball.center = box.center();
  ball.radius = 0.5 * length(box.hi - box.lo);
  const double c = std::max({std::abs(ball.center.x), std::abs(ball.center.y), std::abs(ball.center.z)});
  ball.margin = 2e-9 * (c + 3 * ball.radius) + 1e-12 * c;
  return ball;
}

// Where a node lies against a half-space (unit normal): decided by the ball that holds its box (one
// dot product), and by the box only when the ball straddles the plane. The ball's margin is at
// least the box test's (build_cones), so the ball never decides what the box test would not.
int OccluderBvh::ball_side(const Ball& ball, const HalfSpace& h, double origin_margin) {
  const double d = dot(h.normal, ball.center - h.origin), margin = ball.margin + origin_margin;
  if (d + ball.radius < -margin) return -1;
  if (d - ball.radius > margin) return 1;
  return 0;
}

int OccluderBvh::side_of(std::uint32_t node, const HalfSpace& h, double origin_margin) const {
  if (const int side = ball_side(balls_[node], h, origin_margin)) return side;
  if (box_outside_unit(nodes_[node].box, h)) return -1;
  return box_inside_unit(nodes_[node].box, h) ? 1 : 0;
}

bool OccluderBvh::inside(std::uint32_t node, const HalfSpace& h, double origin_margin) const {
  const int side = ball_side(balls_[node], h, origin_margin);
  return side != 0 ? side > 0 : box_inside_unit(nodes_[node].box, h);
}

// Every triangle of the subtree and every edge neighbour of them faces p the same way (strictly,
// with a margin far above the rounding of the facing test). The facing of a triangle is the sign
// of n.(p - x) for any x of its plane; a neighbour's plane passes through the shared edge, which
// lies in the subtree's box, so bounding n.(p - x) over the normal cone's directions n and the
// points x of the node's ball bounds them all. With w = p - c (c the ball's centre, D = |w|, alpha
// the angle from the cone's axis to w, theta the cone's half-angle, r the ball's radius):
//   n.(p - x) >= D cos(alpha + theta) - r   and   n.(p - x) <= D cos(alpha - theta) + r
// (each while the angle stays in [0, pi], which the tests below need anyway), with
// D cos(alpha -+ theta) = (a cos theta +- b sin theta), a = axis.w, b = |axis x w|. With p_radius > 0
// the same holds for every point of the ball of that radius around p (r grows by it). The margin
// is 1e-6 of the largest |p - x|, far above the rounding of the facing test (kEdgeOn 1e-12).
bool OccluderBvh::faces_uniformly(std::uint32_t node, const Vec3d& p, double p_radius) const {
  const NormalCone& cone = cones_[node];
  if (cone.open || !(cone.half_angle < M_PI / 2)) return false;
  const Ball& ball = balls_[node];
  const Vec3d w = p - ball.center;
  const double a = dot(cone.axis, w), b = length(cross(cone.axis, w));
  const double r = ball.radius + p_radius;
  constexpr double kMargin = 1e-6;
  const double margin = r + kMargin * (std::abs(a) + b + r);  // |a| + b >= D
  if (a * cone.cos_half_angle - b * cone.sin_half_angle > margin) return true;               // all face p
  if (a * cone.cos_half_angle + b * cone.sin_half_angle < -margin) return cone.solid != -2;  // all face away
  return false;
}

void OccluderBvh::build(std::vector<Node>& out, std::uint32_t begin, std::uint32_t end, const std::vector<Vec3d>& centroids,
                        int depth) {
  const std::uint32_t index = static_cast<std::uint32_t>(out.size());
  out.push_back({});
  Aabb box, centroid_box;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.grow(boxes_[order_[i]]);
    centroid_box.grow(centroids[order_[i]]);
  }
  out[index].box = padded(box);
  const Vec3d extent = centroid_box.hi - centroid_box.lo;
  if (end - begin <= kLeafSize || depth > 60 || (extent.x <= 0 && extent.y <= 0 && extent.z <= 0)) {
    out[index].first = begin;
    out[index].count = end - begin;
    return;
  }
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
  // Large subtrees are built side by side (OpenMP tasks), each into its own array, then appended
  // in the serial build's order: the same nodes in the same places.
  constexpr std::uint32_t kParallelSubtree = 1 << 14;
  if (end - begin < 2 * kParallelSubtree || omp_get_num_threads() < 2) {
    build(out, begin, mid, centroids, depth + 1);
    out[index].first = static_cast<std::uint32_t>(out.size());
    build(out, mid, end, centroids, depth + 1);
    return;
  }
  std::vector<Node> halves[2];
#pragma omp task default(shared)
  build(halves[0], begin, mid, centroids, depth + 1);
  build(halves[1], mid, end, centroids, depth + 1);
#pragma omp taskwait
  auto append = [&](const std::vector<Node>& half) {
    const std::uint32_t offset = static_cast<std::uint32_t>(out.size());
    for (Node node : half) {
      if (node.count == 0) node.first += offset;  // an inner node's right child
      out.push_back(node);
    }
  };
  append(halves[0]);
  out[index].first = static_cast<std::uint32_t>(out.size());
  append(halves[1]);
}

bool OccluderBvh::segment_occluded(const Vec3d& a, const Vec3d& b, const Vec3d& skip, double t_min,
                                   double t_max) const {
  auto test = [&](std::uint32_t tri) {
    const auto& corners = triangles_.corners[tri];
    return !touches(corners, skip) && segment_hits_triangle(a, b, corners, t_min, t_max);
  };
  if (brute_force_ || nodes_.empty()) {
    for (std::uint32_t i = 0; i < triangles_.size(); ++i)
      if (test(i)) return true;
    return false;
  }
  const SegmentSlabs slabs(a, b - a, t_min, t_max);
  return descend(
      nodes_, [&](std::uint32_t self) { return slabs.meets(nodes_[self].box); },
      [&](std::uint32_t self) {
        const Node& node = nodes_[self];
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
          if (test(order_[i])) return true;
        return false;
      });
}

void OccluderBvh::triangles_in_volume(const ConvexVolume& volume, const Vec3d& skip,
                                      std::vector<std::uint32_t>& out) const {
  out.clear();
  auto test = [&](std::uint32_t tri) {
    const auto& corners = triangles_.corners[tri];
    return !touches(corners, skip) && triangle_overlaps(corners, volume);
  };
  if (brute_force_ || nodes_.empty()) {
    for (std::uint32_t i = 0; i < triangles_.size(); ++i)
      if (test(i)) out.push_back(i);
    return;
  }
  visit_volume(volume, [](std::uint32_t, std::uint32_t&) { return false; }, [&](std::uint32_t node, std::uint32_t) {
    for (std::uint32_t i = nodes_[node].first; i < nodes_[node].first + nodes_[node].count; ++i)
      if (test(order_[i])) out.push_back(order_[i]);
  });
}

bool OccluderBvh::near_volume(std::uint32_t tri, const ConvexVolume& volume, std::uint32_t held) const {
  const auto& c = triangles_.corners[tri];
  auto outside = [&](const HalfSpace& h) {
    return h.signed_distance(c[0]) < 0 && h.signed_distance(c[1]) < 0 && h.signed_distance(c[2]) < 0;
  };
  // The planes that carry a bit and do not hold the leaf, lowest first; then those past the bits.
  const std::size_t count = volume.planes.size();
  const std::uint32_t with_bits = (1u << std::min<std::size_t>(count, kSlabBit)) - 1;
  for (std::uint32_t untested = with_bits & ~held; untested != 0; untested &= untested - 1)
    if (outside(volume.planes[std::countr_zero(untested)])) return false;
  for (std::size_t k = kSlabBit; k < count; ++k)
    if (outside(volume.planes[k])) return false;
  return box_of(c).overlaps(volume.box);
}

void OccluderBvh::silhouette_candidates(const ConvexVolume& volume, const HalfSpace* inside, int inside_count,
                                        const Vec3d& p, std::vector<std::uint32_t>& out,
                                        std::vector<std::uint8_t>& held_inside, double p_radius) const {
  out.clear();
  held_inside.clear();
  if (brute_force_ || nodes_.empty()) {
    for (std::uint32_t i = 0; i < triangles_.size(); ++i)
      if (near_volume(i, volume)) out.push_back(i);
    held_inside.assign(out.size(), 0);
    return;
  }
  // A subtree that faces p uniformly and that no plane of `inside` cuts carries no silhouette.
  const UnitHalfSpaces slab(inside, inside_count, volume.planes);
  auto uniform = [&](std::uint32_t node, std::uint32_t& held) {
    return holds(*this, slab, node, held) && faces_uniformly(node, p, p_radius);
  };
  visit_volume(volume, uniform, [&](std::uint32_t node, std::uint32_t held) {
    const std::uint8_t in = !slab.too_many && (held & slab.bits) == slab.bits;
    for (std::uint32_t i = nodes_[node].first; i < nodes_[node].first + nodes_[node].count; ++i)
      if (near_volume(order_[i], volume, held)) {
        out.push_back(order_[i]);
        held_inside.push_back(in);
      }
  });
}

void OccluderBvh::silhouette_leaves(const ConvexVolume& volume, const HalfSpace* inside, int inside_count,
                                    const Vec3d& p, double p_radius, std::vector<std::uint32_t>& leaves,
                                    std::vector<std::uint32_t>* held_planes) const {
  leaves.clear();
  if (held_planes) held_planes->clear();
  if (brute_force_ || nodes_.empty()) return;
  const UnitHalfSpaces slab(inside, inside_count, volume.planes);
  auto uniform = [&](std::uint32_t node, std::uint32_t& held) {
    return holds(*this, slab, node, held) && faces_uniformly(node, p, p_radius);
  };
  visit_volume(volume, uniform, [&](std::uint32_t node, std::uint32_t held) {
    leaves.push_back(node);
    if (held_planes) held_planes->push_back(held);
  });
}

void OccluderBvh::leaf_bounds(const std::vector<std::uint32_t>& leaves, LeafBounds& out) const {
  out.leaf.clear();
  out.block.clear();
  for (std::uint32_t leaf : leaves) out.leaf.push_back({nodes_[leaf].box, balls_[leaf]});
  for (std::size_t begin = 0; begin < leaves.size(); begin += kLeafBlock) {
    Aabb box;
    for (std::size_t i = begin; i < std::min(begin + kLeafBlock, leaves.size()); ++i) box.grow(out.leaf[i].box);
    out.block.push_back({box, ball_of(box)});
  }
}

void OccluderBvh::leaves_reached(const LeafBounds& leaves, const ConvexVolume& volume,
                                 std::vector<std::uint32_t>& out) const {
  out.clear();
  const Aabb query = padded(volume.box);
  const UnitPlanes planes(volume.planes);  // as visit_volume
  for (std::size_t b = 0; b < leaves.block.size(); ++b) {
    // A block's box and ball hold its leaves' boxes: a block wholly outside the query box or one
    // plane holds no leaf the tests below would keep, and a plane that holds the block holds its
    // leaves; the leaves are tested against the planes that straddle the block.
    const Bounds& block = leaves.block[b];
    if (!block.box.overlaps(query)) continue;
    std::uint32_t straddled = 0;
    bool block_out = false;
    for (int k = 0; k < planes.count && !block_out; ++k) {
      const int side = ball_side(block.ball, planes.plane[k].h, planes.plane[k].origin_margin);
      block_out = side < 0;
      if (side == 0) straddled |= 1u << k;
    }
    if (block_out) continue;
    const std::size_t end = std::min((b + 1) * kLeafBlock, leaves.leaf.size());
    for (std::size_t i = b * kLeafBlock; i < end; ++i) {
      const Bounds& leaf = leaves.leaf[i];
      if (!leaf.box.overlaps(query)) continue;
      // Wholly outside a plane: by the leaf's ball, or by its box where the ball crosses the plane.
      bool out_of_volume = false;
      for (std::uint32_t untested = straddled; untested != 0 && !out_of_volume; untested &= untested - 1) {
        const int k = std::countr_zero(untested);
        const int side = ball_side(leaf.ball, planes.plane[k].h, planes.plane[k].origin_margin);
        out_of_volume = side < 0 || (side == 0 && box_outside_unit(leaf.box, planes.plane[k].h));
      }
      if (!out_of_volume) out.push_back(static_cast<std::uint32_t>(i));
    }
  }
}

// Depth first, the left child before the right: the leaves come in the order of their triangles
// (the tree stores a left subtree's triangles before the right one's), so what the searches collect
// is ascending without a sort.
template <class Prune, class Leaf>
void OccluderBvh::visit_volume(const ConvexVolume& volume, const Prune& prune, const Leaf& leaf) const {
  const Aabb query = padded(volume.box);
  const UnitPlanes planes(volume.planes);
  struct Entry {
    std::uint32_t node, held;  // held: the planes proven to hold its parent (kSlabBit)
  };
  Entry stack[128];
  int top = 0;
  stack[top++] = {0, 0};
  while (top > 0) {
    Entry e = stack[--top];
    const Node& node = nodes_[e.node];
    if (!node.box.overlaps(query)) continue;
    bool out = false;
    for (std::uint32_t untested = planes.all_bits() & ~e.held; untested != 0 && !out; untested &= untested - 1) {
      const int k = std::countr_zero(untested);
      const int side = side_of(e.node, planes.plane[k].h, planes.plane[k].origin_margin);
      out = side < 0;
      if (side > 0) e.held |= 1u << k;
    }
    if (out || prune(e.node, e.held)) continue;
    if (node.count > 0) {
      leaf(e.node, e.held);
    } else {
      stack[top++] = {node.first, e.held};
      stack[top++] = {e.node + 1, e.held};
    }
  }
}

void OccluderBvh::triangles_near_segment(const Vec3d& a, const Vec3d& b, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (brute_force_ || nodes_.empty()) {
    for (std::uint32_t i = 0; i < triangles_.size(); ++i) out.push_back(i);
    return;
  }
  const SegmentSlabs slabs(a, b - a, 0, 1);
  descend(
      nodes_, [&](std::uint32_t self) { return slabs.meets(nodes_[self].box); },
      [&](std::uint32_t self) {
        for (std::uint32_t i = nodes_[self].first; i < nodes_[self].first + nodes_[self].count; ++i) out.push_back(order_[i]);
        return false;
      });
}

}  // namespace vlit
