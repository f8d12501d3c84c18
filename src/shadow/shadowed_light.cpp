#include "shadow/shadowed_light.h"

#include <cmath>
#include <optional>

#include "shadow/area_silhouette.h"
#include "shadow/area_visibility.h"
#include "shadow/crease_wedges.h"
#include "shadow/disk_pieces.h"
#include "shadow/linear_silhouette.h"
#include "shadow/linear_visibility.h"

namespace vlit {
namespace {

// The silhouette method's per-thread tables (per triangle and edge of the scene: one per thread).
AreaSilhouetteScratch& silhouette_scratch() {
  thread_local AreaSilhouetteScratch scratch;
  return scratch;
}

SpecularOptions effective_specular(const ShadeOptions& options) {
  SpecularOptions s = options.specular;
  if (!options.with_specular) s.method = SpecularMethod::kNone;
  return s;
}

// silhouette_pieces_for with the specular method already made effective.
SilhouettePieces silhouette_pieces(SpecularMethod method, bool disk, bool wedged) {
  return method == SpecularMethod::kNone && !disk && !wedged ? SilhouettePieces::kChains : SilhouettePieces::kTrapezoids;
}

// The linear neighbourhood specular (linear_specular_neighborhood.h) of a partly hidden light:
// the same K samples as for the whole light (window around its peak), each lobe value counted
// only if its point of the segment is visible. Never more than the unshadowed value, equal to it
// when the window is unhidden.
double linear_neighborhood_shadowed(const LinearLight<double>& light, const ShadingPoint<double>& sp, int k_samples,
                                    const std::vector<std::pair<double, double>>& visible) {
  return linear_specular_neighborhood_frame(make_linear_frame(light, sp), sp.shininess, k_samples, [&](double t) {
    for (const auto& [a, b] : visible)
      if (t >= a && t <= b) return true;
    return false;
  });
}

// Removes from `visible` (sorted, disjoint [t_a, t_b] intervals) the parameters t whose point
// Q(t) lies above P's horizon in one of the wedges seen from P; true if something was removed.
bool remove_wedges(const LinearLight<double>& light, const ShadingPoint<double>& sp, std::span<const WedgeCone> wedges,
                   std::vector<std::pair<double, double>>& visible) {
  const Vec3d l0 = light.q0 - sp.p, ld = light.q1 - light.q0;
  bool removed = false;
  thread_local std::vector<std::pair<double, double>> kept;
  for (const WedgeCone& wedge : wedges) {
    // dot(k, L0 + t Ld) > 0 for the wedge's planes and the horizon's: one interval of t per
    // plane, intersected.
    double lo = 0, hi = 1;
    for (const Vec3d& k : {wedge.inward[0], wedge.inward[1], wedge.inward[2], wedge.inward[3], sp.n}) {
      const double c0 = dot(k, l0), c1 = dot(k, ld);
      if (c1 == 0) {
        if (c0 < 0) hi = -1;
      } else if (c1 > 0) {
        lo = std::max(lo, -c0 / c1);
      } else {
        hi = std::min(hi, -c0 / c1);
      }
    }
    if (!(hi > lo)) continue;
    kept.clear();
    for (const auto& [a, b] : visible) {
      if (b <= lo || a >= hi) {
        kept.emplace_back(a, b);
        continue;
      }
      removed = true;
      if (a < lo) kept.emplace_back(a, lo);
      if (b > hi) kept.emplace_back(hi, b);
    }
    visible.swap(kept);
  }
  return removed;
}

Response<double> shade_linear_shadowed(const LinearLight<double>& light, const ShadingPoint<double>& sp,
                                       const ShadeOptions& options, const OccluderBvh& occluders,
                                       std::span<const WedgeCone> wedges) {
  const SpecularOptions spec = effective_specular(options);
  // Every linear kernel integrates over the part of the light above P's horizon (their frame's
  // clipping): where none of it is, there is no visibility to find.
  if (make_linear_frame(light, sp).empty) return shade_linear(light, sp, spec, options.linear);
  thread_local LinearShadowScratch scratch;
  thread_local LinearSilhouetteScratch silhouette;
  std::vector<std::pair<double, double>>* found = nullptr;  // the visible intervals
  bool unoccluded = false;
  if (options.linear_shadows == LinearShadowMethod::kSilhouette) {
    switch (visible_linear_by_silhouettes(light, sp.p, occluders, silhouette)) {
      case LinearSilhouetteVisibility::kUnoccluded: unoccluded = true, found = &silhouette.visible; break;
      case LinearSilhouetteVisibility::kIntervals: found = &silhouette.visible; break;
      case LinearSilhouetteVisibility::kUndecided: break;
    }
  }
  if (!found) {
    unoccluded = visible_linear_intervals(light, sp.p, occluders, scratch) == LinearVisibility::kUnoccluded;
    found = &scratch.visible;
  }
  std::vector<std::pair<double, double>>& visible = *found;
  if (unoccluded) visible.assign(1, {0.0, 1.0});
  const bool wedged = !wedges.empty() && remove_wedges(light, sp, wedges, visible);
  if (unoccluded && !wedged) return shade_linear(light, sp, spec, options.linear);
  Response<double> sum;
  const Vec3d ld = light.q1 - light.q0;
  SpecularOptions piece_spec = spec;
  if (spec.method == SpecularMethod::kNeighborhood) piece_spec.method = SpecularMethod::kNone;
  for (const auto& [ta, tb] : visible) {
    const double weight = tb - ta;
    if (!(weight > 0)) continue;
    const LinearLight<double> piece{ta == 0 ? light.q0 : light.q0 + ld * ta, tb == 1 ? light.q1 : light.q0 + ld * tb,
                                    light.falloff};
    const Response<double> r = shade_linear(piece, sp, piece_spec, options.linear);
    sum.diffuse += weight * r.diffuse;  // intensity is per unit t: the piece spans weight of it
    if (spec.method == SpecularMethod::kExact) sum.specular += weight * r.specular;
    if (spec.method == SpecularMethod::kPeak) sum.specular = std::max(sum.specular, r.specular);  // a maximum
  }
  if (spec.method == SpecularMethod::kNeighborhood && !visible.empty())
    sum.specular = linear_neighborhood_shadowed(light, sp, spec.neighborhood_samples, visible);
  return sum;
}

// The light's visible pieces, each evaluated with the area kernels; `unoccluded()` when no
// occluder reaches between P and the light.
// For a disk (`disk` not null), `light` is its circumscribed polygon: each visible piece is
// intersected with the disk for the diffuse and the exact specular (disk_pieces.h), and with the
// disk's equal-area polygon for the peak and neighbourhood specular.
template <class Unoccluded>
Response<double> shade_area_shadowed(const PreparedAreaLight<double>& light, const ShadingPoint<double>& sp,
                                     const ShadeOptions& options, const OccluderBvh& occluders,
                                     const SilhouetteCluster* cluster, std::span<const WedgeCone> wedges,
                                     const SharedVisibility* seen, const Unoccluded& unoccluded,
                                     const PreparedDiskLight<double>* disk = nullptr) {
  const SpecularOptions spec = effective_specular(options);
  const AreaView<double> view = make_area_view(light, sp.p);
  if (!view.lit) return {};
  ClipPolygon<double> horizon;
  clip_to_horizon(light, view, sp.n, horizon);
  if (horizon.count < 3) return {};
  thread_local AreaShadowScratch scratch;
  AreaSilhouetteScratch& silhouette = silhouette_scratch();
  const LightPieces* visible = nullptr;
  bool nothing_reaches = false;  // no occluder reaches between P and the light
  using Shared = SharedVisibility::State;
  if (options.area_shadows == AreaShadowMethod::kSilhouette && seen && seen->state != Shared::kUndecided) {
    if (seen->state == Shared::kUnoccluded) nothing_reaches = true;
    else visible = &seen->pieces;
  } else if (options.area_shadows == AreaShadowMethod::kSilhouette) {
    switch (visible_area_by_silhouettes(light, view, horizon, sp.p, occluders, silhouette, cluster,
                                        silhouette_pieces(spec.method, disk != nullptr, !wedges.empty()))) {
      case SilhouetteVisibility::kUnoccluded: nothing_reaches = true; break;
      case SilhouetteVisibility::kPieces: visible = &silhouette.pieces; break;
      case SilhouetteVisibility::kUndecided: break;
    }
  }
  if (!visible && !nothing_reaches) {
    if (visible_area_pieces(light, view, horizon, sp.p, occluders, scratch) == AreaVisibility::kUnoccluded)
      nothing_reaches = true;
    else
      visible = &scratch.pieces;
  }
  if (!wedges.empty()) {
    // The wedges of triangles across a crease (crease_wedges.h): cones from P, subtracted as the
    // occluders' cones are.
    thread_local LightPieces whole, cut[2];
    if (nothing_reaches) {
      whole.clear();
      whole.add(horizon.d.data(), horizon.count, view.u, view.v);
    }
    const LightPieces* from = nothing_reaches ? &whole : visible;
    const Rect2 anywhere{-1e300, 1e300, -1e300, 1e300};
    int next = 0;
    for (const WedgeCone& wedge : wedges) {
      if (subtract_cone(*from, wedge.inward.data(), 4, anywhere, view, piece_area_floor(light), cut[next])) {
        from = &cut[next];
        next = 1 - next;
      }
    }
    if (from != &whole) {
      visible = from;
      nothing_reaches = false;
    }
  }
  if (nothing_reaches) return unoccluded();
  const LightPieces& pieces = *visible;
  Response<double> r;
  ClipPolygon<double> piece;
  auto load = [&](const LightPieces& from, std::size_t i) -> const ClipPolygon<double>& {
    piece.count = from.start[i + 1] - from.start[i];
    std::copy(from.points.begin() + from.start[i], from.points.begin() + from.start[i + 1], piece.d.begin());
    return piece;
  };
  // The pieces the peak and neighbourhood methods read: a disk's, clipped once to its equal-area
  // polygon.
  const LightPieces* lobe_pieces = &pieces;
  if (disk && (spec.method == SpecularMethod::kPeak || spec.method == SpecularMethod::kNeighborhood)) {
    thread_local LightPieces clipped;
    clipped.clear();
    ClipPolygon<double> inside;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      clip_piece_to_polygon(load(pieces, i), disk->equal_area, view, inside);
      if (inside.count >= 3) clipped.add(inside.d.data(), inside.count, view.u, view.v);
    }
    lobe_pieces = &clipped;
  }
  AreaPeak<double> best;
  best.angle = 4;
  if (disk) {
    // The diffuse and the exact specular of each piece ∩ disk from one boundary.
    const DiskFrame<double> frame = disk_frame(view, disk->radius, sp.n);
    std::optional<DiskPieceLobe> lobe;
    if (spec.method == SpecularMethod::kExact)
      lobe = disk_piece_lobe(view, disk->radius, sp.n, sp.rv, sp.shininess, spec.exact_tolerance);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const DiskPieceLight l = disk_piece_light(view, frame, sp.n, lobe ? &*lobe : nullptr, load(pieces, i));
      r.diffuse += l.diffuse;
      r.specular += l.specular;
    }
  } else {
    for (std::size_t i = 0; i < pieces.size(); ++i) r.diffuse += area_diffuse_contour(light, view, load(pieces, i), sp.n);
  }
  if ((spec.method == SpecularMethod::kExact && !disk) || spec.method == SpecularMethod::kPeak)
    for (std::size_t i = 0; i < lobe_pieces->size(); ++i) {
      const ClipPolygon<double>& lobe_piece = load(*lobe_pieces, i);
      if (spec.method == SpecularMethod::kExact) {
        r.specular += area_specular_exact_dispatch(lobe_piece, view, sp.rv, sp.shininess, spec.exact_tolerance);
      } else {
        const AreaPeak<double> peak = area_specular_peak_direction(lobe_piece, view, sp.rv);
        if (peak.visible && peak.angle < best.angle) best = peak;
      }
    }
  if (best.visible && spec.method == SpecularMethod::kPeak) r.specular = phong_lobe_from_angle(best.angle, sp.shininess);
  if (spec.method == SpecularMethod::kNeighborhood && pieces.size() > 0) {
    // area_specular_neighborhood.h's rule on the whole light (its peak direction and ring), each
    // of the K + 1 directions counted only if it reaches a visible piece: never more than the
    // unshadowed value, equal to it when the peak and its ring are unhidden.
    ClipPolygon<double> lobe_horizon;  // a disk: its equal-area polygon's horizon clip
    if (disk) clip_to_horizon(disk->equal_area, view, sp.n, lobe_horizon);
    auto reaches_visible = [&](const Vec3d& dir) {
      for (std::size_t i = 0; i < lobe_pieces->size(); ++i)
        if (ray_hits_polygon(load(*lobe_pieces, i), view, dir)) return true;
      return false;
    };
    r.specular = area_specular_neighborhood_seen(disk ? lobe_horizon : horizon, view, sp.rv, sp.shininess,
                                                 spec.neighborhood_samples, reaches_visible, reaches_visible);
  }
  return r;
}

