// Compressed glTF in, plain glTF out: an asset whose geometry is stored with
// KHR_draco_mesh_compression (made by Debian's draco_transcoder) or EXT_meshopt_compression
// (written here with libmeshoptimizer's encoder) bakes to the same colours as the uncompressed
// asset, and the output holds no compression extension.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include "gltf/accessor_reader.h"
#include "gltf/gltf_file.h"
#include "support/gltf_builder.h"
#include "support/run_command.h"

using namespace vlit;
using vlit::test::run_command;
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const std::string kVlit = VLIT_BINARY;
const std::string kAvocado = std::string(VLIT_ASSETS_DIR) + "/samples/Avocado";

std::string q(const std::string& s) { return "'" + s + "'"; }

// The Avocado sample without its textures (their PNGs are not vendored, and draco_transcoder
// refuses an asset whose images it cannot open): the geometry and the material's factors stay.
fs::path plain_avocado(const fs::path& dir) {
  std::ifstream in(kAvocado + "/Avocado.gltf");
  json root = json::parse(in);
  root.erase("images");
  root.erase("textures");
  root.erase("samplers");
  for (auto& m : root["materials"]) {
    m["pbrMetallicRoughness"].erase("baseColorTexture");
    m["pbrMetallicRoughness"].erase("metallicRoughnessTexture");
    m.erase("normalTexture");
  }
  fs::copy_file(kAvocado + "/Avocado.bin", dir / "Avocado.bin", fs::copy_options::overwrite_existing);
  const fs::path out = dir / "avocado.gltf";
  std::ofstream(out) << root.dump(1);
  return out;
}

// A point light above and in front of the avocado (it is 0.063 m tall, 0.043 m wide).
fs::path lights_file(const fs::path& dir) {
  const fs::path path = dir / "lights.json";
  std::ofstream(path) << R"({"lights": [{"type": "point", "position": [0.05, 0.09, 0.06], "intensity": 0.004}]})";
  return path;
}

struct BakedVertex {
  double p[3], n[3], c[3];
};

// Bakes `in` with the CLI (float colours, no encoding step) and returns every vertex of the output
// with its position, normal and colour; checks the output names no compression extension.
std::vector<BakedVertex> bake(const fs::path& in, const fs::path& lights, const fs::path& out) {
  const auto r = run_command(kVlit + " bake " + q(in.string()) + " --lights " + q(lights.string()) +
                             " --color-format float --quiet -o " + q(out.string()));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const GltfFile baked = load_gltf_file(out.string());
  for (const auto* list : {&baked.model.extensionsUsed, &baked.model.extensionsRequired})
    for (const std::string& e : *list) {
      CHECK(e != "KHR_draco_mesh_compression");
      CHECK(e != "EXT_meshopt_compression");
    }
  // The raw JSON too: no primitive or bufferView keeps a compression extension object.
  const std::string bytes = vlit::test::read_all(out);
  CHECK(bytes.find("_compression") == std::string::npos);
  std::vector<BakedVertex> vertices;
  for (const auto& mesh : baked.model.meshes)
    for (const auto& prim : mesh.primitives) {
      const auto p = read_accessor_as_doubles(baked.model, prim.attributes.at("POSITION"), out.string());
      // POSITION's min and max must be its values' exact bounds (glTF 2.0 3.6.2.5; the
      // glTF-Validator's ACCESSOR_MAX_MISMATCH): Draco's quantization moves them.
      const tinygltf::Accessor& position = baked.model.accessors[prim.attributes.at("POSITION")];
      REQUIRE(position.minValues.size() == 3);
      REQUIRE(position.maxValues.size() == 3);
      for (int k = 0; k < 3; ++k) {
        double lo = p[k], hi = p[k];
        for (std::size_t i = k; i < p.size(); i += 3) lo = std::min(lo, p[i]), hi = std::max(hi, p[i]);
        // Compared as the float32 the values are (a file may write 0.02128091 for the float nearest it).
        CHECK(static_cast<float>(position.minValues[k]) == static_cast<float>(lo));
        CHECK(static_cast<float>(position.maxValues[k]) == static_cast<float>(hi));
      }
      const auto n = read_accessor_as_doubles(baked.model, prim.attributes.at("NORMAL"), out.string());
      REQUIRE(prim.attributes.count("COLOR_0"));
      const int color = prim.attributes.at("COLOR_0");
      const std::size_t components = baked.model.accessors[color].type == TINYGLTF_TYPE_VEC4 ? 4 : 3;
      const auto c = read_accessor_as_doubles(baked.model, color, out.string());
      for (std::size_t i = 0; i < p.size() / 3; ++i) {
        BakedVertex v;
        for (int k = 0; k < 3; ++k) {
          v.p[k] = p[3 * i + k];
          v.n[k] = n[3 * i + k];
          v.c[k] = c[components * i + k];
        }
        vertices.push_back(v);
      }
    }
  return vertices;
}

