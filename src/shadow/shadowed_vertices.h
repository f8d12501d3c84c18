// The per-vertex loop's shadowed path: one light's contribution to a chunk of vertices, each
// vertex evaluated on the part of the light it sees (shadowed_light.h). Called by
// src/bake/light_vertices.cpp for the light x primitive pairs the scene plan shadows.
//
// A shadowed vertex costs up to milliseconds (docs/shadows.md), so the chunk is cut into small
// groups of vertices handed to the threads one at a time, and no group starts once `cancel` is
// set: Ctrl-C is answered within one group on one thread, not after the chunk. For area and disk
// lights by silhouettes a group is a cluster of neighbouring vertices (in Morton order of their
// positions) that searches the BVH once (silhouette_cluster.h); otherwise a group is a run of
// consecutive vertices.
#pragma once

#include <atomic>

#include "shading/prepared_light.h"
#include "shadow/crease_wedges.h"
#include "shadow/occluder_bvh.h"

namespace vlit {

// wedges (may be null): the crease wedges of the points' primitive (crease_wedges.h), whose
// vertex first_vertex + i is points[i].
void accumulate_light_shadowed(const PreparedLight<double>& light, const ShadeOptions& options,
                               const ShadingPoint<double>* points, long count, Vec3d* diffuse, Vec3d* specular,
                               const OccluderBvh& occluders, const std::atomic<bool>* cancel = nullptr,
                               const CreaseWedges* wedges = nullptr, std::size_t first_vertex = 0);

}  // namespace vlit
