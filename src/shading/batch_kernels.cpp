#include "shading/batch_kernels.h"

#include <cmath>
#include <string>

namespace vlit {
namespace {

bool is_integer_falloff(double n) { return n == 0 || n == 1 || n == 2 || n == 3; }

// Convex and counter-clockwise about the emitting normal: every corner turns the same way.
bool is_convex(const PreparedAreaLight<double>& a) {
  for (int i = 0; i < a.count; ++i) {
    const Vec3d& p = a.d[i];
    const Vec3d& q = a.d[(i + 1) % a.count];
    const Vec3d& r = a.d[(i + 2) % a.count];
    if (dot(cross(q - p, r - q), a.normal) < -1e-12 * a.radius * a.radius) return false;
  }
  return true;
}

}  // namespace

BatchChoice batch_kernel_for(const PreparedLight<double>& light, const ShadeOptions& options) {
  BatchChoice c;
  std::visit(
      [&](const auto& k) {
        using K = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<K, PointLight<double>> || std::is_same_v<K, SpotLight<double>>) {
          if (!is_integer_falloff(k.falloff)) {
            c.reason = "non-integer falloff";
            return;
          }
          PunctualBatchLight b;
          b.kind = std::is_same_v<K, SpotLight<double>> ? PunctualBatchLight::Kind::kSpot : PunctualBatchLight::Kind::kPoint;
          b.position[0] = k.position.x; b.position[1] = k.position.y; b.position[2] = k.position.z;
          b.falloff = int(k.falloff);
          if constexpr (std::is_same_v<K, SpotLight<double>>) {
            b.direction[0] = k.direction.x; b.direction[1] = k.direction.y; b.direction[2] = k.direction.z;
            b.cos_outer = k.cos_outer;
            b.inv_cone_width = 1 / std::max(k.cos_inner - k.cos_outer, 1e-6);
          }
          if (light.range > 0) b.inv_range2 = 1 / (light.range * light.range);
          c.light = b;
        } else if constexpr (std::is_same_v<K, DirectionalLight<double>>) {
          PunctualBatchLight b;
          b.kind = PunctualBatchLight::Kind::kDirectional;
          b.direction[0] = k.direction.x; b.direction[1] = k.direction.y; b.direction[2] = k.direction.z;
          c.light = b;
        } else if constexpr (std::is_same_v<K, LinearLight<double>>) {
          const Vec3d ld = k.q1 - k.q0;
          const double len = length(ld);
          if (options.linear.force_quadrature) c.reason = "quadrature forced";
          else if (!is_integer_falloff(k.falloff)) c.reason = "non-integer falloff";
          else if (!(len > 0) || !std::isfinite(len)) c.reason = "zero-length segment";
          if (!c.reason.empty()) return;
          LinearBatchLight b;
          b.q0[0] = k.q0.x; b.q0[1] = k.q0.y; b.q0[2] = k.q0.z;
          b.q1[0] = k.q1.x; b.q1[1] = k.q1.y; b.q1[2] = k.q1.z;
          b.u[0] = ld.x / len; b.u[1] = ld.y / len; b.u[2] = ld.z / len;
          b.length = len;
          b.inv_length = float(1 / len);
          b.falloff = int(k.falloff);
          c.light = b;
        } else if constexpr (std::is_same_v<K, PreparedAreaLight<double>>) {
          if (k.count > kAreaBatchMaxVertices) c.reason = "too many vertices";
          else if (!is_convex(k)) c.reason = "non-convex polygon";
          if (!c.reason.empty()) return;
          AreaBatchLight b{};
          b.center[0] = k.center.x; b.center[1] = k.center.y; b.center[2] = k.center.z;
          b.normal[0] = k.normal.x; b.normal[1] = k.normal.y; b.normal[2] = k.normal.z;
          for (int i = 0; i < k.count; ++i) {
            b.d[i][0] = k.d[i].x; b.d[i][1] = k.d[i].y; b.d[i][2] = k.d[i].z;
          }
          b.count = k.count;
          b.radius = k.radius;
          b.two_sided = k.two_sided;
          c.light = b;
        } else if constexpr (std::is_same_v<K, PreparedDiskLight<double>>) {
          const PreparedAreaLight<double>& frame = k.inscribed;  // centre, unit normal, u x v = normal
          DiskBatchLight b{};
          for (int i = 0; i < 3; ++i) {
            b.center[i] = frame.center[i];
            b.normal[i] = frame.normal[i];
            b.u[i] = frame.u[i];
            b.v[i] = frame.v[i];
          }
          b.radius = k.radius;
          b.two_sided = frame.two_sided;
          c.light = b;
        } else {
          static_assert(!sizeof(K*), "every light model has a batch kernel or a reason above");
        }
      },
      light.kernel);
  if (c.light && options.with_specular) {
    const auto* area = std::get_if<PreparedAreaLight<double>>(&light.kernel);
    const auto* linear = std::get_if<LinearBatchLight>(&*c.light);
    if (std::holds_alternative<PunctualBatchLight>(*c.light)) {
      c.specular_batch = true;
    } else if (linear && options.specular.method != SpecularMethod::kExact) {
      c.specular_reason = "no batch kernel for this specular method";
    } else if (linear && (linear->falloff != 2 || options.specular.falloff != SpecularFalloff::kAsDiffuse)) {
      c.specular_reason = "batch linear specular needs the inverse-square falloff";
    } else if (linear) {
      c.specular_batch = true;  // linear_specular_batch.h, integer m (specular_batch_covers)
    } else if (area && options.specular.method == SpecularMethod::kExact) {
      // area_specular_batch.h exists and is tested, but measured no faster than the scalar path
      // (docs/performance.md, "Batch specular"): the plan does not choose it.
      c.specular_reason = "batch area specular not faster than scalar";
    } else if (area) {
      c.specular_reason = "no batch kernel for this specular method";
    } else {
      c.specular_reason = "no batch specular kernel for this model";
    }
  }
  return c;
}

