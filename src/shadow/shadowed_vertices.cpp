#include "shadow/shadowed_vertices.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <vector>

#include "shadow/shadowed_light.h"
#include "shadow/silhouette_cluster.h"

namespace vlit {
namespace {

constexpr long kBlock = 8;         // vertices per group without clusters
// The widest cluster the bake forms: the diagonal of its box, relative to the light's diameter.
// 0.1 and 0.2 were the fastest of 0.025-0.5 in a sweep on the bowling lane and DamagedHelmet
// (the sweep's switch was not kept); docs/shadows.md ("Stop 45" in "Benchmarks") has the
// chosen value against the fixed runs of 32 on the lane, DamagedHelmet and MetalRoughSpheres.
constexpr double kClusterSpan = 0.2;

// Interleaves the low 21 bits of x, y and z (a Morton code).
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

// The vertices in Morton order of their positions within the chunk's box: consecutive ones are
// close in space, so a run of them makes a compact cluster.
std::vector<std::uint32_t> morton_order(const ShadingPoint<double>* points, long count) {
  Aabb box;
  for (long v = 0; v < count; ++v) box.grow(points[v].p);
  const Vec3d extent = box.hi - box.lo;
  const double size = std::max({extent.x, extent.y, extent.z});
  const double scale = size > 0 ? ((1 << 21) - 1) / size : 0;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(count);
  for (long v = 0; v < count; ++v) {
    const Vec3d q = (points[v].p - box.lo) * scale;
    keyed[v] = {spread_bits(static_cast<std::uint64_t>(q.x)) | spread_bits(static_cast<std::uint64_t>(q.y)) << 1 |
                    spread_bits(static_cast<std::uint64_t>(q.z)) << 2,
                static_cast<std::uint32_t>(v)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(count);
  for (long v = 0; v < count; ++v) order[v] = keyed[v].second;
  return order;
}

// The clusters of one light, as the first vertex (into `order`) of each, then `count`: runs of
// consecutive vertices in Morton order, each of at most `size` vertices and with a box whose
// diagonal stays within `span`. Morton order jumps where it passes from one cell of its grid to
// the next, so a run of fixed length may hold two patches of the surface far apart. Its box,
// and the band of occluder triangles whose facing varies over the box (silhouette_cluster.h),
// are then much wider than each of its vertices needs: each vertex reads that band's edges,
// most of which weigh nothing from it.
std::vector<long> cluster_starts(const ShadingPoint<double>* points, const std::vector<std::uint32_t>& order, long count,
                                 int size, double span) {
  std::vector<long> starts;
  Aabb box;
  int members = 0;
  for (long i = 0; i < count; ++i) {
    const Vec3d& p = points[order[i]].p;
    Aabb grown = box;
    grown.grow(p);
    if (members == 0 || members == size || length(grown.hi - grown.lo) > span) {
      starts.push_back(i);
      box = Aabb{};
      members = 0;
    }
    box.grow(p);
    ++members;
  }
  starts.push_back(count);
  return starts;
}

template <class K>
void shade_vertex(const PreparedLight<double>& light, const K& kernel, const ShadeOptions& options,
                  const ShadingPoint<double>& sp, Vec3d& diffuse, Vec3d* specular, const OccluderBvh& occluders,
                  const SilhouetteCluster* cluster, std::span<const WedgeCone> wedges,
                  const SharedVisibility* seen = nullptr) {
  const double window = range_window(light, sp.p);
  if (window <= 0) return;
  const Response<double> r = shade_kernel_shadowed(kernel, sp, options, occluders, cluster, wedges, seen);
  diffuse += light.radiance * (r.diffuse * window);
  if (specular) *specular += light.radiance * (r.specular * window);
}

}  // namespace

void accumulate_light_shadowed(const PreparedLight<double>& light, const ShadeOptions& options,
                               const ShadingPoint<double>* points, long count, Vec3d* diffuse, Vec3d* specular,
                               const OccluderBvh& occluders, const std::atomic<bool>* cancel,
                               const CreaseWedges* wedges, std::size_t first_vertex) {
  auto cancelled = [&] { return cancel && cancel->load(std::memory_order_relaxed); };
  auto wedges_of = [&](long v) { return wedges ? wedges->of(first_vertex + v) : std::span<const WedgeCone>{}; };
  std::visit(
      [&](const auto& kernel) {
        using K = std::decay_t<decltype(kernel)>;
        constexpr bool kArea = std::is_same_v<K, PreparedAreaLight<double>> || std::is_same_v<K, PreparedDiskLight<double>>;
        if constexpr (kArea) {
          if (options.area_shadows == AreaShadowMethod::kSilhouette && options.shadow_clusters && !occluders.brute_force()) {
          const std::vector<std::uint32_t> order = morton_order(points, count);
          const PreparedAreaLight<double> polygon = shadowed_polygon(kernel);
          const std::vector<long> starts = cluster_starts(points, order, count, std::max(1, options.shadow_cluster_size),
                                                          kClusterSpan * 2 * polygon.radius);
          const long clusters = static_cast<long>(starts.size()) - 1;
#pragma omp parallel for schedule(dynamic, 1)
          for (long c = 0; c < clusters; ++c) {
            if (cancelled()) continue;
            const long begin = starts[c];
            const int n = static_cast<int>(starts[c + 1] - begin);
            thread_local SilhouetteCluster cluster;
            thread_local SharedVisibility seen;
            thread_local std::vector<int> keeps, asks;  // per vertex of a position: horizon_keeps; its class, or -1
            prepare_silhouette_cluster(polygon, points, order.data() + begin, n, occluders, cluster);
            // Vertices at one position (split at a seam of normals or texture coordinates;
            // adjacent in Morton order) whose horizons clip the polygon alike ask the BVH once
            // (see_light_above_horizon): those whose horizon leaves the whole polygon, and those
            // with the same normal. Within the cluster only, so that a vertex's answer never
            // depends on which thread took the cluster.
            auto sp_at = [&](int i) -> const ShadingPoint<double>& { return points[order[begin + i]]; };
            auto horizon_keeps = [&](int i) {  // 0: no corner of the polygon, 1: some, 2: all (as clip_to_horizon)
              const ShadingPoint<double>& sp = sp_at(i);
              const double offset = dot(sp.n, polygon.center - sp.p);
              int kept = 0;
              for (int k = 0; k < polygon.count; ++k) kept += dot(sp.n, polygon.d[k]) + offset >= 0;
              return kept == 0 ? 0 : kept == polygon.count ? 2 : 1;
            };
            auto same_normal = [&](int i, int j) { return std::memcmp(&sp_at(i).n, &sp_at(j).n, sizeof(Vec3d)) == 0; };
            auto shade_at = [&](int i, const SharedVisibility* shared) {
              const std::uint32_t v = order[begin + i];
              shade_vertex(light, kernel, options, points[v], diffuse[v], specular ? specular + v : nullptr, occluders,
                           &cluster, wedges_of(v), shared);
            };
            for (int g0 = 0, g1 = 0; g0 < n; g0 = g1) {
              for (g1 = g0 + 1; g1 < n && sp_at(g1).p == sp_at(g0).p; ++g1) {}
              if (g1 - g0 == 1) {
                shade_at(g0, nullptr);
                continue;
              }
              // The classes: a vertex with the whole polygon above its horizon joins the first
              // such one, one with a cut polygon the first with its normal.
              asks.assign(g1 - g0, -1);
              keeps.resize(g1 - g0);
              for (int i = g0; i < g1; ++i) {
                keeps[i - g0] = horizon_keeps(i);
                if (keeps[i - g0] == 0) continue;
                asks[i - g0] = i - g0;
                for (int j = g0; j < i; ++j)
                  if (keeps[j - g0] == keeps[i - g0] && (keeps[i - g0] == 2 || same_normal(i, j))) {
                    asks[i - g0] = asks[j - g0];
                    break;
                  }
              }
              for (int i = g0; i < g1; ++i) {
                const int a = asks[i - g0];
                if (a != i - g0) continue;  // below the horizon, or shaded with its class
                int members = 0;
                for (int j = i; j < g1; ++j) members += asks[j - g0] == a;
                if (members == 1) {
                  shade_at(i, nullptr);
                  continue;
                }
                bool wedged = false;  // some member cuts crease wedges from the shared pieces
                for (int j = i; j < g1; ++j) wedged = wedged || (asks[j - g0] == a && !wedges_of(order[begin + j]).empty());
                see_light_above_horizon(polygon, sp_at(i), occluders, &cluster,
                                        silhouette_pieces_for(options, std::is_same_v<K, PreparedDiskLight<double>>, wedged),
                                        seen);
                for (int j = i; j < g1; ++j)
                  if (asks[j - g0] == a) shade_at(j, &seen);
              }
              for (int i = g0; i < g1; ++i)
                if (asks[i - g0] < 0) shade_at(i, nullptr);
            }
          }
          return;
        }
        }
        const long blocks = (count + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(dynamic, 1)
        for (long b = 0; b < blocks; ++b) {
          if (cancelled()) continue;
          for (long v = b * kBlock; v < std::min(count, (b + 1) * kBlock); ++v)
            shade_vertex(light, kernel, options, points[v], diffuse[v], specular ? specular + v : nullptr, occluders,
                         nullptr, wedges_of(v));
        }
      },
      light.kernel);
}

}  // namespace vlit
