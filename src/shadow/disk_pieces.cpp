#include "shadow/disk_pieces.h"

#include <cmath>
#include <vector>

#include "area_light.h"
#include "disk_diffuse_contour.h"

namespace vlit {
namespace {

constexpr double kTwoPi = 2 * M_PI;
// Arcs and segments shorter than this (radians, or fraction of the radius) are dropped.
constexpr double kTiny = 1e-14;
// Piece edges shorter than this fraction of the radius are skipped (see disk_piece_diffuse).
constexpr double kShortEdge = 1e-7;
// A line within this fraction of the radius of touching the rim from outside keeps the whole rim:
// the cap it would cut is below 1e-18 of the disk.
constexpr double kTangent = 1e-12;
// Consecutive elements whose ends are farther apart than this (fraction of the radius) leave a
// gap that a clip made: it is closed along the clipping line.
constexpr double kGap = 1e-12;

struct Point2 {
  double x, y;
};

// One element of the boundary of the kept region, counter-clockwise.
struct Element {
  bool arc;
  double a0, a1;  // arc: from angle a0 to a1 > a0
  Point2 p0, p1;  // segment: from p0 to p1 (arcs: their end points, for the closing segments)
};

Point2 on_rim(double radius, double angle) { return {radius * std::cos(angle), radius * std::sin(angle)}; }

Element make_arc(double radius, double a0, double a1) {
  return {true, a0, a1, on_rim(radius, a0), on_rim(radius, a1)};
}

// Keeps the part of `boundary` with nx x + ny y >= c (n a unit vector), closing the cut along the line.
void clip(const std::vector<Element>& boundary, double radius, double nx, double ny, double c, std::vector<Element>& out) {
  out.clear();
  auto side = [&](const Point2& p) { return nx * p.x + ny * p.y - c; };
  for (const Element& e : boundary) {
    if (!e.arc) {
      const double s0 = side(e.p0), s1 = side(e.p1);
      if (s0 < 0 && s1 < 0) continue;
      Element kept = e;
      if (s0 < 0 || s1 < 0) {
        const double t = s0 / (s0 - s1);
        const Point2 x{e.p0.x + (e.p1.x - e.p0.x) * t, e.p0.y + (e.p1.y - e.p0.y) * t};
        (s0 < 0 ? kept.p0 : kept.p1) = x;
      }
      if (std::hypot(kept.p1.x - kept.p0.x, kept.p1.y - kept.p0.y) > kTiny * radius) out.push_back(kept);
      continue;
    }
    // The rim inside the half-plane: angles within omega of the normal's angle phi.
    if (c <= -radius * (1 - kTangent)) {  // the whole rim (a circumscribed polygon's edges touch it)
      out.push_back(e);
      continue;
    }
    if (c >= radius) continue;
    const double omega = std::acos(c / radius), phi = std::atan2(ny, nx);
    double lo = phi - omega;
    lo -= kTwoPi * std::ceil((lo - (e.a0 - kTwoPi)) / kTwoPi);  // now lo <= a0 - 2 pi < lo + 2 pi
    for (int k = 0; k < 3; ++k) {
      const double b0 = std::max(e.a0, lo + kTwoPi * k), b1 = std::min(e.a1, lo + 2 * omega + kTwoPi * k);
      if (!(b1 - b0 > kTiny)) continue;
      out.push_back(make_arc(radius, b0, b1));
    }
  }
  // Close each cut: where an element ends away from the start of the next, both ends lie on the
  // line, and the boundary follows it (consecutive elements of the boundary otherwise share their
  // end points up to rounding).
  std::vector<Element> closed;
  closed.reserve(out.size() + 2);
  for (std::size_t i = 0; i < out.size(); ++i) {
    closed.push_back(out[i]);
    const Point2& from = out[i].p1;
    const Point2& to = out[(i + 1) % out.size()].p0;
    if (std::hypot(to.x - from.x, to.y - from.y) > kGap * radius) closed.push_back({false, 0, 0, from, to});
  }
  out.swap(closed);
}

// The 2D corners of a piece, counter-clockwise in (u, v).
int corners_ccw(const ClipPolygon<double>& piece, const AreaView<double>& view, Point2* out) {
  const int n = piece.count;
  double twice_area = 0;
  for (int i = 0; i < n; ++i) out[i] = {dot(view.u, piece.d[i]), dot(view.v, piece.d[i])};
  for (int i = 0; i < n; ++i) {
    const Point2& a = out[i];
    const Point2& b = out[(i + 1) % n];
    twice_area += a.x * b.y - b.x * a.y;
  }
  if (twice_area < 0) std::reverse(out, out + n);
  return n;
}

// Lambert's edge term of the straight edge a -> b (2D, relative to the centre), as in eq. 9.
double edge_term(const AreaView<double>& view, const Vec3d& n, const Point2& a, const Point2& b) {
  const Vec3d ra = view.D + view.u * a.x + view.v * a.y, rb = view.D + view.u * b.x + view.v * b.y;
  const Vec3d cr = cross(ra, rb);
  const double len = length(cr);
  return len > 0 ? std::atan2(len, dot(ra, rb)) / len * dot(n, cr) : 0.0;
}

// piece ∩ disk as the counter-clockwise boundary of its rim arcs and straight segments, from its
// counter-clockwise corners.
void piece_in_disk(double radius, const Point2* corner, int count, std::vector<Element>& boundary) {
  thread_local std::vector<Element> next;
  boundary.assign(1, make_arc(radius, 0, kTwoPi));
  for (int i = 0; i < count && !boundary.empty(); ++i) {
    const Point2& a = corner[i];
    const Point2& b = corner[(i + 1) % count];
    const double ex = b.x - a.x, ey = b.y - a.y, len = std::hypot(ex, ey);
    // A very short edge (a trapezoid's degenerate side, a clip that grazed a corner) has no
    // reliable direction: its line could cut the disk anywhere. Its neighbours bound the piece
    // there up to a sliver of its length squared.
    if (!(len > kShortEdge * radius)) continue;
    const double nx = -ey / len, ny = ex / len;  // inward for a counter-clockwise piece
    clip(boundary, radius, nx, ny, nx * a.x + ny * a.y, next);
    boundary.swap(next);
  }
}

bool corners_in_disk(const Point2* corner, int count, double radius) {
  for (int i = 0; i < count; ++i)
    if (!(std::hypot(corner[i].x, corner[i].y) <= radius)) return false;
  return true;
}

}  // namespace

DiskPieceLobe disk_piece_lobe(const AreaView<double>& view, double radius, const Vec3d& n, const Vec3d& rv, double m,
                              double tolerance) {
  DiskPieceLobe lobe;
  lobe.rv = normalize(rv);
  lobe.m = m;
  lobe.tolerance = tolerance;
  // The lobe's half-space Rv.(x - P) >= 0, also for m = 0 (its limit m -> 0+), as a line in the
  // disk's plane: (Rv.u) x + (Rv.v) y >= -Rv.D.
  const double lx = dot(lobe.rv, view.u), ly = dot(lobe.rv, view.v), lc = -dot(lobe.rv, view.D), ll = std::hypot(lx, ly);
  lobe.clips = ll > 0;
  if (lobe.clips) {
    lobe.nx = lx / ll;
    lobe.ny = ly / ll;
    lobe.c = lc / ll;
  }
  lobe.misses = !lobe.clips && lc > 0;
  // Rv outside the visible part: integrate only the tail c^{m+1} (area_specular_exact.h). Decided
  // on the whole disk, as disk_specular_exact does: the full form holds wherever Rv is.
  lobe.lobe_width = 1 / std::sqrt(m + 1);
  lobe.tail = m > 0 && !disk_exact_detail::rv_near_disk(view, radius, n, lobe.rv, lobe.lobe_width);
  lobe.cuts = disk_exact_detail::rim_cuts(view, radius, lobe.rv, m, lobe.lobe_width);
  return lobe;
}

namespace {

// The exact specular of the region inside `boundary` (piece ∩ disk).
double boundary_specular(const AreaView<double>& view, double radius, const DiskPieceLobe& lobe,
                         std::vector<Element>& boundary) {
  using namespace disk_exact_detail;
  if (lobe.misses) return 0;
  if (lobe.clips) {
    thread_local std::vector<Element> lobe_side;
    clip(boundary, radius, lobe.nx, lobe.ny, lobe.c, lobe_side);
    boundary.swap(lobe_side);
  }
  if (boundary.empty()) return 0;
  const Vec3d& rv = lobe.rv;
  const double m = lobe.m;
  thread_local std::vector<DiskCurve<double>> curves;
  curves.clear();
  const auto integrand = [&](int c, double t) {
    return disk_curve_integrand(view, radius, rv, m, lobe.tail, curves[c], t);
  };
  AdaptiveKronrod<double, kDiskExactMaxPieces> quad;
  for (const Element& e : boundary) {
    const int c = int(curves.size());
    const auto along = [&integrand, c](double t) { return integrand(c, t); };
    if (e.arc) {
      curves.push_back({0, {}, {}});
      add_rim_arc(along, c, e.a0, e.a1, lobe.cuts, m, quad);
    } else {
      const Vec3d a = view.D + view.u * e.p0.x + view.v * e.p0.y;
      const Vec3d along_edge = view.u * (e.p1.x - e.p0.x) + view.v * (e.p1.y - e.p0.y);
      if (!(length_squared(along_edge) > 0)) continue;
      curves.push_back({1, a, along_edge});
      add_straight(along, c, a, along_edge, 0.0, 1.0, rv, m, lobe.lobe_width, quad);
    }
  }
  const double value = quad.refine(integrand, [](int) { return 1.0; }, lobe.tolerance);
  return std::max(lobe.tail ? value / (m + 1) : -value / (m + 1), 0.0);
}

}  // namespace

DiskPieceLight disk_piece_light(const AreaView<double>& view, const DiskFrame<double>& frame, const Vec3d& n,
                                const DiskPieceLobe* lobe, const ClipPolygon<double>& piece) {
  DiskPieceLight r;
  if (!view.lit || piece.count < 3) return r;
  const double radius = frame.big_r;
  std::array<Point2, kMaxClipVertices> corner;
  const int count = corners_ccw(piece, view, corner.data());
  double sum = 0;
  if (corners_in_disk(corner.data(), count, radius)) {  // the piece lies in the disk: its own edges
    for (int i = 0; i < count; ++i) sum += edge_term(view, n, corner[i], corner[(i + 1) % count]);
    r.diffuse = std::max(0.0, -0.5 * sum);
    // A polygon light of its own (its corners lie above P's horizon).
    if (lobe) r.specular = area_specular_exact_dispatch(piece, view, lobe->rv, lobe->m, lobe->tolerance);
    return r;
  }
  thread_local std::vector<Element> boundary;
  piece_in_disk(radius, corner.data(), count, boundary);
  for (const Element& e : boundary)
    sum += e.arc ? disk_arc_contour(view, frame, e.a0, e.a1, 0.5 * (e.a1 - e.a0)) : edge_term(view, n, e.p0, e.p1);
  r.diffuse = std::max(0.0, -0.5 * sum);
  if (lobe) r.specular = boundary_specular(view, radius, *lobe, boundary);
  return r;
}

void clip_piece_to_polygon(const ClipPolygon<double>& piece, const PreparedAreaLight<double>& polygon,
                           const AreaView<double>& view, ClipPolygon<double>& out) {
  // The polygon's edges as half-spaces through the centre's plane: dot(k, x) + offset >= 0 keeps
  // the inner side (x relative to the centre). The polygon is convex and wound the same way as
  // its normal; the side holding the centre is inside.
  ClipPolygon<double> a = piece, b;
  for (int i = 0; i < polygon.count && a.count > 0; ++i) {
    const Vec3d& p = polygon.d[i];
    const Vec3d& q = polygon.d[(i + 1) % polygon.count];
    Vec3d k = cross(view.normal, q - p);
    double offset = -dot(k, p);
    if (offset < 0) k = -k, offset = -offset;  // the centre (x = 0) is inside
    clip_halfspace(a.d.data(), a.count, k, offset, b);
    a = b;
  }
  out = a;
}

}  // namespace vlit