// GCC function multiversioning; other compilers (clang in the fuzz preset) get one baseline copy.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define VLIT_BATCH_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"), flatten))
#else
#define VLIT_BATCH_CLONES
#endif

VLIT_BATCH_CLONES
void evaluate_diffuse_batch(const BatchLight& light, const BatchPoints& points, long begin, long end,
                            const BatchOutput& out) {
  if (const auto* p = std::get_if<PunctualBatchLight>(&light)) punctual_diffuse_batch(*p, points, begin, end, out);
  else if (const auto* l = std::get_if<LinearBatchLight>(&light)) linear_diffuse_batch(*l, points, begin, end, out);
  else if (const auto* a = std::get_if<AreaBatchLight>(&light)) area_diffuse_batch(*a, points, begin, end, out);
  else if (const auto* d = std::get_if<DiskBatchLight>(&light)) disk_diffuse_batch(*d, points, begin, end, out);
}

bool enable_area_specular_batch(BatchChoice& choice, const PreparedLight<double>& light) {
  const auto* area = std::get_if<PreparedAreaLight<double>>(&light.kernel);
  if (!choice.light || !area || area->count > kAreaSpecularBatchMaxVertices) return false;
  choice.specular_batch = true;
  choice.area_specular = *area;
  return true;
}

bool specular_batch_covers(const BatchChoice& choice, double m) {
  if (!choice.specular_batch || !choice.light) return false;
  auto integer_up_to = [m](int largest) { return m == std::floor(m) && m >= 0 && m <= largest; };
  if (choice.area_specular) return integer_up_to(kAreaSpecularBatchMaxShininess);
  if (std::holds_alternative<LinearBatchLight>(*choice.light)) return integer_up_to(kLinearSpecularBatchMaxShininess);
  return m >= 0;
}

VLIT_BATCH_CLONES
void evaluate_specular_batch(const BatchChoice& choice, const SpecularOptions& specular, double m, const BatchPoints& points,
                             long begin, long end, const BatchSpecularOutput& out) {
  const bool with_falloff = specular.falloff == SpecularFalloff::kAsDiffuse;
  if (choice.area_specular) area_specular_batch(*choice.area_specular, int(m), points, begin, end, out);
  else if (const auto* l = std::get_if<LinearBatchLight>(&*choice.light)) linear_specular_batch(*l, int(m), points, begin, end, out);
  else if (const auto* p = std::get_if<PunctualBatchLight>(&*choice.light))
    punctual_specular_batch(*p, with_falloff, m, points, begin, end, out);
}

const char* batch_instruction_set() {
#if defined(__GNUC__) && defined(__x86_64__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f")) return "avx512";
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return "avx2";
#endif
  return "baseline";
}

}  // namespace vlit
