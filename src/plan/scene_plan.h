// The scene plan: before any vertex is lit, decide from the scene and the options what work is
// needed, and leave out the rest ("leave out what a given scene does not need"):
// - lights that cannot contribute anywhere (zero intensity or colour) are dropped;
// - light x primitive pairs that cannot contribute are skipped: a one-sided area or disk light
//   whose emitting side does not reach the primitive's bounding box, a spot light whose cone
//   misses the primitive's bounding sphere, a light whose glTF range ends before the box, a light
//   made from a primitive's own emissive triangles and that primitive (it does not light itself);
//   then, vertex by vertex, a pair none of whose vertices can receive the light (each behind the
//   emitting side, beyond the range, outside the cone, or with the whole light below its tangent
//   plane: conditions under which every kernel gives exactly 0, so skipping changes no bit);
// - a light that reaches no vertex at all is reported with why (unreached_light_warnings);
// - specular work is planned only when an eye is given and asked for;
// - every per-light constant is computed once (PreparedLight, and BatchLight for the lights
//   whose diffuse runs in a float SIMD batch kernel);
// - shadows (when asked for) only on the pairs where some triangle may lie between the primitive
//   and the light: boxes prove the rest unoccluded, and a planar primitive cannot shadow itself.
// describe() prints the plan for `--explain`.
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"
#include "shading/batch_kernels.h"
#include "shading/prepared_light.h"

namespace vlit {

struct PlanOptions {
  ShadeOptions shade;
  bool has_eye = false;
  bool float_batch = true;  // let lights' diffuse use the float SIMD batch kernels
  bool shadows = false;  // --shadows on: lights with "shadows": true are hidden by the scene's triangles
};

// What the plan left out and why. Every skip is counted by its reason; only the first
// kMaxDetails are kept word for word (light, primitive, reason) for --explain: a scene with
// thousands of lights and primitives would otherwise keep and print millions of lines.
struct SkipLog {
  static constexpr std::size_t kMaxDetails = 40;
  std::vector<std::string> details;                          // "<subject>: <reason>", the first kMaxDetails
  std::vector<std::pair<std::string, std::size_t>> reasons;  // reason, count; in order of first use
  std::size_t total = 0;

  // `subject()` names what was skipped ("light L x primitive 3"); called only while details are kept.
  template <class Subject>
  void add(const std::string& reason, Subject&& subject) {
    ++total;
    auto it = std::find_if(reasons.begin(), reasons.end(), [&](const auto& r) { return r.first == reason; });
    if (it == reasons.end()) reasons.emplace_back(reason, 1);
    else ++it->second;
    if (details.size() < kMaxDetails) details.push_back(subject() + ": " + reason);
  }
};

struct ScenePlan {
  std::vector<PreparedLight<double>> lights;          // the lights that can contribute somewhere
  std::vector<std::size_t> source_of_light;          // parallel to lights: index into Scene::lights
  std::vector<BatchChoice> batch_of_light;            // parallel to lights: float batch kernel, or why not
  std::vector<std::vector<int>> lights_of_primitive;  // per scene primitive: indices into lights
  // Parallel to lights_of_primitive: 1 where the pair is evaluated with shadows (docs/shadows.md).
  // A pair gets shadows only if shadows are on, the light casts them, and some triangle may lie
  // between the primitive and the light (otherwise the plan proves nothing can occlude).
  std::vector<std::vector<char>> shadowed_of_primitive;
  bool shadows_requested = false;
  bool needs_occluders = false;                       // some pair is shadowed: build the BVH
  std::size_t shadowed_pairs = 0;
  std::size_t occluder_triangles = 0;                 // triangles of the scene when planned
  ShadeOptions shade;                                 // with_specular already resolved
  SkipLog skipped;                                    // what was left out, why
  // Lights (indices into lights) that reach no vertex of the scene, with every reason their
  // pairs were skipped, "; "-separated; empty when the scene has no vertex.
  std::vector<std::pair<std::size_t, std::string>> unreached;
  std::size_t pairs_total = 0, pairs_kept = 0;
};

ScenePlan make_scene_plan(const Scene& scene, const PlanOptions& options);

// Human-readable plan: which kernels run where, what was skipped and why.
std::string describe(const ScenePlan& plan, const Scene& scene);

// One line per light that reaches no vertex: "light NAME reaches no vertex: REASONS", with a hint
// when the light faces away from everything (its winding). For warnings and --explain.
std::vector<std::string> unreached_light_warnings(const ScenePlan& plan, const Scene& scene);

}  // namespace vlit
