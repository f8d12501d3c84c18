#include "plan/scene_plan.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/input_error.h"
#include "core/robust_math.h"
#include "plan/shadow_plan.h"
#include "scene/material.h"

namespace vlit {
namespace {

struct Bounds {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  bool empty() const { return lo.x > hi.x; }
  Vec3d center() const { return (lo + hi) * 0.5; }
  double radius() const { return 0.5 * length(hi - lo); }
  Vec3d corner(int i) const { return {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z}; }
};

Bounds bounds_of(const ScenePrimitive& p) {
  Bounds b;
  for (const Vec3d& v : p.positions) {
    b.lo = min(b.lo, v);
    b.hi = max(b.hi, v);
  }
  return b;
}

// Unit normal of the emitting side of a one-sided area light (Newell's normal of the polygon,
// counter-clockwise seen from the side it emits to) and a point on its plane.
std::pair<Vec3d, Vec3d> emitter_plane(const LightSource& l) {
  if (l.type == LightType::kDisk) return {normalize(l.normal), l.center};
  Vec3d newell;
  for (std::size_t i = 0; i < l.polygon.size(); ++i) newell += cross(l.polygon[i], l.polygon[(i + 1) % l.polygon.size()]);
  return {normalize(newell), l.polygon[0]};
}

// Why the light cannot reach primitive `p` (bounding box b), or empty if it may.
std::string cannot_reach(const LightSource& l, std::size_t p, const Bounds& b) {
  if (b.empty()) return "no vertices";
  if (l.emitting_primitive >= 0 && static_cast<std::size_t>(l.emitting_primitive) == p)
    return "the light is this primitive's own emission";
  if ((l.type == LightType::kArea || l.type == LightType::kDisk) && !l.two_sided) {
    const auto [n, q] = emitter_plane(l);
    bool any_in_front = false;
    for (int i = 0; i < 8 && !any_in_front; ++i) any_in_front = dot(b.corner(i) - q, n) > 0;
    if (!any_in_front) return "the box is behind the emitting side";
  }
  if (l.range && (l.type == LightType::kPoint || l.type == LightType::kSpot)) {
    if (length(b.center() - l.position) - b.radius() >= *l.range) return "beyond the light's range";
  }
  if (l.type == LightType::kSpot) {
    // The bounding sphere misses the cone if the angle from the axis to the sphere's centre,
    // minus the sphere's angular radius, exceeds the outer cone angle.
    const Vec3d to_center = b.center() - l.position;
    const double dist = length(to_center);
    if (dist > b.radius()) {
      const double angle_to_center = angle_between(to_center, l.direction);
      const double angular_radius = std::asin(std::min(1.0, b.radius() / dist));
      if (angle_to_center - angular_radius > std::acos(std::clamp(l.cos_outer, -1.0, 1.0))) return "outside the spot cone";
    }
  }
  return {};
}

// The per-vertex tests behind no_vertex_reached, each a condition under which every kernel gives
// exactly 0 (not merely little): a skipped pair then changes no bit of a bake.
enum VertexMiss : unsigned {
  kBehindEmitter = 1,  // one-sided area or disk light: the vertex is behind its emitting side
  kOutOfRange = 2,     // glTF range: the range window is 0 at and beyond it
  kOutsideCone = 4,    // spot: s = 0 outside the outer cone
  kFacingAway = 8,     // horizon clipping: the whole light is below the vertex's tangent plane
};
constexpr const char* kMissWords[] = {"behind the emitting side", "beyond the light's range", "outside the spot cone",
                                      "facing away from the light"};

// Rounding margin, relative to the distances involved: a vertex within it of a boundary counts as
// reached, so the kernel's own rounding can never make it lit after the plan skipped it.
constexpr double kMissMargin = 1e-9;

// Which tests vertex (p, n) fails for light l; 0 when it may receive light. Comparisons are
// written so that a NaN fails none of them (non-finite input is never skipped here).
unsigned vertex_misses(const LightSource& l, const Vec3d& p, const Vec3d& n) {
  unsigned miss = 0;
  auto below = [&](double value, double scale) { return value < -kMissMargin * scale; };
  switch (l.type) {
    case LightType::kPoint:
    case LightType::kSpot: {
      const Vec3d to_light = l.position - p;
      const double d = length(to_light);
      if (below(dot(n, to_light), d)) miss |= kFacingAway;
      if (l.range && d * d > *l.range * *l.range * (1 + kMissMargin)) miss |= kOutOfRange;
      if (l.type == LightType::kSpot && d > 0 && dot(-to_light, l.direction) / d < l.cos_outer - kMissMargin)
        miss |= kOutsideCone;
      break;
    }
    case LightType::kDirectional:
      if (below(-dot(n, l.direction), 1.0)) miss |= kFacingAway;
      break;
    case LightType::kLinear:
      if (below(dot(n, l.from - p), length(l.from - p)) && below(dot(n, l.to - p), length(l.to - p))) miss |= kFacingAway;
      break;
    case LightType::kArea: {
      bool all_below = true;
      for (const Vec3d& q : l.polygon) all_below = all_below && below(dot(n, q - p), length(q - p));
      if (all_below) miss |= kFacingAway;
      if (!l.two_sided) {
        const auto [plane_normal, q] = emitter_plane(l);
        if (below(dot(p - q, plane_normal), length(p - q))) miss |= kBehindEmitter;
      }
      break;
    }
    case LightType::kDisk: {
      const Vec3d axis = normalize(l.normal);
      const double along = dot(n, axis);
      // The highest point of the disk above the tangent plane: centre plus radius along n's
      // component in the disk's plane.
      const double highest = dot(n, l.center - p) + l.radius * std::sqrt(std::max(0.0, 1 - along * along));
      if (below(highest, length(l.center - p) + l.radius)) miss |= kFacingAway;
      if (!l.two_sided && below(dot(p - l.center, axis), length(p - l.center) + l.radius)) miss |= kBehindEmitter;
      break;
    }
  }
  return miss;
}

// Why light l reaches no vertex of primitive `prim` ("every vertex behind the emitting side or
// facing away from the light"), or empty if some vertex may receive its light.
std::string no_vertex_reached(const LightSource& l, const ScenePrimitive& prim) {
  unsigned seen = 0;
  for (std::size_t v = 0; v < prim.positions.size(); ++v) {
    const unsigned miss = vertex_misses(l, prim.positions[v], v < prim.normals.size() ? prim.normals[v] : Vec3d{});
    if (miss == 0) return {};
    seen |= miss;
  }
  std::string why = "every vertex";
  const char* joint = " ";
  for (unsigned bit = 0; bit < 4; ++bit)
    if (seen & (1u << bit)) {
      why += joint;
      why += kMissWords[bit];
      joint = " or ";
    }
  return why;
}

const char* diffuse_kernel(const LightSource& l, const ShadeOptions& o) {
  switch (l.type) {
    case LightType::kPoint: return "point (eq. 1)";
    case LightType::kDirectional: return "directional";
    case LightType::kSpot: return "spot (point x cone)";
    case LightType::kLinear: {
      const bool integer = l.falloff == std::round(l.falloff);
      return integer && !o.linear.force_quadrature ? "linear closed form (eq. 4)" : "linear adaptive quadrature (eq. 4)";
    }
    case LightType::kArea: return "area contour integral (eq. 9)";
    case LightType::kDisk: return "disk contour integral, closed form (eq. 9)";
  }
  return "?";
}

const char* specular_kernel(const ShadeOptions& o) {
  if (!o.with_specular) return "none";
  switch (o.specular.method) {
    case SpecularMethod::kNone: return "none";
    case SpecularMethod::kPeak: return "peak";
    case SpecularMethod::kNeighborhood: return "neighborhood";
    case SpecularMethod::kExact:
      return o.specular.falloff == SpecularFalloff::kAsDiffuse ? "exact" : "exact-no-falloff";
  }
  return "?";
}

}  // namespace

ScenePlan make_scene_plan(const Scene& scene, const PlanOptions& options) {
  ScenePlan plan;
  plan.shade = options.shade;
  plan.shade.with_specular = options.shade.with_specular && options.has_eye &&
                             options.shade.specular.method != SpecularMethod::kNone;
  if (!plan.shade.with_specular) plan.shade.specular.method = SpecularMethod::kNone;

  std::vector<const LightSource*> kept;
  for (std::size_t li = 0; li < scene.lights.size(); ++li) {
    const LightSource& l = scene.lights[li];
    const Vec3d radiance = l.color * l.intensity;
    if (!(radiance.x > 0 || radiance.y > 0 || radiance.z > 0)) {
      plan.skipped.add("zero intensity or colour", [&] { return "light " + l.name; });
      continue;
    }
    try {
      plan.lights.push_back(prepare_light<double>(l));
    } catch (const std::invalid_argument& e) {  // a light the kernel cannot use: name it
      throw InputError(l.name, e.what());
    }
    plan.source_of_light.push_back(li);
    if (options.float_batch) plan.batch_of_light.push_back(batch_kernel_for(plan.lights.back(), plan.shade));
    else plan.batch_of_light.push_back({std::nullopt, "double precision requested", false, "", std::nullopt});
    kept.push_back(&l);
  }

  plan.lights_of_primitive.resize(scene.primitives.size());
  std::vector<std::vector<std::string>> misses(kept.size());  // per light: its distinct skip reasons
  bool any_vertex = false;
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Bounds b = bounds_of(scene.primitives[p]);
    any_vertex = any_vertex || !b.empty();
    for (std::size_t i = 0; i < kept.size(); ++i) {
      ++plan.pairs_total;
      // The box first (cheap, whole primitives), then the vertices (the first reached one ends it).
      std::string why = cannot_reach(*kept[i], p, b);
      if (why.empty()) why = no_vertex_reached(*kept[i], scene.primitives[p]);
      if (why.empty()) {
        plan.lights_of_primitive[p].push_back(static_cast<int>(i));
        ++plan.pairs_kept;
      } else {
        plan.skipped.add(why, [&] { return "light " + kept[i]->name + " x primitive " + std::to_string(p); });
        if (std::find(misses[i].begin(), misses[i].end(), why) == misses[i].end()) misses[i].push_back(why);
      }
    }
  }
  // A light that lights nothing at all is named with every reason it was skipped.
  std::vector<char> reaches(kept.size(), 0);
  for (const auto& lights : plan.lights_of_primitive)
    for (int i : lights) reaches[static_cast<std::size_t>(i)] = 1;
  for (std::size_t i = 0; i < kept.size() && any_vertex; ++i) {
    if (reaches[i]) continue;
    std::string why;
    for (const std::string& m : misses[i]) why += (why.empty() ? "" : "; ") + m;
    plan.unreached.emplace_back(i, why);
  }
  plan_shadows(scene, kept, options.shadows, plan);
  return plan;
}

