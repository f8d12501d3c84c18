#include "shadow/shadowed_vertices.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "shadow/shadowed_light.h"
#include "shadow/silhouette_cluster.h"

namespace vlit {
namespace {

constexpr long kBlock = 8;         // vertices per group without clusters

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

template <class K>
void shade_vertex(const PreparedLight<double>& light, const K& kernel, const ShadeOptions& options,
                  const ShadingPoint<double>& sp, Vec3d& diffuse, Vec3d* specular, const OccluderBvh& occluders,
                  const SilhouetteCluster* cluster, std::span<const WedgeCone> wedges) {
  const double window = range_window(light, sp.p);
  if (window <= 0) return;
  const Response<double> r = shade_kernel_shadowed(kernel, sp, options, occluders, cluster, wedges);
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
          const int cluster_size = std::max(1, options.shadow_cluster_size);
          const long clusters = (count + cluster_size - 1) / cluster_size;
#pragma omp parallel for schedule(dynamic, 1)
          for (long c = 0; c < clusters; ++c) {
            if (cancelled()) continue;
            const long begin = c * cluster_size;
            const int n = static_cast<int>(std::min<long>(cluster_size, count - begin));
            thread_local SilhouetteCluster cluster;
            prepare_silhouette_cluster(polygon, points, order.data() + begin, n, occluders, cluster);
            for (int i = 0; i < n; ++i) {
              const std::uint32_t v = order[begin + i];
              shade_vertex(light, kernel, options, points[v], diffuse[v], specular ? specular + v : nullptr, occluders,
                           &cluster, wedges_of(v));
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