// For every vertex of `decoded`, the vertex of `reference` nearest in position and normal (the
// two the colour depends on); returns the largest colour difference, in units of the brightest
// reference colour, and the largest position distance of a match.
struct Match {
  double colour = 0, position = 0;
};
Match compare(const std::vector<BakedVertex>& reference, const std::vector<BakedVertex>& decoded) {
  double brightest = 0;
  for (const auto& v : reference) brightest = std::max({brightest, v.c[0], v.c[1], v.c[2]});
  REQUIRE(brightest > 0);
  Match worst;
  for (const auto& d : decoded) {
    const BakedVertex* best = nullptr;
    double best_distance = std::numeric_limits<double>::infinity();
    for (const auto& r : reference) {
      double distance = 0;
      for (int k = 0; k < 3; ++k)
        distance += (d.p[k] - r.p[k]) * (d.p[k] - r.p[k]) / (0.06 * 0.06) + (d.n[k] - r.n[k]) * (d.n[k] - r.n[k]);
      if (distance < best_distance) best_distance = distance, best = &r;
    }
    double position = 0;
    for (int k = 0; k < 3; ++k) {
      worst.colour = std::max(worst.colour, std::abs(d.c[k] - best->c[k]) / brightest);
      position += (d.p[k] - best->p[k]) * (d.p[k] - best->p[k]);
    }
    worst.position = std::max(worst.position, std::sqrt(position));
  }
  return worst;
}

void append_u32(std::string& s, std::uint32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); }

// A GLB container (glTF 2.0 "Binary glTF Layout"), written here independently of vlit's code.
void write_glb(const fs::path& path, const json& root, std::string bin) {
  std::string text = root.dump();
  while (text.size() % 4) text.push_back(' ');
  while (bin.size() % 4) bin.push_back('\0');
  std::string out;
  append_u32(out, 0x46546C67u);
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(28 + text.size() + bin.size()));
  append_u32(out, static_cast<std::uint32_t>(text.size()));
  append_u32(out, 0x4E4F534Au);
  out += text;
  append_u32(out, static_cast<std::uint32_t>(bin.size()));
  append_u32(out, 0x004E4942u);
  out += bin;
  std::ofstream(path, std::ios::binary) << out;
}

}  // namespace

TEST_CASE("a Draco-compressed asset made by draco_transcoder bakes like the uncompressed one") {
  if (run_command("command -v draco_transcoder").exit_code != 0) {
    MESSAGE("skipped: draco_transcoder (Debian package draco) is not installed");
    return;
  }
  const fs::path dir = vlit::test::temp_dir("draco");
  const fs::path plain = plain_avocado(dir), lights = lights_file(dir), draco = dir / "avocado-draco.glb";
  // 16 bits for positions over the 0.063 m box (a step of 1e-6 m), 14 for normals (octahedral:
  // an angle of at most about 2e-4 rad), 12 for texture coordinates and tangents.
  const auto t = run_command("draco_transcoder -i " + q(plain.string()) + " -o " + q(draco.string()) +
                             " -qp 16 -qn 14 -qt 12 -qtg 12");
  REQUIRE_MESSAGE(t.exit_code == 0, std::string(t.out + t.err));
  // It really is compressed: the transcoder's output requires the extension.
  REQUIRE(vlit::test::read_all(draco).find("KHR_draco_mesh_compression") != std::string::npos);

  const auto reference = bake(plain, lights, dir / "plain-baked.glb");
  const auto decoded = bake(draco, lights, dir / "draco-baked.glb");
  REQUIRE(reference.size() == 406);
  CHECK(decoded.size() >= 300);  // Draco may merge identical points; never loses the surface
  const Match m = compare(reference, decoded);
  // Tolerance: the diffuse I cos(theta) / d^2 with d >= 0.04 m changes by at most
  // (angle error + 2 * position error / d) times the brightest value: 2e-4 + 2 * 1e-6 / 0.04 = 2.5e-4;
  // 1e-3 leaves room for the point light's direction error. A wrong attribute or point order is O(1).
  CHECK(m.position < 2e-6);
  CHECK(m.colour < 1e-3);
  MESSAGE("Draco: largest colour difference " << m.colour << " of the brightest, position " << m.position << " m");
}