std::string describe(const ScenePlan& plan, const Scene& scene) {
  std::ostringstream s;
  s << "plan: " << plan.lights.size() << " lights, " << scene.primitives.size() << " primitives, "
    << scene.vertex_count() << " vertices; " << plan.pairs_kept << " of " << plan.pairs_total
    << " light x primitive pairs lit\n";
  s << "plan: specular " << specular_kernel(plan.shade) << "\n";
  if (!plan.shadows_requested) {
    s << "plan: shadows off\n";
  } else {
    s << "plan: shadows on for " << plan.shadowed_pairs << " of " << plan.pairs_kept << " lit pairs";
    if (plan.needs_occluders)
      s << "; BVH over " << plan.occluder_triangles << " triangles; area lights: visible part from "
        << (plan.shade.area_shadows == AreaShadowMethod::kSilhouette ? "silhouette edges" : "triangle cuts")
        << "; linear lights: visible intervals from "
        << (plan.shade.linear_shadows == LinearShadowMethod::kSilhouette ? "silhouette edges" : "triangle intervals");
    else s << "; no BVH (nothing can occlude)";
    s << "\n";
  }
  for (std::size_t i = 0; i < plan.lights.size(); ++i) {
    const LightSource& l = scene.lights[plan.source_of_light[i]];
    const BatchChoice& batch = plan.batch_of_light[i];
    // The light's vertices, those on shadowed pairs, and those of unshadowed pairs whose material's
    // shininess the batch specular kernel does not cover (bake/batch_lighting.cpp).
    std::size_t vertices = 0, shadowed = 0, specular_scalar = 0;
    for (std::size_t p = 0; p < scene.primitives.size(); ++p)
      for (std::size_t k = 0; k < plan.lights_of_primitive[p].size(); ++k)
        if (static_cast<std::size_t>(plan.lights_of_primitive[p][k]) == i) {
          const std::size_t n = scene.primitives[p].positions.size();
          vertices += n;
          if (plan.shadowed_of_primitive[p][k]) shadowed += n;
          else if (batch.specular_batch &&
                   !specular_batch_covers(batch, phong_from_metallic_roughness(scene.material_of(scene.primitives[p])).shininess))
            specular_scalar += n;
        }
    s << "plan: light " << l.name << ": " << diffuse_kernel(l, plan.shade) << ", " << vertices << " vertices, ";
    // Shadowed pairs run the scalar shadowed path for diffuse and specular (bake/light_vertices.cpp).
    if (vertices > 0 && shadowed == vertices) {
      s << "scalar double (shadowed: the visible part of the light, eq. 10)\n";
      continue;
    }
    if (batch.light) s << "float SIMD batch (" << batch_instruction_set() << ")";
    else s << "scalar double (" << batch.reason << ")";
    // The specular's path, beside the diffuse's (bake/batch_lighting.h).
    if (plan.shade.with_specular) {
      s << "; specular " << specular_kernel(plan.shade) << ": ";
      if (batch.specular_batch && specular_scalar == 0) s << "double SIMD batch (" << batch_instruction_set() << ")";
      else if (batch.specular_batch && specular_scalar == vertices - shadowed)
        s << "scalar double (no batch kernel for the materials' shininess)";
      else if (batch.specular_batch)
        s << "double SIMD batch (" << batch_instruction_set() << "), scalar double for " << specular_scalar
          << " vertices (no batch kernel for their materials' shininess)";
      else if (batch.light) s << "scalar double (" << batch.specular_reason << ")";
      else s << "scalar double";
    }
    if (shadowed > 0) s << "; " << shadowed << " of them shadowed: scalar double (eq. 10)";
    s << "\n";
  }
  for (const std::string& line : unreached_light_warnings(plan, scene)) s << "plan: " << line << "\n";
  for (const std::string& line : plan.skipped.details) s << "plan: skipped " << line << "\n";
  if (plan.skipped.total > plan.skipped.details.size()) {
    s << "plan: ... and " << plan.skipped.total - plan.skipped.details.size() << " more skipped; all "
      << plan.skipped.total << " by reason:";
    for (const auto& [reason, count] : plan.skipped.reasons) s << " " << reason << " (" << count << ");";
    s << "\n";
  }
  return s.str();
}

std::vector<std::string> unreached_light_warnings(const ScenePlan& plan, const Scene& scene) {
  std::vector<std::string> out;
  for (const auto& [i, why] : plan.unreached) {
    const LightSource& l = scene.lights[plan.source_of_light[i]];
    std::string line = "light " + l.name + " reaches no vertex: " + why;
    if (why.find("emitting side") != std::string::npos)
      line += " (it emits toward the side from which its polygon runs counter-clockwise; reverse the polygon or make it two-sided)";
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace vlit
