// What `render` (and the library's render) draws for a lit primitive: each vertex's colour by the
// shading policy (shading/shading_policy.h: kd x diffuse + ks x specular), for the rasterizer,
// which knows nothing about lighting.
#pragma once

#include <cstdint>
#include <vector>

#include "bake/light_vertices.h"
#include "raster/raster.h"
#include "scene/scene.h"

namespace vlit {

// `indices`: the primitive's triangles, moved in by callers that no longer need them.
raster::DrawMesh lit_draw_mesh(const ScenePrimitive& primitive, const Material& material, const VertexLight& light,
                               std::vector<std::uint32_t> indices);

}  // namespace vlit
