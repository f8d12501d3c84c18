#include "shadow/shadowed_light.h"

#include <cmath>

#include "shadow/area_visibility.h"
#include "shadow/linear_visibility.h"

namespace vlit {
namespace {

SpecularOptions effective_specular(const ShadeOptions& options) {
  SpecularOptions s = options.specular;
  if (!options.with_specular) s.method = SpecularMethod::kNone;
  return s;
}

Response<double> shade_linear_shadowed(const LinearLight<double>& light, const ShadingPoint<double>& sp,
                                       const ShadeOptions& options, const OccluderBvh& occluders) {
  const SpecularOptions spec = effective_specular(options);
  thread_local LinearShadowScratch scratch;
  if (visible_linear_intervals(light, sp.p, occluders, scratch) == LinearVisibility::kUnoccluded)
    return shade_linear(light, sp, spec, options.linear);
  Response<double> sum;
  double best_peak = -1;
  const Vec3d ld = light.q1 - light.q0;
  for (const auto& [ta, tb] : scratch.visible) {
    const double weight = tb - ta;
    if (!(weight > 0)) continue;
    const LinearLight<double> piece{ta == 0 ? light.q0 : light.q0 + ld * ta, tb == 1 ? light.q1 : light.q0 + ld * tb,
                                    light.falloff};
    const Response<double> r = shade_linear(piece, sp, spec, options.linear);
    sum.diffuse += weight * r.diffuse;
    switch (spec.method) {
      case SpecularMethod::kNone: break;
      case SpecularMethod::kExact: sum.specular += weight * r.specular; break;
      case SpecularMethod::kPeak:
        sum.specular = std::max(sum.specular, r.specular);
        break;
      case SpecularMethod::kNeighborhood: {
        // The neighbourhood of the piece holding the peak.
        SpecularOptions peak_only = spec;
        peak_only.method = SpecularMethod::kPeak;
        const double peak = shade_linear(piece, sp, peak_only, options.linear).specular;
        if (peak > best_peak) {
          best_peak = peak;
          sum.specular = r.specular;
        }
        break;
      }
    }
  }
  return sum;
}

// The light's visible pieces, each evaluated with the area kernels; `unoccluded()` when no
// occluder reaches between P and the light.
template <class Unoccluded>
Response<double> shade_area_shadowed(const PreparedAreaLight<double>& light, const ShadingPoint<double>& sp,
                                     const ShadeOptions& options, const OccluderBvh& occluders,
                                     const Unoccluded& unoccluded) {
  const SpecularOptions spec = effective_specular(options);
  const AreaView<double> view = make_area_view(light, sp.p);
  if (!view.lit) return {};
  ClipPolygon<double> horizon;
  clip_to_horizon(light, view, sp.n, horizon);
  if (horizon.count < 3) return {};
  thread_local AreaShadowScratch scratch;
  if (visible_area_pieces(light, view, horizon, sp.p, occluders, scratch) == AreaVisibility::kUnoccluded)
    return unoccluded();
  const LightPieces& pieces = scratch.pieces;
  Response<double> r;
  ClipPolygon<double> piece;
  auto load = [&](std::size_t i) {
    const int n = pieces.start[i + 1] - pieces.start[i];
    piece.count = n;
    std::copy(pieces.points.begin() + pieces.start[i], pieces.points.begin() + pieces.start[i + 1], piece.d.begin());
  };
  AreaPeak<double> best;
  best.angle = 4;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    load(i);
    r.diffuse += area_diffuse_contour(light, view, piece, sp.n);
    switch (spec.method) {
      case SpecularMethod::kNone: break;
      case SpecularMethod::kExact:
        r.specular += area_specular_exact(piece, view, sp.rv, sp.shininess, spec.exact_tolerance);
        break;
      case SpecularMethod::kPeak:
      case SpecularMethod::kNeighborhood: {
        const AreaPeak<double> peak = area_specular_peak_direction(piece, view, sp.rv);
        if (peak.visible && peak.angle < best.angle) best = peak;
        break;
      }
    }
  }
  if (best.visible && (spec.method == SpecularMethod::kPeak || spec.method == SpecularMethod::kNeighborhood)) {
    const double peak_value = phong_lobe_from_angle(best.angle, sp.shininess);
    r.specular = peak_value;
    const int samples = spec.neighborhood_samples;
    if (spec.method == SpecularMethod::kNeighborhood && samples > 0 && peak_value > 0) {
      // area_specular_neighborhood.h's ring, tested against every visible piece.
      const Vec3d& w = best.direction;
      const Vec3d helper = std::abs(w.x) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
      const Vec3d t1 = normalize(cross(w, helper));
      const Vec3d t2 = cross(w, t1);
      const double gamma = neighborhood_half_angle(sp.shininess);
      const double cg = std::cos(gamma), sg = std::sin(gamma);
      int visible = 0;
      for (int k = 0; k < samples; ++k) {
        const double phi = 2 * M_PI * (k + 0.5) / samples;
        const Vec3d dir = w * cg + (t1 * std::cos(phi) + t2 * std::sin(phi)) * sg;
        for (std::size_t i = 0; i < pieces.size(); ++i) {
          load(i);
          if (ray_hits_polygon(piece, view, dir)) {
            ++visible;
            break;
          }
        }
      }
      r.specular = peak_value * (1 + visible) / (samples + 1);
    }
  }
  return r;
}

// The regular 64-gon of the disk's area (vertex radius R sqrt(2 pi / (n sin(2 pi / n)))).
PreparedAreaLight<double> equal_area_polygon(const DiskLight<double>& disk) {
  constexpr int n = kMaxAreaVertices;
  const double radius = disk.radius * std::sqrt(2 * M_PI / (n * std::sin(2 * M_PI / n)));
  return disk_polygon(disk, n, radius);
}

// Reach of a directional light's shadow ray: past every occluder.
double directional_reach(const OccluderBvh& occluders, const Vec3d& p) {
  const Aabb& box = occluders.bounds();
  if (box.empty()) return 0;
  return 2 * (length(box.hi - box.lo) + length(p - box.center())) + 1;
}

}  // namespace