// Reach of a directional light's shadow ray: past every occluder.
double directional_reach(const OccluderBvh& occluders, const Vec3d& p) {
  const Aabb& box = occluders.bounds();
  if (box.empty()) return 0;
  return 2 * (length(box.hi - box.lo) + length(p - box.center())) + 1;
}

}  // namespace

SilhouettePieces silhouette_pieces_for(const ShadeOptions& options, bool disk, bool wedged) {
  return silhouette_pieces(effective_specular(options).method, disk, wedged);
}

void see_light_above_horizon(const PreparedAreaLight<double>& polygon, const ShadingPoint<double>& sp,
                             const OccluderBvh& occluders, const SilhouetteCluster* cluster, SilhouettePieces cut,
                             SharedVisibility& out) {
  using State = SharedVisibility::State;
  out.state = State::kUnlit;
  out.pieces.clear();
  const AreaView<double> view = make_area_view(polygon, sp.p);
  if (!view.lit) return;
  ClipPolygon<double> horizon;
  clip_to_horizon(polygon, view, sp.n, horizon);
  if (horizon.count < 3) return;
  AreaSilhouetteScratch& silhouette = silhouette_scratch();
  switch (visible_area_by_silhouettes(polygon, view, horizon, sp.p, occluders, silhouette, cluster, cut)) {
    case SilhouetteVisibility::kUnoccluded: out.state = State::kUnoccluded; break;
    case SilhouetteVisibility::kPieces:
      out.state = State::kPieces;
      out.pieces = silhouette.pieces;
      break;
    case SilhouetteVisibility::kUndecided: out.state = State::kUndecided; break;
  }
}

