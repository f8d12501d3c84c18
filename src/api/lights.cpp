// The public error type, lights built in code or read from LIGHTS.json, and the settings shared
// by every call. Lights built in code are validated by the LIGHTS.json reader itself (they are
// written as one LIGHTS.json document and parsed), so both ways accept and refuse exactly the same
// lights, with the same messages.
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>
#include <omp.h>

#include "api/api_internal.h"
#include "core/version.h"
#include "io/lights_json.h"

namespace vlit {

const char* library_version() { return kVersion; }

namespace {

std::string format_error(const std::string& input, const std::string& problem, const std::string& where) {
  return (input.empty() ? std::string("<input>") : input) + ": " + (where.empty() ? "" : where + ": ") + problem;
}

nlohmann::json json_of(const Vector3& v) { return nlohmann::json::array({v[0], v[1], v[2]}); }

// The light as a LIGHTS.json object (docs/lights-json.md). Non-finite numbers would become
// null, which the reader refuses as "expected a number"; they are refused before, by name.
nlohmann::json json_of(const Light& light) {
  nlohmann::json j;
  if (!light.name.empty()) j["name"] = light.name;
  j["intensity"] = light.intensity;
  j["color"] = json_of(light.color);
  j["shadows"] = light.casts_shadows;
  switch (light.kind) {
    case LightKind::kPoint:
      j["type"] = "point";
      j["position"] = json_of(light.position);
      j["falloff"] = light.falloff;
      break;
    case LightKind::kDirectional:
      j["type"] = "directional";
      j["direction"] = json_of(light.direction);
      break;
    case LightKind::kSpot:
      j["type"] = "spot";
      j["position"] = json_of(light.position);
      j["direction"] = json_of(light.direction);
      j["falloff"] = light.falloff;
      j["inner_cone_angle"] = light.inner_cone_angle;
      j["outer_cone_angle"] = light.outer_cone_angle;
      break;
    case LightKind::kLinear:
      j["type"] = "linear";
      j["from"] = json_of(light.from);
      j["to"] = json_of(light.to);
      j["falloff"] = light.falloff;
      break;
    case LightKind::kArea: {
      j["type"] = "area";
      nlohmann::json polygon = nlohmann::json::array();
      for (const Vector3& q : light.polygon) polygon.push_back(json_of(q));
      j["polygon"] = polygon;
      j["two_sided"] = light.two_sided;
      break;
    }
    case LightKind::kDisk:
      j["type"] = "disk";
      j["center"] = json_of(light.center);
      j["normal"] = json_of(light.normal);
      j["radius"] = light.radius;
      j["two_sided"] = light.two_sided;
      break;
    default:
      throw Error("lights", "unknown LightKind " + std::to_string(static_cast<int>(light.kind)));
  }
  return j;
}

// The first field of `j` holding a non-finite number, as a JSON pointer below the light; empty if none.
std::string non_finite_field(const nlohmann::json& j, const std::string& pointer) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) return pointer;
  if (j.is_object())
    for (const auto& item : j.items())
      if (std::string p = non_finite_field(item.value(), pointer + "/" + item.key()); !p.empty()) return p;
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i)
      if (std::string p = non_finite_field(j[i], pointer + "/" + std::to_string(i)); !p.empty()) return p;
  return {};
}

}  // namespace

Error::Error(std::string input, std::string problem, std::string where)
    : std::runtime_error(format_error(input, problem, where)),
      input_(std::move(input)), problem_(std::move(problem)), where_(std::move(where)) {}

namespace {

// The part every factory shares: the kind, the emitted intensity and the colour.
Light emitter(LightKind kind, double intensity, const Vector3& color) {
  Light l;
  l.kind = kind;
  l.intensity = intensity;
  l.color = color;
  return l;
}

}  // namespace

Light Light::point(const Vector3& position, double intensity, const Vector3& color) {
  Light l = emitter(LightKind::kPoint, intensity, color);
  l.position = position;
  return l;
}

Light Light::directional(const Vector3& direction, double intensity, const Vector3& color) {
  Light l = emitter(LightKind::kDirectional, intensity, color);
  l.direction = direction;
  return l;
}

Light Light::spot(const Vector3& position, const Vector3& direction, double outer_cone_angle, double intensity,
                  const Vector3& color) {
  Light l = emitter(LightKind::kSpot, intensity, color);
  l.position = position;
  l.direction = direction;
  l.outer_cone_angle = outer_cone_angle;
  return l;
}

Light Light::tube(const Vector3& from, const Vector3& to, double intensity, const Vector3& color) {
  Light l = emitter(LightKind::kLinear, intensity, color);
  l.from = from;
  l.to = to;
  return l;
}

Light Light::panel(std::vector<Vector3> polygon, double intensity, const Vector3& color) {
  Light l = emitter(LightKind::kArea, intensity, color);
  l.polygon = std::move(polygon);
  return l;
}

Light Light::disk(const Vector3& center, const Vector3& normal, double radius, double intensity, const Vector3& color) {
  Light l = emitter(LightKind::kDisk, intensity, color);
  l.center = center;
  l.normal = normal;
  l.radius = radius;
  return l;
}

Lights::Lights() : impl_(std::make_shared<Impl>()) {}
Lights::~Lights() = default;
Lights::Lights(const Lights&) = default;
Lights& Lights::operator=(const Lights&) = default;

