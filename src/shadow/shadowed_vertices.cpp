#include "shadow/shadowed_vertices.h"

#include "shadow/shadowed_light.h"

namespace vlit {

void accumulate_light_shadowed(const PreparedLight<double>& light, const ShadeOptions& options,
                               const ShadingPoint<double>* points, long count, Vec3d* diffuse, Vec3d* specular,
                               const OccluderBvh& occluders) {
  std::visit(
      [&](const auto& kernel) {
        // Dynamic schedule: the cost per vertex varies with how many occluders it sees.
#pragma omp parallel for schedule(dynamic, 64)
        for (long v = 0; v < count; ++v) {
          const ShadingPoint<double>& sp = points[v];
          const double window = range_window(light, sp.p);
          if (window <= 0) continue;
          const Response<double> r = shade_kernel_shadowed(kernel, sp, options, occluders);
          diffuse[v] += light.radiance * (r.diffuse * window);
          if (specular) specular[v] += light.radiance * (r.specular * window);
        }
      },
      light.kernel);
}

}  // namespace vlit
