// The bake's float batch path: one light's diffuse over a chunk of vertices with a float SIMD
// batch kernel (shading/batch_kernels.h), the lanes a kernel flags as stiff recomputed with the
// scalar double kernel. Used by light_vertices.cpp for the lights the scene plan gives a batch
// kernel (diffuse only); everything else stays on the scalar path there.
#pragma once

#include <cstdint>
#include <vector>

#include "shading/batch_kernels.h"

namespace vlit {

// A chunk of shading points as structure of arrays, plus the per-lane scratch of one light.
class BatchChunk {
 public:
  // Copies `count` shading points (position, unit normal) into the arrays.
  void fill(const ShadingPoint<double>* points, long count);
  BatchPoints points() const { return {px_.data(), py_.data(), pz_.data(), nx_.data(), ny_.data(), nz_.data()}; }
  BatchOutput scratch() { return {response_.data(), stiff_.data()}; }
  long count() const { return count_; }

 private:
  long count_ = 0;
  std::vector<double> px_, py_, pz_;
  std::vector<float> nx_, ny_, nz_;
  std::vector<float> response_;
  std::vector<std::uint8_t> stiff_;
};

// diffuse[v] += radiance * Id(v) for every vertex of the chunk, all cores. `points` are the same
// shading points the chunk was filled from (for the stiff lanes). The result for a vertex does not
// depend on the number of threads: work is split in whole blocks and a lane's float result is the
// same in any vector width (shaders_cpu/batch/batch_points.h).
void accumulate_light_batch(const PreparedLight<double>& light, const BatchLight& batch, const ShadeOptions& options,
                            BatchChunk& chunk, const ShadingPoint<double>* points, Vec3d* diffuse);

}  // namespace vlit
