// The shadow part of the scene plan: which light x primitive pairs need shadows. A pair is
// shadowed when shadows are on, the light casts them ("shadows" in LIGHTS.json), and the plan
// cannot prove that nothing lies between the primitive and the light. The proof: every segment
// from a vertex to the light lies in the box around the primitive's box and the light (swept
// across the scene for a directional light), so a primitive whose box misses that box cannot
// occlude; a planar primitive cannot occlude its own vertices (a segment from a point of the
// plane to a light off the plane meets the plane only at that point).
#pragma once

#include "plan/scene_plan.h"

namespace vlit {

// Fills plan.shadowed_of_primitive, shadowed_pairs, needs_occluders and the skipped lines.
// `kept` are the lights of plan.lights, in order.
void plan_shadows(const Scene& scene, const std::vector<const LightSource*>& kept, bool shadows_on, ScenePlan& plan);

}  // namespace vlit
