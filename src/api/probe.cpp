// The light meter of `vlit probe` (src/cli/probe_command.cpp) on arrays of points: the same sum
// over lights, point by point, with the same kernels; points are spread over the OpenMP threads
// (each point is independent, so the result does not depend on their number).
#include <algorithm>
#include <optional>

#include "api/api_internal.h"
#include "shadow/light_meter.h"

namespace vlit {
namespace {

constexpr std::size_t kChunk = 4096;  // points between two looks at the cancel token

template <class T>
std::vector<ProbeValue> probe_points(const std::vector<SurfacePoint>& points, const std::vector<LightSource>& sources,
                                     const ShadeOptions& options, const OccluderBvh* occluders, const Settings& settings) {
  std::vector<PreparedLight<T>> lights;
  for (const auto& s : sources) lights.push_back(prepare_light<T>(s));
  std::vector<ProbeValue> out(points.size());
  for (std::size_t begin = 0; begin < points.size(); begin += kChunk) {
    if (api::cancelled(settings)) throw Cancelled("points");
    const long count = static_cast<long>(std::min(points.size(), begin + kChunk) - begin);
#pragma omp parallel for schedule(dynamic, 64)
    for (long i = 0; i < count; ++i) {
      const SurfacePoint& p = points[begin + i];
      const ShadingPoint<T> sp = make_shading_point(static_cast<Vec3<T>>(api::to_vec3d(p.position)),
                                                    static_cast<Vec3<T>>(api::to_vec3d(p.normal)),
                                                    static_cast<Vec3<T>>(api::to_vec3d(p.eye)), T(p.shininess));
      const auto [diffuse, specular] = light_meter(lights, sources, sp, options, occluders);
      out[begin + i] = {diffuse, specular};
    }
    if (settings.progress) settings.progress(begin + count, points.size());
  }
  return out;
}

}  // namespace

std::vector<ProbeValue> probe(const std::vector<SurfacePoint>& points, const Lights& lights, const ProbeSettings& settings,
                              const std::vector<Mesh>& occluders) {
  return api::translate_errors("points", [&] {
    api::check_settings(settings, "points");
    // What points.csv refuses (io/points_csv.h): a zero or non-finite normal, a negative shininess.
    for (std::size_t i = 0; i < points.size(); ++i) {
      const SurfacePoint& p = points[i];
      const std::string where = "points[" + std::to_string(i) + "]";
      for (const Vector3* v : {&p.position, &p.normal, &p.eye})
        if (!std::isfinite((*v)[0]) || !std::isfinite((*v)[1]) || !std::isfinite((*v)[2]))
          throw Error("points", "coordinate is not finite", where);
      if (!(length(api::to_vec3d(p.normal)) > 0)) throw Error("points", "normal has zero length", where);
      if (!(p.shininess >= 0) || !std::isfinite(p.shininess)) throw Error("points", "shininess must be finite and >= 0", where);
    }
    const ShadeOptions options = api::shade_options(settings);
    api::ThreadCount threads(settings.threads);
    std::optional<OccluderBvh> bvh;
    if (settings.shadows && !occluders.empty()) {
      if (settings.precision == Precision::kFloat)
        throw Error("points", "shadows need Precision::kDouble (shadows are computed in double)", "settings.precision");
      bvh.emplace(occluders_of(api::scene_of_meshes(occluders)));
    }
    if (settings.precision == Precision::kFloat)
      return probe_points<float>(points, lights.impl().sources, options, nullptr, settings);
    return probe_points<double>(points, lights.impl().sources, options, bvh ? &*bvh : nullptr, settings);
  });
}

}  // namespace vlit
