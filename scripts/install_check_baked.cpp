// For scripts/install-test.sh: reads a baked glTF back with vlit's own loader (built against the
// installed package through pkg-config) and checks that every triangle primitive carries a
// COLOR_0 with one colour per position, not all black. Exit status 1 otherwise.
//   install_check_baked BAKED.glb
#include <algorithm>
#include <cstdio>
#include <cstring>

#include <vlit/vlit.h>

// The largest channel of a COLOR_0 accessor (float, or normalized unsigned byte or short).
double largest_channel(const tinygltf::Model& model, const tinygltf::Accessor& accessor) {
  const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
  const tinygltf::Buffer& buffer = model.buffers.at(view.buffer);
  const int components = tinygltf::GetNumComponentsInType(accessor.type);
  const int size = tinygltf::GetComponentSizeInBytes(accessor.componentType);
  const std::size_t stride = view.byteStride ? view.byteStride : std::size_t(components) * size;
  double largest = 0;
  for (std::size_t i = 0; i < accessor.count; ++i)
    for (int c = 0; c < std::min(components, 3); ++c) {
      const unsigned char* at = buffer.data.data() + view.byteOffset + accessor.byteOffset + i * stride + c * size;
      double x = 0;
      if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) { float f; std::memcpy(&f, at, 4); x = f; }
      else if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) { std::uint16_t u; std::memcpy(&u, at, 2); x = u / 65535.0; }
      else if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) x = *at / 255.0;
      largest = std::max(largest, x);
    }
  return largest;
}

int main(int argc, char** argv) {
  if (argc != 2) return std::fprintf(stderr, "usage: %s BAKED.glb\n", argv[0]), 2;
  try {
    const tinygltf::Model model = vlit::load_model(argv[1]);
    std::size_t primitives = 0, colored = 0;
    for (const tinygltf::Mesh& mesh : model.meshes)
      for (const tinygltf::Primitive& prim : mesh.primitives) {
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;
        ++primitives;
        const auto position = prim.attributes.find("POSITION");
        const auto color = prim.attributes.find("COLOR_0");
        if (position == prim.attributes.end() || color == prim.attributes.end()) continue;
        if (model.accessors[color->second].count == model.accessors[position->second].count) ++colored;
      }
    // Lit, not black: the largest stored channel over all COLOR_0 values.
    double brightest = 0;
    for (const tinygltf::Mesh& mesh : model.meshes)
      for (const tinygltf::Primitive& prim : mesh.primitives)
        if (const auto color = prim.attributes.find("COLOR_0"); color != prim.attributes.end())
          brightest = std::max(brightest, largest_channel(model, model.accessors[color->second]));
    std::printf("%s: %zu of %zu triangle primitives have COLOR_0; brightest stored channel %.4g\n", argv[1], colored,
                primitives, brightest);
    if (primitives == 0 || colored != primitives || !(brightest > 0)) return 1;
  } catch (const vlit::Error& e) {
    return std::fprintf(stderr, "%s\n", e.what()), 1;
  }
  return 0;
}
