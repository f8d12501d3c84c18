// The bake's float batch path: the diffuse of the lights the scene plan gives a float batch kernel
// (shading/batch_kernels.h), over a chunk of vertices; the lanes a kernel flags as stiff are
// recomputed with the scalar double kernel. With specular on, these lights' specular is computed
// here too: by a batch specular kernel where the plan found one (its stiff lanes again by the
// scalar double kernel), else by the scalar double kernel. Used by light_vertices.cpp; everything else stays on
// the scalar path there.
#pragma once

#include <cstdint>
#include <vector>

#include "plan/scene_plan.h"

namespace vlit {

// Scratch for one chunk of shading points as structure of arrays, reused from chunk to chunk.
class BatchChunk {
 public:
  void resize(long count);
  // Copies points [begin, end) (position, unit normal, reflected view direction) into the arrays.
  void fill(const ShadingPoint<double>* points, long begin, long end);
  BatchPoints points() const {
    return {px_.data(), py_.data(), pz_.data(), nx_.data(), ny_.data(), nz_.data(), rx_.data(), ry_.data(), rz_.data()};
  }
  BatchOutput scratch() { return {response_.data(), stiff_.data()}; }
  BatchSpecularOutput specular_scratch() { return {specular_.data(), specular_stiff_.data()}; }
  long count() const { return count_; }

 private:
  long count_ = 0;
  std::vector<double> px_, py_, pz_;
  std::vector<float> nx_, ny_, nz_;
  std::vector<double> rx_, ry_, rz_;  // reflected view direction, for the specular kernels
  std::vector<float> response_;
  std::vector<std::uint8_t> stiff_;
  std::vector<double> specular_;
  std::vector<std::uint8_t> specular_stiff_;
};

// diffuse[v] += radiance * Id(v), and specular[v] += radiance * Is(v) when `specular` is not null,
// for every vertex of the chunk and every light of `lights`
// (indices into plan.lights, each with plan.batch_of_light[i].light set), in that order, all
// cores: a thread takes a block of vertices and lights it with every light, so there is no
// barrier between lights. Diffuse alone: 1024-lane blocks, static schedule. With specular:
// 256-lane blocks handed to the next free thread (dynamic schedule), so that a block made slow by
// the scalar specular, or a busy core, does not hold the others up.
// The result for a vertex does not depend on the number of threads or on the blocks: a lane's
// float result is the same in any vector width (shaders_cpu/batch/batch_points.h).
void accumulate_batch_lights(const ScenePlan& plan, const std::vector<int>& lights, BatchChunk& chunk,
                             const ShadingPoint<double>* points, long count, Vec3d* diffuse, Vec3d* specular);

}  // namespace vlit
