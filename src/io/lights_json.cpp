#include "io/lights_json.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "io/read_file.h"

namespace vlit {
namespace {

using nlohmann::json;

// Walks one light object, checking types and ranges; every error carries the JSON pointer.
class LightReader {
 public:
  LightReader(const json& object, std::string file, std::string pointer)
      : object_(object), file_(std::move(file)), pointer_(std::move(pointer)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(file_, problem, key.empty() ? pointer_ : pointer_ + "/" + key);
  }

  bool has(const std::string& key) {
    used_.insert(key);
    return object_.contains(key);
  }

  double number(const std::string& key, std::optional<double> fallback = std::nullopt) {
    if (!has(key)) {
      if (fallback) return *fallback;
      fail(key, "missing required number");
    }
    const json& v = object_.at(key);
    if (!v.is_number()) fail(key, "expected a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(key, "number is not finite");
    return x;
  }

  Vec3d vec3(const json& v, const std::string& key) const {
    if (!v.is_array() || v.size() != 3) fail(key, "expected an array of 3 numbers");
    Vec3d out;
    double* c[3] = {&out.x, &out.y, &out.z};
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number()) fail(key, "expected an array of 3 numbers");
      *c[i] = v[i].get<double>();
      if (!std::isfinite(*c[i])) fail(key, "coordinate is not finite");
    }
    return out;
  }

  Vec3d vec3(const std::string& key, std::optional<Vec3d> fallback = std::nullopt) {
    if (!has(key)) {
      if (fallback) return *fallback;
      fail(key, "missing required [x, y, z]");
    }
    return vec3(object_.at(key), key);
  }

  bool boolean(const std::string& key, bool fallback) {
    if (!has(key)) return fallback;
    if (!object_.at(key).is_boolean()) fail(key, "expected true or false");
    return object_.at(key).get<bool>();
  }

  std::string string(const std::string& key) {
    if (!has(key)) fail(key, "missing required string");
    if (!object_.at(key).is_string()) fail(key, "expected a string");
    return object_.at(key).get<std::string>();
  }

  std::vector<Vec3d> points(const std::string& key) {
    if (!has(key)) fail(key, "missing required array of [x, y, z] points");
    const json& v = object_.at(key);
    if (!v.is_array()) fail(key, "expected an array of [x, y, z] points");
    std::vector<Vec3d> out;
    for (size_t i = 0; i < v.size(); ++i) out.push_back(vec3(v[i], key + "/" + std::to_string(i)));
    return out;
  }

  void reject_unknown_keys() const {
    for (const auto& item : object_.items())
      if (!used_.count(item.key())) fail(item.key(), "unknown property (check the spelling; see docs/lights-json.md)");
  }

  const std::string& pointer() const { return pointer_; }

 private:
  const json& object_;
  std::string file_, pointer_;
  std::set<std::string> used_;
};

Vec3d unit_or_fail(LightReader& r, const std::string& key, const Vec3d& v) {
  const double len = length(v);
  if (!(len > 0)) r.fail(key, "direction has zero length");
  return v / len;
}

// How far a vertex of an area light may lie off its plane, relative to the polygon's size (the
// diagonal of its bounding box): docs/lights-json.md.
constexpr double kPlanarTolerance = 1e-6;

// Checks that a polygon is a usable planar emitter: >= 3 vertices, non-zero area, planar.
void validate_polygon(LightReader& r, const std::vector<Vec3d>& polygon) {
  if (polygon.size() < 3) r.fail("polygon", "an area light needs at least 3 vertices");
  // Newell's normal: robust for non-convex polygons; its length is twice the area.
  Vec3d newell;
  Vec3d extent_lo = polygon[0], extent_hi = polygon[0];
  for (size_t i = 0; i < polygon.size(); ++i) {
    newell += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    extent_lo = min(extent_lo, polygon[i]);
    extent_hi = max(extent_hi, polygon[i]);
  }
  const double twice_area = length(newell);
  const double size = length(extent_hi - extent_lo);
  if (!(twice_area > 0) || !(twice_area > 1e-300)) r.fail("polygon", "polygon has zero area");
  const Vec3d n = newell / twice_area;
  // Offsets from the plane through the first vertex with Newell's normal.
  double max_offset = 0;
  std::size_t worst = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const double offset = std::abs(dot(polygon[i] - polygon[0], n));
    if (offset > max_offset) max_offset = offset, worst = i;
  }
  const double tolerance = kPlanarTolerance * size;
  if (max_offset > tolerance) {
    char text[240];
    std::snprintf(text, sizeof text,
                  "polygon is not planar: vertex %zu is %.3g off the plane of the polygon, more than the tolerance %.3g "
                  "(%g x its size %.3g)", worst, max_offset, tolerance, kPlanarTolerance, size);
    r.fail("polygon", text);
  }
}

