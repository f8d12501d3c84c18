// The per-vertex loop: every vertex of every primitive, every light the scene plan keeps for
// it, all cores. Output is coloured light per vertex, before the material: diffuse = Σ radiance ·
// Id and specular = Σ radiance · Is (kd = ks = 1). The bake stores the diffuse as the COLOR_0
// multiplier; the renderer combines both with the material.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "plan/scene_plan.h"
#include "scene/scene.h"

namespace vlit {

struct VertexLight {
  std::vector<Vec3f> diffuse;   // per vertex, linear RGB
  std::vector<Vec3f> specular;  // per vertex, linear RGB (empty when no specular was planned)
};

struct LightingRequest {
  ShadeOptions shade;
  std::optional<Vec3d> eye;  // specular is evaluated only with an eye
  // Lights' diffuse uses the float SIMD batch kernels where the plan finds one (bake/batch_lighting.h);
  // false keeps every light on the scalar double kernels.
  bool float_batch = true;
  bool shadows = false;      // --shadows: lights hidden by the scene's triangles (docs/shadows.md)
  // Called from the calling thread with (vertices done, vertices total); may be empty.
  std::function<void(std::size_t, std::size_t)> progress;
  // Polled between chunks of vertices (each takes about 0.1 s) and between blocks of a few
  // shadowed vertices: when true, lighting stops early (results incomplete).
  const std::atomic<bool>* cancel = nullptr;
};

// The plan light_scene_vertices would follow for this request (for --explain).
ScenePlan plan_lighting(const Scene& scene, const LightingRequest& request);

// One VertexLight per scene primitive, in the same order. Deterministic: the result does not
// depend on the number of threads (each vertex is computed independently, lights summed in a fixed
// order: the plan's lights with a float batch kernel, then the others, each group in the plan's order).
std::vector<VertexLight> light_scene_vertices(const Scene& scene, const LightingRequest& request);
std::vector<VertexLight> light_scene_vertices(const Scene& scene, const ScenePlan& plan, const LightingRequest& request);

}  // namespace vlit
