#include "bake/light_vertices.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include "bake/batch_lighting.h"
#include "scene/material.h"
#include "shadow/shadowed_vertices.h"

namespace vlit {
namespace {

// Adds one light's contribution to a chunk of vertices. The light model is resolved once per
// chunk (std::visit outside the vertex loop), so the inner loop has no dispatch.
void accumulate_light(const PreparedLight<double>& light, const ShadeOptions& options,
                      const ShadingPoint<double>* points, long count, Vec3d* diffuse, Vec3d* specular) {
  const bool windowed = light.range > 0;
  std::visit(
      [&](const auto& kernel) {
#pragma omp parallel for schedule(static)
        for (long v = 0; v < count; ++v) {
          const ShadingPoint<double>& sp = points[v];
          Response<double> r = shade_kernel<double>(kernel, sp, options);
          if (windowed) {
            const double window = range_window(light, sp.p);
            r.diffuse *= window;
            r.specular *= window;
          }
          diffuse[v] += light.radiance * r.diffuse;
          if (specular) specular[v] += light.radiance * r.specular;
        }
      },
      light.kernel);
}

// Double light to the float output, saturating at the largest float so an over-lit vertex stays
// the brightest rather than becoming Inf (and later black in an encoder that drops non-finite
// values). Inputs are finite and >= 0 by construction of the kernels.
Vec3f to_output(const Vec3d& c) {
  constexpr double kMax = std::numeric_limits<float>::max();
  return {static_cast<float>(std::min(c.x, kMax)), static_cast<float>(std::min(c.y, kMax)),
          static_cast<float>(std::min(c.z, kMax))};
}

}  // namespace

ScenePlan plan_lighting(const Scene& scene, const LightingRequest& request) {
  PlanOptions options;
  options.shade = request.shade;
  options.has_eye = request.eye.has_value();
  options.float_batch = request.float_batch;
  options.shadows = request.shadows;
  return make_scene_plan(scene, options);
}

std::vector<VertexLight> light_scene_vertices(const Scene& scene, const LightingRequest& request) {
  return light_scene_vertices(scene, plan_lighting(scene, request), request);
}

std::vector<VertexLight> light_scene_vertices(const Scene& scene, const ScenePlan& plan, const LightingRequest& request) {
  const ShadeOptions& options = plan.shade;
  const Vec3d eye = request.eye.value_or(Vec3d{});
  std::vector<VertexLight> out(scene.primitives.size());
  const std::size_t total = scene.vertex_count();
  std::size_t done = 0;
  // Progress and cancellation are checked between chunks of vertices. A chunk's size adapts to
  // its cost, so that each takes about 30 to 120 ms whether a vertex costs nanoseconds
  // (unshadowed diffuse) or milliseconds (exact specular): the progress line moves and Ctrl-C is
  // answered within about that time. A primitive with shadowed pairs takes chunks of 0.25 to 1 s:
  // the shadowed loop answers Ctrl-C between its clusters anyway, and each of its lights runs
  // one parallel loop over the chunk's clusters, which in a 0.12 s chunk of many lights were too
  // few to keep both cores busy (MetalRoughSpheres under 8 panels: docs/shadows.md). Each vertex
  // is computed independently, so the chunking never changes a result.
  constexpr std::size_t kMaxChunk = 1 << 14, kMinChunk = 64;
  constexpr double kChunkSecondsLow = 0.03, kChunkSecondsHigh = 0.12;
  constexpr double kShadowedChunkSecondsLow = 0.25, kShadowedChunkSecondsHigh = 1.0;
  std::size_t chunk = 1024;
  std::vector<Vec3d> diffuse(kMaxChunk), specular(options.with_specular ? kMaxChunk : 0);
  std::vector<ShadingPoint<double>> points(kMaxChunk);  // per vertex, computed once for all lights
  BatchChunk batch;                                   // the same points as arrays, for batch kernels
  std::vector<int> batch_lights;
  std::optional<OccluderBvh> occluders;  // built only when the plan shadows some pair
  if (plan.needs_occluders) occluders.emplace(occluders_of(scene));
  // Vertices sharing a position with others: the wedges across creases (crease_wedges.h).
  std::optional<SharedPositions> shared;
  if (occluders && options.crease_wedges) shared.emplace(scene);
  CreaseWedges wedges;
  for (std::size_t pi = 0; pi < scene.primitives.size(); ++pi) {
    const ScenePrimitive& prim = scene.primitives[pi];
    const double shininess = phong_from_metallic_roughness(scene.material_of(prim)).shininess;
    VertexLight& result = out[pi];
    const std::size_t n = prim.positions.size();
    result.diffuse.assign(n, Vec3f{});
    if (options.with_specular) result.specular.assign(n, Vec3f{});
    // Shadowed pairs take the shadowed path; of the others, lights with a float batch kernel
    // first, all in one parallel region; then the rest. Decided once per primitive, from the plan.
    const std::vector<int>& lights_here = plan.lights_of_primitive[pi];
    auto shadowed = [&](std::size_t k) { return occluders && plan.shadowed_of_primitive[pi][k]; };
    batch_lights.clear();
    bool any_shadowed = false;
    for (std::size_t k = 0; k < lights_here.size(); ++k) {
      if (!shadowed(k) && plan.batch_of_light[lights_here[k]].light) batch_lights.push_back(lights_here[k]);
      any_shadowed = any_shadowed || shadowed(k);
    }
    wedges = shared && any_shadowed ? shared->wedges_of(pi) : CreaseWedges{};
    const double seconds_low = any_shadowed ? kShadowedChunkSecondsLow : kChunkSecondsLow;
    const double seconds_high = any_shadowed ? kShadowedChunkSecondsHigh : kChunkSecondsHigh;
    for (std::size_t begin = 0, end = 0; begin < n; begin = end) {
      if (request.cancel && request.cancel->load()) return out;
      const auto chunk_start = std::chrono::steady_clock::now();
      end = std::min(n, begin + chunk);
      const long count = static_cast<long>(end - begin);
      std::fill(diffuse.begin(), diffuse.begin() + count, Vec3d{});
      if (options.with_specular) std::fill(specular.begin(), specular.begin() + count, Vec3d{});
      if (!lights_here.empty()) {
#pragma omp parallel for schedule(static)
        for (long v = 0; v < count; ++v)
          points[v] = make_shading_point(prim.positions[begin + v], prim.normals[begin + v], eye, shininess);
      }
      accumulate_batch_lights(plan, batch_lights, batch, points.data(), count, diffuse.data(),
                              options.with_specular ? specular.data() : nullptr);
      for (std::size_t k = 0; k < lights_here.size(); ++k) {
        const PreparedLight<double>& light = plan.lights[lights_here[k]];
        Vec3d* spec_out = options.with_specular ? specular.data() : nullptr;
        if (shadowed(k))
          accumulate_light_shadowed(light, options, points.data(), count, diffuse.data(), spec_out, *occluders,
                                    request.cancel, &wedges, begin);
        else if (!plan.batch_of_light[lights_here[k]].light)
          accumulate_light(light, options, points.data(), count, diffuse.data(), spec_out);
      }
      for (std::size_t v = begin; v < end; ++v) {
        result.diffuse[v] = to_output(diffuse[v - begin]);
        if (options.with_specular) result.specular[v] = to_output(specular[v - begin]);
      }
      done += end - begin;
      if (request.progress) request.progress(done, total);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - chunk_start).count();
      if (end - begin == chunk && seconds < seconds_low) {
        // Toward the middle of the window at once (2x to 16x): a parallel loop's last clusters
        // leave a core idle, so a bake of a few short chunks pays that more than once.
        const double toward_middle = seconds > 0 ? 0.5 * (seconds_low + seconds_high) / seconds : 16.0;
        chunk = std::min(kMaxChunk, static_cast<std::size_t>(static_cast<double>(chunk) * std::clamp(toward_middle, 2.0, 16.0)));
      } else if (seconds > seconds_high) {
        chunk = std::max(kMinChunk, chunk / 2);
      }
    }
  }
  return out;
}

}  // namespace vlit
