// The per-vertex loop's shadowed path: one light's contribution to a chunk of vertices, each
// vertex evaluated on the part of the light it sees (shadowed_light.h). Called by
// src/bake/light_vertices.cpp for the light x primitive pairs the scene plan shadows.
#pragma once

#include "shading/prepared_light.h"
#include "shadow/occluder_bvh.h"

namespace vlit {

void accumulate_light_shadowed(const PreparedLight<double>& light, const ShadeOptions& options,
                               const ShadingPoint<double>* points, long count, Vec3d* diffuse, Vec3d* specular,
                               const OccluderBvh& occluders);

}  // namespace vlit
