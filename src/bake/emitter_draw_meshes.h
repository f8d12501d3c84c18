// The lights that have a shape, drawn as what they are: a panel (area light), a disk, a tube
// (linear light), each with the radiance it emits, for `render --preview`. Lights made from a
// primitive's own emissive triangles are not here: that primitive is drawn with its emission.
//   - area and disk: the polygon (a disk as 48 sides) in colour x intensity, the radiance of
//     LightSource (luminance, nits). A one-sided light is black from behind (it emits along its
//     front face only, as the kernels light); a two-sided one shows its radiance on both faces.
//   - linear: a segment has no radius in the model (Picott 1992 eq. 3), so it is drawn as a band
//     kTubePixels wide on screen, facing the camera, in colour x intensity / length: the emission
//     (candela per metre) of the glTF emissive line that makes this light (gltf/emissive_lights.h).
#pragma once

#include <vector>

#include "raster/raster.h"
#include "scene/light_source.h"

namespace vlit {

inline constexpr double kTubePixels = 3;

// `camera` and `image_height` size the tubes' bands in pixels.
std::vector<raster::DrawMesh> emitter_draw_meshes(const std::vector<LightSource>& lights, const raster::Camera& camera,
                                                  int image_height);

}  // namespace vlit
