// What `render --preview` draws for a primitive: what a glTF viewer shows for a baked, unlit asset
// (KHR_materials_unlit): COLOR_0 x baseColorFactor per vertex, plus the material's own emission
// (emissiveFactor x KHR_materials_emissive_strength), with no lighting. Base colour textures are
// not sampled (the rasterizer interpolates vertex colours only); the caller says so.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/raster.h"
#include "scene/scene.h"

namespace vlit {

// A primitive without COLOR_0 (empty primitive.colors) draws its base colour, as glTF's default
// COLOR_0 of white. `indices`: the primitive's triangles, moved in.
raster::DrawMesh preview_draw_mesh(const ScenePrimitive& primitive, const Material& material,
                                   std::vector<std::uint32_t> indices);

}  // namespace vlit
