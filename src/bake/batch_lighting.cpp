#include "bake/batch_lighting.h"

#include <algorithm>

namespace vlit {

void BatchChunk::fill(const ShadingPoint<double>* points, long count) {
  count_ = count;
  const std::size_t n = static_cast<std::size_t>(count);
  if (px_.size() < n) {
    for (auto* v : {&px_, &py_, &pz_}) v->resize(n);
    for (auto* v : {&nx_, &ny_, &nz_, &response_}) v->resize(n);
    stiff_.resize(n);
  }
#pragma omp parallel for schedule(static)
  for (long v = 0; v < count; ++v) {
    const ShadingPoint<double>& sp = points[v];
    px_[v] = sp.p.x; py_[v] = sp.p.y; pz_[v] = sp.p.z;
    nx_[v] = static_cast<float>(sp.n.x); ny_[v] = static_cast<float>(sp.n.y); nz_[v] = static_cast<float>(sp.n.z);
  }
}

void accumulate_light_batch(const PreparedLight<double>& light, const BatchLight& batch, const ShadeOptions& options,
                            BatchChunk& chunk, const ShadingPoint<double>* points, Vec3d* diffuse) {
  constexpr long kBlock = 256;  // lanes per task: whole blocks, so the split never changes a lane's code path
  const long count = chunk.count();
  const long blocks = (count + kBlock - 1) / kBlock;
  const BatchPoints pts = chunk.points();
  const BatchOutput out = chunk.scratch();
#pragma omp parallel for schedule(static)
  for (long b = 0; b < blocks; ++b) {
    const long begin = b * kBlock, end = std::min(count, begin + kBlock);
    evaluate_diffuse_batch(batch, pts, begin, end, out);
    for (long v = begin; v < end; ++v) {
      const double id = out.stiff[v] ? shade(light, points[v], options).diffuse : static_cast<double>(out.diffuse[v]);
      diffuse[v] += light.radiance * id;
    }
  }
}

}  // namespace vlit