template <class K>
Response<double> shade_kernel_shadowed(const K& k, const ShadingPoint<double>& sp, const ShadeOptions& options,
                                       const OccluderBvh& occluders) {
  if constexpr (std::is_same_v<K, LinearLight<double>>) {
    return shade_linear_shadowed(k, sp, options, occluders);
  } else if constexpr (std::is_same_v<K, PreparedAreaLight<double>>) {
    return shade_area_shadowed(k, sp, options, occluders,
                               [&] { return shade_area(k, sp, effective_specular(options)); });
  } else if constexpr (std::is_same_v<K, DiskLight<double>>) {
    return shade_area_shadowed(equal_area_polygon(k), sp, options, occluders,
                               [&] { return shade_kernel<double>(k, sp, options); });
  } else {
    const Response<double> r = shade_kernel<double>(k, sp, options);
    if (r.diffuse == 0 && r.specular == 0) return r;
    Vec3d target;
    if constexpr (std::is_same_v<K, DirectionalLight<double>>) {
      target = sp.p - k.direction * directional_reach(occluders, sp.p);
    } else {
      target = k.position;  // point, spot
    }
    return occluders.segment_occluded(sp.p, target, sp.p) ? Response<double>{} : r;
  }
}

template Response<double> shade_kernel_shadowed(const PointLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&);
template Response<double> shade_kernel_shadowed(const DirectionalLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&);
template Response<double> shade_kernel_shadowed(const SpotLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&);
template Response<double> shade_kernel_shadowed(const LinearLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&);
template Response<double> shade_kernel_shadowed(const PreparedAreaLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&);
template Response<double> shade_kernel_shadowed(const DiskLight<double>&, const ShadingPoint<double>&,
                                                const ShadeOptions&, const OccluderBvh&);

Response<double> shade_shadowed(const PreparedLight<double>& light, const ShadingPoint<double>& sp,
                                const ShadeOptions& options, const OccluderBvh& occluders) {
  const double window = range_window(light, sp.p);
  if (window <= 0) return {};
  Response<double> r =
      std::visit([&](const auto& k) { return shade_kernel_shadowed(k, sp, options, occluders); }, light.kernel);
  r.diffuse *= window;
  r.specular *= window;
  return r;
}

}  // namespace vlit
