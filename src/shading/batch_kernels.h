// The SIMD batch kernels (shaders_cpu/batch/) behind one entry point, and the choice of which
// prepared lights can use them.
//
// A light's diffuse gets a batch kernel when its model has one: point, spot and directional with
// integer falloff 0..3, linear with integer falloff 0..3 (closed forms), convex area polygons,
// disks. Everything else (real falloff, non-convex polygons) stays on the scalar double kernels;
// batch_kernel_for says why. With specular on, the diffuse keeps its batch kernel and the specular
// is computed beside it (bake/batch_lighting.h): by a batch specular kernel where the model has one
// (point, spot, directional: punctual_specular_batch.h; linear lights' exact specular with the
// inverse-square falloff and integer m: linear_specular_batch.h), else by the scalar double
// kernel, lane by lane. The exact specular of convex area polygons has a batch kernel too
// (area_specular_batch.h, integer m), which the plan does not choose: measured no faster than
// the scalar path, because the lanes its closed form refuses (11 % to 50 % on the benchmark's
// floor) cost the scalar adaptive form either way (docs/performance.md, "Batch specular").
//
// evaluate_diffuse_batch is compiled for AVX-512, AVX2 and baseline x86-64 and picks the variant
// for the running CPU once, at load time (GCC function multiversioning): the release build stays
// portable ("native-free") and still uses the widest vectors the machine has. Results are the
// same bits whichever variant runs (shaders_cpu/batch/batch_points.h, "Determinism").
#pragma once

#include <optional>
#include <string>
#include <variant>

#include "batch/area_diffuse_batch.h"
#include "batch/area_specular_batch.h"
#include "batch/batch_points.h"
#include "batch/disk_diffuse_batch.h"
#include "batch/linear_diffuse_batch.h"
#include "batch/linear_specular_batch.h"
#include "batch/punctual_diffuse_batch.h"
#include "batch/punctual_specular_batch.h"
#include "shading/prepared_light.h"

namespace vlit {

using BatchLight = std::variant<PunctualBatchLight, LinearBatchLight, AreaBatchLight, DiskBatchLight>;

struct BatchChoice {
  std::optional<BatchLight> light;  // the diffuse's batch kernel; empty: the scalar double kernel runs
  std::string reason;               // why not, when empty
  // With specular on and `light` set: whether evaluate_specular_batch computes the specular, else
  // why not (the scalar double kernel does).
  bool specular_batch = false;
  std::string specular_reason;
  // The area light's prepared polygon, for area_specular_batch.h (set with specular_batch).
  std::optional<PreparedAreaLight<double>> area_specular;
};

// Whether the diffuse of `light` can use a float batch kernel under `options`, and its per-light
// constants. The specular (options.with_specular) does not change the choice.
BatchChoice batch_kernel_for(const PreparedLight<double>& light, const ShadeOptions& options);

// Diffuse response (unit intensity, kd = 1, range window included) of one light at lanes
// [begin, end) of `points`, with stiff lanes flagged (BatchOutput). No allocation.
void evaluate_diffuse_batch(const BatchLight& light, const BatchPoints& points, long begin, long end,
                            const BatchOutput& out);

// Gives `choice` (a convex area light's diffuse choice, at most kAreaSpecularBatchMaxVertices
// corners) the batch exact specular of area_specular_batch.h, which batch_kernel_for does not
// choose; false when the light does not qualify. For tests and the benchmark.
bool enable_area_specular_batch(BatchChoice& choice, const PreparedLight<double>& light);

// Whether evaluate_specular_batch computes the specular of `choice`'s light for shininess m (area
// lights: integer m in [0, kAreaSpecularBatchMaxShininess]; linear: integer m in
// [0, kLinearSpecularBatchMaxShininess]; the others: any m).
bool specular_batch_covers(const BatchChoice& choice, double m);

// Specular response (unit intensity, ks = 1, range window included) of the light of `choice`
// (specular_batch_covers(choice, m) true) at lanes [begin, end) of `points` (rx, ry, rz set), with
// shininess m and the specular falloff of `specular`; stiff lanes flagged. No allocation.
void evaluate_specular_batch(const BatchChoice& choice, const SpecularOptions& specular, double m, const BatchPoints& points,
                             long begin, long end, const BatchSpecularOutput& out);

// Which instruction set evaluate_diffuse_batch runs with on this machine ("avx512", "avx2",
// "baseline"), for --explain and the benchmark.
const char* batch_instruction_set();

}  // namespace vlit
