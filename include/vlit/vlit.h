// vlit as a library: per-vertex lighting of triangle meshes with point, directional, spot, linear
// (tube), area (panel) and disk lights, baked into glTF COLOR_0, measured at points, or rendered.
//
// This header is the whole public API (docs/library.md). It needs C++17 and tinygltf's header;
// nothing else of vlit's internals is visible. Every call:
//   - is reentrant: no globals; the only state is in its arguments;
//   - reports bad input by throwing vlit::Error naming the input (a file path, the `name` given
//     for an in-memory model, or "lights" for lights built in code) and the place in it;
//   - stops early when Settings::cancel becomes true, throwing vlit::Cancelled and leaving its
//     outputs untouched;
//   - runs on Settings::threads OpenMP threads (0 = OpenMP's default: OMP_NUM_THREADS or all
//     cores); results do not depend on the thread count.
// Defaults are those of the command line (`vlit bake|render|probe --help`).
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace vlit {

// The library's version, "MAJOR.MINOR.PATCH" (the same as `vlit --version`).
const char* library_version();

using Vector3 = std::array<double, 3>;  // x, y, z (world space, glTF's units) or linear R, G, B

// ---------------------------------------------------------------------------------------------
// Errors

// Bad input: "INPUT: [WHERE: ]PROBLEM" in what(), and each part on its own.
class Error : public std::runtime_error {
 public:
  Error(std::string input, std::string problem, std::string where = {});
  const std::string& input() const { return input_; }      // file path or in-memory name
  const std::string& where() const { return where_; }      // e.g. "/lights/2/radius", may be empty
  const std::string& problem() const { return problem_; }

 private:
  std::string input_, problem_, where_;
};

// Settings::cancel was set: the call stopped and changed nothing it was given.
class Cancelled : public Error {
 public:
  explicit Cancelled(std::string input) : Error(std::move(input), "cancelled") {}
};

// ---------------------------------------------------------------------------------------------
// Lights (docs/lights-json.md gives each field's meaning, units and valid range)

enum class LightKind { kPoint, kDirectional, kSpot, kLinear, kArea, kDisk };

struct Light {
  LightKind kind = LightKind::kPoint;
  std::string name;                 // for messages; empty = its index
  Vector3 color{1, 1, 1};           // linear RGB, >= 0
  double intensity = 1;             // >= 0; per unit of the segment parameter (linear), radiance (area, disk)
  double falloff = 2;               // distance exponent n: [0, 3] (point, spot); 0, 1, 2 or 3 (linear)
  bool casts_shadows = true;        // hidden by the scene's triangles when shadows are on

  Vector3 position{0, 0, 0};        // point, spot
  Vector3 direction{0, 0, -1};      // directional, spot: the direction light travels (any length > 0)
  double inner_cone_angle = 0;      // spot, radians: [0, outer]
  double outer_cone_angle = 0.78539816339744831;  // spot, radians: (0, pi/2]

  Vector3 from{0, 0, 0}, to{0, 0, 0};  // linear: the segment

  std::vector<Vector3> polygon;     // area: >= 3 coplanar vertices, counter-clockwise seen from the lit side
  Vector3 center{0, 0, 0};          // disk
  Vector3 normal{0, 0, 1};          // disk: the side it lights
  double radius = 1;                // disk, > 0
  bool two_sided = false;           // area, disk

  static Light point(const Vector3& position, double intensity, const Vector3& color = {1, 1, 1});
  static Light directional(const Vector3& direction, double intensity, const Vector3& color = {1, 1, 1});
  static Light spot(const Vector3& position, const Vector3& direction, double outer_cone_angle, double intensity,
                    const Vector3& color = {1, 1, 1});
  static Light tube(const Vector3& from, const Vector3& to, double intensity, const Vector3& color = {1, 1, 1});
  static Light panel(std::vector<Vector3> polygon, double intensity, const Vector3& color = {1, 1, 1});
  static Light disk(const Vector3& center, const Vector3& normal, double radius, double intensity,
                    const Vector3& color = {1, 1, 1});
};

// A validated list of lights, ready to use. Copies are cheap (shared, immutable contents).
class Lights {
 public:
  Lights();
  ~Lights();
  Lights(const Lights&);
  Lights& operator=(const Lights&);

  // LIGHTS.json text (name stands for the file in errors) or file; throws Error on any problem.
  static Lights parse_json(const std::string& text, const std::string& name = "<lights.json>");
  static Lights read_json(const std::string& path);

  // Validates like LIGHTS.json does; throws Error("lights", ..., "/lights/INDEX/FIELD") naming
  // the offending field. Returns *this for chaining.
  Lights& add(const Light& light);
  Lights& add(const Lights& other);

  std::size_t size() const;
  bool empty() const { return size() == 0; }
  Light operator[](std::size_t index) const;  // a description (spot angles from their cosines)

  struct Impl;                                  // not part of the API (src/api/)
  const Impl& impl() const { return *impl_; }   // not part of the API

 private:
  std::shared_ptr<Impl> impl_;
};

// ---------------------------------------------------------------------------------------------
// Settings shared by every call

// --specular: kExact is the definition (docs/conventions.md), kExactNoFalloff the paper's eq. 6
// without the distance falloff, kPeak / kNeighborhood the lobe's maximum (fast modes).
enum class Specular { kPeak, kNeighborhood, kExact, kNone, kExactNoFalloff };

struct Settings {
  int threads = 0;                                   // OpenMP threads; 0 = OpenMP's default
  const std::atomic<bool>* cancel = nullptr;         // polled between chunks of vertices; may be null
  // (vertices done, vertices total), on the calling thread between chunks; may be empty.
  std::function<void(std::size_t, std::size_t)> progress;
  Specular specular = Specular::kExact;              // specular method (see Specular)
  int neighborhood_samples = 4;                      // K of kNeighborhood, [1, 1024]
  bool shadows = false;                              // --shadows on (docs/shadows.md)
  bool file_lights = true;                           // use the lights stored in the model (not --no-file-lights)
  std::size_t max_vertices = 50'000'000;             // --max-vertices
  std::size_t max_emissive_lights = 64;              // --max-emissive-lights
};

// ---------------------------------------------------------------------------------------------
// Models: glTF (or a mesh file turned into glTF) held as a tinygltf::Model

// Reads .gltf/.glb (images are kept undecoded, no network), or an OBJ, PLY, OFF or STL mesh as a
// new glTF document. Warnings (skipped primitives, ...) are appended to `warnings` when given.
tinygltf::Model load_model(const std::string& path, std::vector<std::string>* warnings = nullptr);

// Writes .glb or .gltf (by the extension of `path`) atomically. `read_from` is the file the model
// was loaded from, so that relative image URIs stay valid; empty = the output's directory.
void save_model(const tinygltf::Model& model, const std::string& path, const std::string& read_from = {});

// ---------------------------------------------------------------------------------------------
// Bake: light every vertex and store it in a vertex colour attribute (docs/gltf-output.md)

enum class ColorEncoding { kUnorm16, kUnorm8, kFloat };  // --color-format
enum class ExistingColors { kReplace, kMultiply };       // --mode

struct BakeSettings : Settings {
  std::string target = "COLOR_0";                  // --target: COLOR_n or an application-specific _NAME
  ColorEncoding encoding = ColorEncoding::kUnorm16;
  ExistingColors existing = ExistingColors::kReplace;
  double exposure = 1;                             // > 0
  bool mark_unlit = true;                          // add KHR_materials_unlit (not --no-unlit)
  std::optional<Vector3> specular_eye;             // --specular-eye: also bake the specular seen from here
};

struct BakeSummary {
  std::size_t vertices = 0, lights = 0;
  std::size_t clipped_vertices = 0;                // a channel above 1 clamped (unorm encodings)
  double max_quantization_error = 0;
  std::size_t replaced_attributes = 0;             // primitives whose target attribute existed
  std::size_t duplicated_meshes = 0;               // meshes copied so each instance has its own light
  std::vector<std::string> warnings;               // one line each, prefixed with the input's name
};

// Lights `model` (its own lights unless !settings.file_lights, plus `lights`) and writes the light
// into it. `name` stands for the model in errors and warnings. On an exception the model is as it was.
BakeSummary bake(tinygltf::Model& model, const Lights& lights, const BakeSettings& settings = {},
                 const std::string& name = "<model>");

// `vlit bake INPUT -o OUTPUT`: read, bake, write atomically; never overwrites the input.
BakeSummary bake_asset(const std::string& input, const std::string& output, const Lights& lights,
                       const BakeSettings& settings = {});

// ---------------------------------------------------------------------------------------------
// Plain arrays: meshes that are not glTF, lit in memory

// A metallic-roughness material (glTF's defaults), mapped to Phong as in docs/conventions.md.
struct SurfaceMaterial {
  Vector3 base_color{1, 1, 1};  // linear RGB
  double metallic = 1, roughness = 1;
  bool double_sided = false;
};

struct Mesh {
  std::vector<Vector3> positions;            // world space
  std::vector<Vector3> normals;              // one per position, unit; empty = computed from triangles
  std::vector<std::uint32_t> triangles;      // 3 indices each, counter-clockwise front faces
  SurfaceMaterial material;
  std::string name;                          // for errors; empty = "meshes[INDEX]"
};

// Light per vertex before the material (kd = ks = 1), linear RGB.
struct VertexLighting {
  std::vector<std::array<float, 3>> diffuse;   // one per position
  std::vector<std::array<float, 3>> specular;  // one per position when an eye was given, else empty
};

// One VertexLighting per mesh. With `eye`, the specular seen from it is computed too.
std::vector<VertexLighting> light_meshes(const std::vector<Mesh>& meshes, const Lights& lights,
                                      const Settings& settings = {}, const std::optional<Vector3>& eye = {});

// ---------------------------------------------------------------------------------------------
// Probe: the light meter of `vlit probe` at arbitrary points (kd = ks = 1, colours ignored, each
// light weighted by its scalar intensity)

struct SurfacePoint {
  Vector3 position{0, 0, 0};
  Vector3 normal{0, 0, 1};    // any length > 0
  Vector3 eye{0, 0, 1};       // for the specular
  double shininess = 1;       // Phong exponent m, >= 0
};

struct ProbeValue {
  double diffuse = 0, specular = 0;
};

enum class Precision { kDouble, kFloat };  // --precision

struct ProbeSettings : Settings {
  Precision precision = Precision::kDouble;
};

// One value per point. `occluders` (with settings.shadows) hide the lights that cast shadows;
// shadows need Precision::kDouble.
std::vector<ProbeValue> probe(const std::vector<SurfacePoint>& points, const Lights& lights,
                              const ProbeSettings& settings = {}, const std::vector<Mesh>& occluders = {});

// ---------------------------------------------------------------------------------------------
// Render: light, then rasterize with Gouraud shading into a linear-RGB image in memory

struct View {                 // a perspective camera
  Vector3 eye{0, 0, 5};
  Vector3 target{0, 0, 0};
  Vector3 up{0, 1, 0};
  double yfov = 0.8;          // radians, (0, pi)
};

struct RenderSettings : Settings {
  int width = 800, height = 600;   // pixels
  int samples = 4;                 // per pixel: 1, 4, 9, ..., 64
  Vector3 background{0, 0, 0};     // linear RGB
  bool cull_back_faces = false;
  std::optional<View> view;        // empty = the model's first camera, else a 3/4 view of the scene
};

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // linear RGB, 3 per pixel, rows top to bottom
};

Image render(const tinygltf::Model& model, const Lights& lights, const RenderSettings& settings = {},
             const std::string& name = "<model>");
Image render(const std::vector<Mesh>& meshes, const Lights& lights, const RenderSettings& settings = {});

// 8-bit sRGB, 3 bytes per pixel, after multiplying by `exposure` (--exposure).
std::vector<std::uint8_t> to_srgb8(const Image& image, double exposure = 1);
// Writes to_srgb8(image, exposure) as a PNG, atomically; throws Error(path, ...) on failure.
void save_png(const Image& image, const std::string& path, double exposure = 1);

}  // namespace vlit