TEST_CASE("an EXT_meshopt_compression asset written with libmeshoptimizer bakes like the uncompressed one") {
  const fs::path dir = vlit::test::temp_dir("meshopt");
  const fs::path plain = plain_avocado(dir), lights = lights_file(dir), packed = dir / "avocado-meshopt.glb";
  const GltfFile source = load_gltf_file(plain.string());
  const tinygltf::Primitive& prim = source.model.meshes[0].primitives[0];
  const std::size_t count = source.model.accessors[prim.attributes.at("POSITION")].count;

  // The asset's JSON with its buffers replaced: buffer 0 (the GLB chunk) holds the compressed
  // streams, buffer 1 is the fallback the extension requires (no data, only a size).
  json root = json::parse(std::ifstream(plain));
  root["accessors"] = json::array();
  root["bufferViews"] = json::array();
  std::string bin;
  std::size_t fallback_size = 0;
  auto add_stream = [&](const std::string& bytes, std::size_t elements, std::size_t stride, const std::string& mode,
                        const std::string& filter) {
    std::vector<unsigned char> encoded;
    if (mode == "ATTRIBUTES") {
      encoded.resize(meshopt_encodeVertexBufferBound(elements, stride));
      encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), bytes.data(), elements, stride));
    } else {
      std::vector<unsigned int> indices(elements);
      std::memcpy(indices.data(), bytes.data(), bytes.size());
      encoded.resize(meshopt_encodeIndexBufferBound(elements, count));
      encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices.data(), elements));
    }
    REQUIRE(!encoded.empty());
    while (bin.size() % 4) bin.push_back('\0');
    json ext = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", encoded.size()}, {"byteStride", mode == "ATTRIBUTES" ? stride : 4},
                {"count", elements}, {"mode", mode}};
    if (filter != "NONE") ext["filter"] = filter;
    bin.append(reinterpret_cast<const char*>(encoded.data()), encoded.size());
    json view = {{"buffer", 1}, {"byteOffset", fallback_size}, {"byteLength", elements * (mode == "ATTRIBUTES" ? stride : 4)},
                 {"extensions", {{"EXT_meshopt_compression", ext}}}};
    if (mode == "ATTRIBUTES") view["byteStride"] = stride;
    fallback_size += view["byteLength"].get<std::size_t>();
    root["bufferViews"].push_back(view);
    return root["bufferViews"].size() - 1;
  };
  auto floats = [&](int accessor) {
    const auto d = read_accessor_as_doubles(source.model, accessor, plain.string());
    return std::vector<float>(d.begin(), d.end());
  };
  json attributes = json::object();
  for (const auto& [semantic, accessor] : prim.attributes) {
    const tinygltf::Accessor& a = source.model.accessors[accessor];
    json acc = {{"componentType", TINYGLTF_COMPONENT_TYPE_FLOAT}, {"count", a.count}};
    const std::vector<float> values = floats(accessor);
    if (semantic == "NORMAL") {
      // Normals through the OCTAHEDRAL filter: 16-bit signed octahedral x, y (KHR_mesh_quantization
      // normalized shorts), so the decoder's filter must run for the normals to come back.
      std::vector<float> xyzw(4 * a.count);
      for (std::size_t i = 0; i < a.count; ++i)
        for (int k = 0; k < 3; ++k) xyzw[4 * i + k] = values[3 * i + k];
      std::string bytes(8 * a.count, '\0');
      meshopt_encodeFilterOct(bytes.data(), a.count, 8, 16, xyzw.data());
      acc = {{"componentType", TINYGLTF_COMPONENT_TYPE_SHORT}, {"normalized", true}, {"count", a.count}, {"type", "VEC3"},
             {"bufferView", add_stream(bytes, a.count, 8, "ATTRIBUTES", "OCTAHEDRAL")}};
    } else {
      const std::size_t components = values.size() / a.count;
      std::string bytes(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
      acc["type"] = components == 2 ? "VEC2" : components == 3 ? "VEC3" : "VEC4";
      acc["bufferView"] = add_stream(bytes, a.count, 4 * components, "ATTRIBUTES", "NONE");
      if (semantic == "POSITION") acc["min"] = a.minValues, acc["max"] = a.maxValues;
    }
    root["accessors"].push_back(acc);
    attributes[semantic] = root["accessors"].size() - 1;
  }
  const std::vector<std::uint32_t> indices = draw_order_of(source.model, prim, count, plain.string());
  const std::string index_bytes(reinterpret_cast<const char*>(indices.data()), indices.size() * 4);
  root["accessors"].push_back({{"componentType", TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}, {"count", indices.size()}, {"type", "SCALAR"},
                               {"bufferView", add_stream(index_bytes, indices.size(), 4, "TRIANGLES", "NONE")}});
  root["meshes"][0]["primitives"][0]["attributes"] = attributes;
  root["meshes"][0]["primitives"][0]["indices"] = root["accessors"].size() - 1;
  root["buffers"] = json::array({{{"byteLength", bin.size()}},
                                 {{"byteLength", fallback_size}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}});
  root["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
  root["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
  write_glb(packed, root, bin);

  const auto reference = bake(plain, lights, dir / "plain-baked.glb");
  const auto decoded = bake(packed, lights, dir / "meshopt-baked.glb");
  REQUIRE(decoded.size() == reference.size());
  // The vertex and index codecs are lossless: same positions, same order. The normals went through
  // 16-bit octahedral quantization: an angle error of at most about 1e-4 rad, so colours agree to
  // 1e-4 of the brightest (plus the float rounding of the normalized shorts).
  double colour = 0;
  double brightest = 0;
  for (const auto& v : reference) brightest = std::max({brightest, v.c[0], v.c[1], v.c[2]});
  for (std::size_t i = 0; i < reference.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      CHECK(decoded[i].p[k] == reference[i].p[k]);
      colour = std::max(colour, std::abs(decoded[i].c[k] - reference[i].c[k]) / brightest);
    }
  CHECK(colour < 2e-4);
  MESSAGE("meshopt: largest colour difference " << colour << " of the brightest");

  SUBCASE("a corrupt stream is a one-line error naming the bufferView, and nothing is written") {
    json broken = root;
    broken["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 3;
    const fs::path bad = dir / "broken.glb";
    write_glb(bad, broken, bin);
    const auto r = run_command(kVlit + " bake " + q(bad.string()) + " --lights " + q(lights.string()) + " -o " +
                               q((dir / "broken-out.glb").string()));
    CHECK(r.exit_code != 0);
    CHECK(r.err.find("bufferViews[0].extensions.EXT_meshopt_compression") != std::string::npos);
    CHECK(r.err.find("does not decode") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(dir / "broken-out.glb"));
  }
}

TEST_CASE("bake names a required extension vlit does not support, before parsing") {
  const fs::path dir = vlit::test::temp_dir("required-extension");
  json root = json::parse(std::ifstream(plain_avocado(dir)));
  root["accessors"][4].erase("bufferView");  // what a parser running first would trip on
  root["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  root["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
  std::ofstream(dir / "instanced.gltf") << root.dump();
  const auto r = run_command(kVlit + " bake " + q((dir / "instanced.gltf").string()) + " -o " + q((dir / "out.glb").string()));
  CHECK(r.exit_code != 0);
  CHECK(r.err.find("instanced.gltf: requires extension EXT_mesh_gpu_instancing, which vlit does not support") != std::string::npos);
  CHECK(r.err.find("bufferView") == std::string::npos);
  CHECK(!fs::exists(dir / "out.glb"));
}

namespace {

// The JSON chunk of a .glb, or the whole text of a .gltf.
json json_of(const fs::path& path) {
  const std::string bytes = vlit::test::read_all(path);
  if (path.extension() == ".gltf") return json::parse(bytes);
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return json::parse(bytes.substr(20, length));
}

}  // namespace

TEST_CASE("bake --meshopt writes EXT_meshopt_compression that decodes to the uncompressed bake") {
  const fs::path dir = vlit::test::temp_dir("meshopt-out");
  const fs::path plain = plain_avocado(dir), lights = lights_file(dir);
  for (const std::string ext : {".glb", ".gltf"}) {
    CAPTURE(ext);
    const fs::path flat = dir / ("flat" + ext), packed = dir / ("packed" + ext);
    for (const auto& [out, flag] : {std::pair{flat, std::string()}, std::pair{packed, std::string(" --meshopt")}}) {
      const auto r = run_command(kVlit + " bake " + q(plain.string()) + " --lights " + q(lights.string()) + flag +
                                 " --quiet -o " + q(out.string()));
      REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    }
    // The file says what it needs, and every vertex and index view is encoded.
    const json root = json_of(packed);
    REQUIRE(root.contains("extensionsRequired"));
    CHECK(std::find(root["extensionsRequired"].begin(), root["extensionsRequired"].end(), "EXT_meshopt_compression") !=
          root["extensionsRequired"].end());
    const json& prim = root["meshes"][0]["primitives"][0];
    auto mode_of = [&](int accessor) {
      const json& view = root["bufferViews"][root["accessors"][accessor]["bufferView"].get<int>()];
      return view["extensions"]["EXT_meshopt_compression"].value("mode", std::string());
    };
    for (const auto& item : prim["attributes"].items()) {
      // Named, not bound: CAPTURE's lambda captures it (clang 14 does not capture structured bindings).
      const std::string semantic = item.key();
      const auto& accessor = item.value();
      CAPTURE(semantic);
      CHECK(mode_of(accessor.get<int>()) == "ATTRIBUTES");
    }
    CHECK(mode_of(prim["indices"].get<int>()) == "TRIANGLES");
    const json& fallback = root["buffers"][root["buffers"].size() - 1];
    CHECK(fallback["extensions"]["EXT_meshopt_compression"]["fallback"] == true);
    CHECK(!fallback.contains("uri"));
    CHECK(fs::file_size(packed) < fs::file_size(flat));

    // Decoded (vlit's reader, libmeshoptimizer's decoder), every attribute reads the same values
    // as the uncompressed bake's, and the indices the same triangles in the same order (the
    // triangle codec may start a triangle at another corner: the same triangle, the same winding).
    const GltfFile a = load_gltf_file(flat.string()), b = load_gltf_file(packed.string());
    REQUIRE(a.model.accessors.size() == b.model.accessors.size());
    const int indices = a.model.meshes[0].primitives[0].indices;
    for (std::size_t i = 0; i < a.model.accessors.size(); ++i) {
      CAPTURE(i);
      const auto x = read_accessor_as_doubles(a.model, static_cast<int>(i), flat.string());
      const auto y = read_accessor_as_doubles(b.model, static_cast<int>(i), packed.string());
      REQUIRE(x.size() == y.size());
      if (static_cast<int>(i) != indices) {
        CHECK(std::equal(x.begin(), x.end(), y.begin()));
        continue;
      }
      REQUIRE(x.size() % 3 == 0);
      std::size_t same = 0;
      for (std::size_t t = 0; t < x.size(); t += 3)
        for (int r = 0; r < 3; ++r)
          if (y[t] == x[t + r] && y[t + 1] == x[t + (r + 1) % 3] && y[t + 2] == x[t + (r + 2) % 3]) {
            ++same;
            break;
          }
      CHECK(same == x.size() / 3);
    }
  }
}