template <class K>
Response<double> shade_kernel_shadowed(const K& k, const ShadingPoint<double>& sp, const ShadeOptions& options,
                                       const OccluderBvh& occluders, const SilhouetteCluster* cluster,
                                       std::span<const WedgeCone> wedges, const SharedVisibility* seen) {
  if constexpr (std::is_same_v<K, LinearLight<double>>) {
    return shade_linear_shadowed(k, sp, options, occluders, wedges);
  } else if constexpr (std::is_same_v<K, PreparedAreaLight<double>>) {
    return shade_area_shadowed(k, sp, options, occluders, cluster, wedges, seen,
                               [&] { return shade_area(k, sp, effective_specular(options)); });
  } else if constexpr (std::is_same_v<K, PreparedDiskLight<double>>) {
    return shade_area_shadowed(shadowed_polygon(k), sp, options, occluders, cluster, wedges, seen,
                               [&] { return shade_kernel<double>(k, sp, options); }, &k);
  } else {
    const Response<double> r = shade_kernel<double>(k, sp, options);
    if (r.diffuse == 0 && r.specular == 0) return r;
    Vec3d target;
    if constexpr (std::is_same_v<K, DirectionalLight<double>>) {
      target = sp.p - k.direction * directional_reach(occluders, sp.p);
    } else {
      target = k.position;  // point, spot
    }
    for (const WedgeCone& wedge : wedges)
      if (wedge.contains(target - sp.p)) return {};
    return occluders.segment_occluded(sp.p, target, sp.p) ? Response<double>{} : r;
  }
}

