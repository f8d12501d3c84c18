#include "shadow/occluder_bvh.h"

#include <algorithm>
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

// Slab test of the segment a + t d, t in [t0, t1], against a box.
bool segment_meets_box(const Vec3d& a, const Vec3d& d, double t0, double t1, const Aabb& box) {
  for (int axis = 0; axis < 3; ++axis) {
    const double o = a[axis], v = d[axis];
    const double lo = box.lo[axis], hi = box.hi[axis];
    if (v == 0) {
      if (o < lo || o > hi) return false;
      continue;
    }
    double ta = (lo - o) / v, tb = (hi - o) / v;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

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

// The box lies wholly outside the half-space (its corner farthest along the normal is behind the
// plane by more than the rounding of the per-triangle test could explain).
bool box_outside(const Aabb& box, const HalfSpace& h) {
  const Vec3d far{h.normal.x >= 0 ? box.hi.x : box.lo.x, h.normal.y >= 0 ? box.hi.y : box.lo.y,
                  h.normal.z >= 0 ? box.hi.z : box.lo.z};
  const Vec3d w = far - h.origin;
  const double s = dot(h.normal, w);
  return s < -1e-9 * length(h.normal) * (length(w) + length(box.hi - box.lo));
}

}  // namespace

OccluderBvh::OccluderBvh(OccluderTriangles triangles, bool brute_force)
    : triangles_(std::move(triangles)), edges_(edges_of(triangles_)), brute_force_(brute_force) {
  const std::size_t n = triangles_.size();
  boxes_.resize(n);
  std::vector<Vec3d> centroids(n);
  for (std::size_t i = 0; i < n; ++i) {
    boxes_[i] = box_of(triangles_.corners[i]);
    bounds_.grow(boxes_[i]);
    centroids[i] = boxes_[i].center();
  }
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) order_[i] = static_cast<std::uint32_t>(i);
  if (!brute_force_ && n > 0) {
    nodes_.reserve(2 * (n / kLeafSize + 1));
    build(0, static_cast<std::uint32_t>(n), centroids, 0);
  }
}

std::uint32_t OccluderBvh::build(std::uint32_t begin, std::uint32_t end, std::vector<Vec3d>& centroids, int depth) {
  const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Aabb box, centroid_box;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.grow(boxes_[order_[i]]);
    centroid_box.grow(centroids[order_[i]]);
  }
  nodes_[index].box = padded(box);
  const Vec3d extent = centroid_box.hi - centroid_box.lo;
  if (end - begin <= kLeafSize || depth > 60 || (extent.x <= 0 && extent.y <= 0 && extent.z <= 0)) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
  build(begin, mid, centroids, depth + 1);
  const std::uint32_t right = build(mid, end, centroids, depth + 1);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
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
  const Vec3d d = b - a;
  std::uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!segment_meets_box(a, d, t_min, t_max, node.box)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        if (test(order_[i])) return true;
    } else {
      const std::uint32_t self = static_cast<std::uint32_t>(&node - nodes_.data());
      stack[top++] = node.first;
      stack[top++] = self + 1;
    }
  }
  return false;
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
  const Aabb query = padded(volume.box);
  std::uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t self = stack[--top];
    const Node& node = nodes_[self];
    if (!node.box.overlaps(query)) continue;
    bool outside = false;
    for (const HalfSpace& h : volume.planes)
      if ((outside = box_outside(node.box, h))) break;
    if (outside) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        if (test(order_[i])) out.push_back(order_[i]);
    } else {
      stack[top++] = node.first;
      stack[top++] = self + 1;
    }
  }
  std::sort(out.begin(), out.end());
}

}  // namespace vlit