LightSource read_light(const json& object, const std::string& file, const std::string& pointer) {
  if (!object.is_object()) throw InputError(file, "expected a light object", pointer);
  LightReader r(object, file, pointer);
  LightSource light;
  light.name = file + ":" + pointer;
  if (r.has("name")) light.name = r.string("name");
  const std::string type = r.string("type");
  light.intensity = r.number("intensity", 1.0);
  if (light.intensity < 0) r.fail("intensity", "intensity must be >= 0");
  light.color = r.vec3("color", Vec3d{1, 1, 1});
  light.casts_shadows = r.boolean("shadows", true);
  if (light.color.x < 0 || light.color.y < 0 || light.color.z < 0) r.fail("color", "color components must be >= 0");

  // Any real n in [0, 3] for every type with a falloff (docs/lights-json.md); integer ones get
  // the closed forms, the others quadrature (the scene plan chooses).
  auto read_falloff = [&] {
    light.falloff = r.number("falloff", 2.0);
    if (light.falloff < 0 || light.falloff > 3) r.fail("falloff", "falloff must be in [0, 3]");
  };

  if (type == "point") {
    light.type = LightType::kPoint;
    light.position = r.vec3("position");
    read_falloff();
  } else if (type == "directional") {
    light.type = LightType::kDirectional;
    light.direction = unit_or_fail(r, "direction", r.vec3("direction"));
  } else if (type == "spot") {
    light.type = LightType::kSpot;
    light.position = r.vec3("position");
    light.direction = unit_or_fail(r, "direction", r.vec3("direction"));
    read_falloff();
    const double outer = r.number("outer_cone_angle", M_PI / 4);
    const double inner = r.number("inner_cone_angle", 0.0);
    if (!(outer > 0 && outer <= M_PI / 2)) r.fail("outer_cone_angle", "must be in (0, pi/2] radians");
    if (!(inner >= 0 && inner <= outer)) r.fail("inner_cone_angle", "must be in [0, outer_cone_angle] radians");
    light.cos_inner = std::cos(inner);
    light.cos_outer = std::cos(outer);
  } else if (type == "linear") {
    light.type = LightType::kLinear;
    light.from = r.vec3("from");
    light.to = r.vec3("to");
    read_falloff();
  } else if (type == "area") {
    light.type = LightType::kArea;
    light.polygon = r.points("polygon");
    light.two_sided = r.boolean("two_sided", false);
    validate_polygon(r, light.polygon);
  } else if (type == "disk") {
    light.type = LightType::kDisk;
    light.center = r.vec3("center");
    light.normal = unit_or_fail(r, "normal", r.vec3("normal"));
    light.radius = r.number("radius");
    if (!(light.radius > 0)) r.fail("radius", "radius must be > 0");
    light.two_sided = r.boolean("two_sided", false);
  } else {
    r.fail("type", "unknown light type \"" + type + "\" (expected point, directional, spot, linear, area or disk)");
  }
  r.reject_unknown_keys();
  return light;
}

}  // namespace

std::vector<LightSource> parse_lights_json(const std::string& text, const std::string& name) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    // e.byte is the 1-based offset of the error; turn it into a line number for humans.
    const size_t byte = std::min<size_t>(e.byte, text.size());
    const long line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(byte ? byte - 1 : 0), '\n');
    throw InputError(name, "invalid JSON: " + std::string(e.what()), "line " + std::to_string(line));
  } catch (const json::exception& e) {
    // Not a syntax error but still a bad file, e.g. out_of_range 406 for a number beyond double
    // (found by fuzz/fuzz_lights_json.cpp; it escaped as a message without the file name).
    throw InputError(name, "invalid JSON: " + std::string(e.what()));
  }
  if (!root.is_object() || !root.contains("lights") || !root.at("lights").is_array())
    throw InputError(name, "expected an object with a \"lights\" array");
  for (const auto& item : root.items())
    if (item.key() != "lights") throw InputError(name, "unknown property", "/" + item.key());
  std::vector<LightSource> lights;
  const json& array = root.at("lights");
  for (size_t i = 0; i < array.size(); ++i)
    lights.push_back(read_light(array[i], name, "/lights/" + std::to_string(i)));
  return lights;
}

std::vector<LightSource> read_lights_json(const std::string& path) {
  return parse_lights_json(read_text_file(path), path);
}

}  // namespace vlit
