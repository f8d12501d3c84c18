// Storing per-vertex light in a glTF model as a vertex colour attribute (COLOR_0 by default).
// The stored colour is the multiplier glTF viewers apply to baseColor (the spec's COLOR_0
// semantics): viewer colour = baked light x albedo. Nothing else in the model changes, except that
// a mesh instanced by several nodes is duplicated so each instance carries its own light.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "bake/light_vertices.h"
#include "scene/scene.h"

namespace vlit {

enum class ColorFormat { kUnorm16, kUnorm8, kFloat };

// What to do when the primitive already has the target attribute.
enum class BakeMode {
  kReplace,   // store the light (the old colours are dropped; the caller warns)
  kMultiply,  // store old colour x light (the old alpha is kept)
};

struct BakeOptions {
  std::string target = "COLOR_0";  // COLOR_n, or a custom attribute name starting with "_"
  BakeMode mode = BakeMode::kReplace;
  ColorFormat format = ColorFormat::kUnorm16;
  double exposure = 1;      // multiplies the light before encoding
  bool mark_unlit = true;   // add KHR_materials_unlit so viewers do not light the asset again
  std::string source = "<model>";  // the input's name, for errors about its existing colours
};

struct BakeReport {
  std::size_t vertices = 0;
  // Vertices with specular light in a channel whose base colour is 0, where a multiplier of the
  // base colour cannot show it (the specular of that channel is left out).
  std::size_t specular_unrepresentable = 0;
  std::size_t clipped_vertices = 0;     // a channel above 1 clamped (unorm formats only)
  // Unorm formats: the brightest RGB channel of a vertex (after exposure), over all vertices, and
  // the value 99 % of the vertices stay at or below; exposure / each is the exposure that fits all
  // of them, or 99 %, into [0, 1] (the stored colour is linear in the exposure).
  double brightest_channel = 0;
  double brightest_channel_p99 = 0;
  double max_quantization_error = 0;    // largest |stored - exact| over unclipped channels
  std::size_t replaced_attributes = 0;  // primitives whose existing target attribute was replaced or multiplied
  std::size_t duplicated_meshes = 0;
  // Colour sets below the target (COLOR_0 for a bake into COLOR_1, ...) that a primitive lacked,
  // added in white so the sets stay contiguous as glTF requires (the viewer's picture is unchanged).
  std::size_t filled_color_sets = 0;
};

// `light` holds one VertexLight per scene primitive (light_scene_vertices). The scene must have
// been built from this model (gltf/gltf_scene.h).
// When `light` carries specular light (a bake with --specular-eye), it is folded into the stored
// multiplier so that viewer = stored x baseColor shows kd x diffuse + ks x specular:
//   stored = diffuse [x old colour, multiply mode] + ks x specular / baseColor, per channel,
// with ks from the material mapping (docs/conventions.md); exact only where the texture is white
// and the encoding does not clamp (docs/gltf-output.md "Specular in a multiplier").
BakeReport bake_vertex_colors(tinygltf::Model& model, const Scene& scene, const std::vector<VertexLight>& light,
                              const BakeOptions& options);

}  // namespace vlit