template Response<double> shade_kernel_shadowed(const PointLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&,
                                                const SilhouetteCluster*, std::span<const WedgeCone>,
                                                const SharedVisibility*);
template Response<double> shade_kernel_shadowed(const DirectionalLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&,
                                                const SilhouetteCluster*, std::span<const WedgeCone>,
                                                const SharedVisibility*);
template Response<double> shade_kernel_shadowed(const SpotLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&,
                                                const SilhouetteCluster*, std::span<const WedgeCone>,
                                                const SharedVisibility*);
template Response<double> shade_kernel_shadowed(const LinearLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&,
                                                const SilhouetteCluster*, std::span<const WedgeCone>,
                                                const SharedVisibility*);
template Response<double> shade_kernel_shadowed(const PreparedAreaLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&,
                                                const SilhouetteCluster*, std::span<const WedgeCone>,
                                                const SharedVisibility*);
template Response<double> shade_kernel_shadowed(const PreparedDiskLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&,
                                                const SilhouetteCluster*, std::span<const WedgeCone>,
                                                const SharedVisibility*);

Response<double> shade_shadowed(const PreparedLight<double>& light, const ShadingPoint<double>& sp,
                                const ShadeOptions& options, const OccluderBvh& occluders,
                                std::span<const WedgeCone> wedges) {
  const double window = range_window(light, sp.p);
  if (window <= 0) return {};
  Response<double> r = std::visit(
      [&](const auto& k) { return shade_kernel_shadowed(k, sp, options, occluders, nullptr, wedges); }, light.kernel);
  r.diffuse *= window;
  r.specular *= window;
  return r;
}

}  // namespace vlit
