// What `render` (and the library's render) draws for a lit primitive: each vertex's colour is
// kd x diffuse + ks x specular, kd and ks from the glTF material (phong_from_metallic_roughness,
// docs/conventions.md), for the rasterizer, which knows nothing about lighting.
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
