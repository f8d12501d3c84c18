#include "bake/light_vertices.h"

#include <algorithm>

#include "scene/material.h"

namespace vlit {

std::vector<VertexLight> light_scene_vertices(const Scene& scene, const LightingRequest& request) {
  std::vector<PreparedLight<double>> lights;
  lights.reserve(scene.lights.size());
  for (const LightSource& l : scene.lights) lights.push_back(prepare_light<double>(l));

  ShadeOptions options = request.shade;
  options.with_specular = options.with_specular && request.eye.has_value();
  const Vec3d eye = request.eye.value_or(Vec3d{});

  std::vector<VertexLight> out(scene.primitives.size());
  const std::size_t total = scene.vertex_count();
  std::size_t done = 0;
  for (std::size_t pi = 0; pi < scene.primitives.size(); ++pi) {
    const ScenePrimitive& prim = scene.primitives[pi];
    const double shininess = phong_from_metallic_roughness(scene.material_of(prim)).shininess;
    VertexLight& result = out[pi];
    const std::size_t n = prim.positions.size();
    result.diffuse.assign(n, Vec3f{});
    if (options.with_specular) result.specular.assign(n, Vec3f{});
    // Chunks keep progress reports on the calling thread without locks in the inner loop.
    const std::size_t chunk = 1 << 14;
    for (std::size_t begin = 0; begin < n; begin += chunk) {
      if (request.cancel && request.cancel->load()) return out;
      const long end = static_cast<long>(std::min(n, begin + chunk));
#pragma omp parallel for schedule(static)
      for (long v = static_cast<long>(begin); v < end; ++v) {
        const ShadingPoint<double> sp = make_shading_point(prim.positions[v], prim.normals[v], eye, shininess);
        Vec3d diffuse, specular;
        for (const PreparedLight<double>& light : lights) {
          const Response<double> r = shade(light, sp, options);
          diffuse += light.radiance * r.diffuse;
          specular += light.radiance * r.specular;
        }
        result.diffuse[v] = static_cast<Vec3f>(diffuse);
        if (options.with_specular) result.specular[v] = static_cast<Vec3f>(specular);
      }
      done += static_cast<std::size_t>(end) - begin;
      if (request.progress) request.progress(done, total);
    }
  }
  return out;
}

}  // namespace vlit