Lights Lights::parse_json(const std::string& text, const std::string& name) {
  Lights lights;
  lights.impl_->sources = api::translate_errors(name, [&] { return parse_lights_json(text, name); });
  return lights;
}

Lights Lights::read_json(const std::string& path) {
  Lights lights;
  lights.impl_->sources = api::translate_errors(path, [&] { return read_lights_json(path); });
  return lights;
}

Lights& Lights::add(const Light& light) {
  const std::size_t index = size();
  const std::string pointer = "/lights/" + std::to_string(index);
  nlohmann::json one = json_of(light);
  if (const std::string field = non_finite_field(one, pointer); !field.empty())
    throw Error("lights", "number is not finite", field);
  nlohmann::json document;
  document["lights"] = nlohmann::json::array({one});
  // Parsed alone, the light is /lights/0; its messages must name its place in this list.
  std::vector<LightSource> parsed;
  try {
    parsed = parse_lights_json(document.dump(), "lights");
  } catch (const InputError& e) {
    std::string where = e.where();
    if (where.rfind("/lights/0", 0) == 0) where = pointer + where.substr(9);
    throw Error("lights", e.problem(), where);
  }
  if (light.name.empty()) parsed[0].name = "lights:" + pointer;
  auto copy = std::make_shared<Impl>(*impl_);  // copies made before stay as they were
  copy->sources.push_back(std::move(parsed[0]));
  impl_ = std::move(copy);
  return *this;
}

Lights& Lights::add(const Lights& other) {
  auto copy = std::make_shared<Impl>(*impl_);
  copy->sources.insert(copy->sources.end(), other.impl_->sources.begin(), other.impl_->sources.end());
  impl_ = std::move(copy);
  return *this;
}

std::size_t Lights::size() const { return impl_->sources.size(); }

Light Lights::operator[](std::size_t index) const {
  if (index >= size()) throw std::out_of_range("vlit::Lights: index " + std::to_string(index) + " >= " + std::to_string(size()));
  const LightSource& s = impl_->sources[index];
  Light l;
  l.name = s.name;
  l.color = api::to_vector3(s.color);
  l.intensity = s.intensity;
  l.falloff = s.falloff;
  l.casts_shadows = s.casts_shadows;
  l.position = api::to_vector3(s.position);
  l.direction = api::to_vector3(s.direction);
  l.inner_cone_angle = std::acos(std::clamp(s.cos_inner, -1.0, 1.0));
  l.outer_cone_angle = std::acos(std::clamp(s.cos_outer, -1.0, 1.0));
  l.from = api::to_vector3(s.from);
  l.to = api::to_vector3(s.to);
  for (const Vec3d& q : s.polygon) l.polygon.push_back(api::to_vector3(q));
  l.center = api::to_vector3(s.center);
  l.normal = api::to_vector3(s.normal);
  l.radius = s.radius;
  l.two_sided = s.two_sided;
  switch (s.type) {
    case LightType::kPoint: l.kind = LightKind::kPoint; break;
    case LightType::kDirectional: l.kind = LightKind::kDirectional; break;
    case LightType::kSpot: l.kind = LightKind::kSpot; break;
    case LightType::kLinear: l.kind = LightKind::kLinear; break;
    case LightType::kArea: l.kind = LightKind::kArea; break;
    case LightType::kDisk: l.kind = LightKind::kDisk; break;
  }
  return l;
}

namespace api {

ThreadCount::ThreadCount(int threads) {
  if (threads > 0) {
    saved_ = omp_get_max_threads();
    omp_set_num_threads(threads);
    changed_ = true;
  }
}

ThreadCount::~ThreadCount() {
  if (changed_) omp_set_num_threads(saved_);
}

void check_settings(const Settings& s, const std::string& input) {
  if (s.threads < 0) throw Error(input, "threads must be >= 0 (0 = OpenMP's default)", "settings.threads");
  if (s.specular == Specular::kNeighborhood && (s.neighborhood_samples < 1 || s.neighborhood_samples > 1024))
    throw Error(input, "neighborhood_samples must be in [1, 1024]", "settings.neighborhood_samples");
  if (s.max_vertices == 0) throw Error(input, "max_vertices must be > 0", "settings.max_vertices");
}

ShadeOptions shade_options(const Settings& s) {
  ShadeOptions o;
  switch (s.specular) {
    case Specular::kPeak: o.specular.method = SpecularMethod::kPeak; break;
    case Specular::kNeighborhood: o.specular.method = SpecularMethod::kNeighborhood; break;
    case Specular::kExact: o.specular.method = SpecularMethod::kExact; break;
    case Specular::kNone: o.specular.method = SpecularMethod::kNone; break;
    case Specular::kExactNoFalloff:
      o.specular.method = SpecularMethod::kExact;
      o.specular.falloff = SpecularFalloff::kNone;
      break;
  }
  o.specular.neighborhood_samples = s.neighborhood_samples;
  o.with_specular = o.specular.method != SpecularMethod::kNone;
  return o;
}

SceneLimits scene_limits(const Settings& s) {
  SceneLimits limits;
  limits.max_vertices = s.max_vertices;
  limits.max_emissive_lights = s.max_emissive_lights;
  return limits;
}

bool cancelled(const Settings& s) { return s.cancel && s.cancel->load(); }

}  // namespace api
}  // namespace vlit
