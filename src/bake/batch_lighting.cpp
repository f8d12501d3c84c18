#include "bake/batch_lighting.h"

#include <algorithm>

namespace vlit {

void BatchChunk::resize(long count) {
  count_ = count;
  const std::size_t n = static_cast<std::size_t>(count);
  if (px_.size() >= n) return;
  for (auto* v : {&px_, &py_, &pz_, &rx_, &ry_, &rz_, &specular_}) v->resize(n);
  specular_stiff_.resize(n);
  for (auto* v : {&nx_, &ny_, &nz_, &response_}) v->resize(n);
  stiff_.resize(n);
}

void BatchChunk::fill(const ShadingPoint<double>* points, long begin, long end) {
  for (long v = begin; v < end; ++v) {
    const ShadingPoint<double>& sp = points[v];
    px_[v] = sp.p.x; py_[v] = sp.p.y; pz_[v] = sp.p.z;
    nx_[v] = static_cast<float>(sp.n.x); ny_[v] = static_cast<float>(sp.n.y); nz_[v] = static_cast<float>(sp.n.z);
    rx_[v] = sp.rv.x; ry_[v] = sp.rv.y; rz_[v] = sp.rv.z;
  }
}

namespace {

// Every light of `lights` over lanes [begin, end) of the chunk, in the order given.
void light_block(const ScenePlan& plan, const std::vector<int>& lights, const BatchPoints& pts,
                 const BatchOutput& out, const BatchSpecularOutput& spec_out, const ShadingPoint<double>* points,
                 long begin, long end, Vec3d* diffuse, Vec3d* specular) {
  ShadeOptions specular_only = plan.shade;  // for lanes whose diffuse the batch kernel has
  specular_only.with_diffuse = false;
  for (int li : lights) {
    const PreparedLight<double>& light = plan.lights[li];
    const BatchChoice& choice = plan.batch_of_light[li];
    evaluate_diffuse_batch(*choice.light, pts, begin, end, out);
    if (!specular) {
      for (long v = begin; v < end; ++v) {
        const double id = out.stiff[v] ? shade(light, points[v], plan.shade).diffuse : static_cast<double>(out.diffuse[v]);
        diffuse[v] += light.radiance * id;
      }
      continue;
    }
    // One material per primitive: every point of the chunk has the same shininess.
    if (specular_batch_covers(choice, points[begin].shininess)) {
      evaluate_specular_batch(choice, plan.shade.specular, points[begin].shininess, pts, begin, end, spec_out);
      for (long v = begin; v < end; ++v) {
        if (out.stiff[v] | spec_out.stiff[v]) {
          const Response<double> r = shade(light, points[v], plan.shade);
          diffuse[v] += light.radiance * (out.stiff[v] ? r.diffuse : static_cast<double>(out.diffuse[v]));
          specular[v] += light.radiance * (spec_out.stiff[v] ? r.specular : spec_out.specular[v]);
        } else {
          diffuse[v] += light.radiance * static_cast<double>(out.diffuse[v]);
          specular[v] += light.radiance * spec_out.specular[v];
        }
      }
      continue;
    }
    // The specular by the scalar double kernel; its diffuse only where the batch lane was stiff.
    for (long v = begin; v < end; ++v) {
      const Response<double> r = shade(light, points[v], out.stiff[v] ? plan.shade : specular_only);
      diffuse[v] += light.radiance * (out.stiff[v] ? r.diffuse : static_cast<double>(out.diffuse[v]));
      specular[v] += light.radiance * r.specular;
    }
  }
}

}  // namespace

void accumulate_batch_lights(const ScenePlan& plan, const std::vector<int>& lights, BatchChunk& chunk,
                             const ShadingPoint<double>* points, long count, Vec3d* diffuse, Vec3d* specular) {
  if (lights.empty() || count <= 0) return;
  chunk.resize(count);
  const BatchPoints pts = chunk.points();
  const BatchOutput out = chunk.scratch();
  const BatchSpecularOutput spec_out = chunk.specular_scratch();
  // Lanes per task, whole blocks (the split never changes a lane's code path). A thread fills a
  // block and lights it with every light, so no barrier separates the lights.
  auto run_block = [&](long begin, long end) {
    chunk.fill(points, begin, end);
    light_block(plan, lights, pts, out, spec_out, points, begin, end, diffuse, specular);
  };
  if (!specular) {
    constexpr long kBlock = 1024;
    const long blocks = (count + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(static)
    for (long b = 0; b < blocks; ++b) run_block(b * kBlock, std::min(count, (b + 1) * kBlock));
    return;
  }
  // With specular the scalar kernels make a block's cost uneven (a highlight, a closed form
  // refused), so blocks are smaller and handed out as threads come free.
  constexpr long kSpecularBlock = 256;
  const long blocks = (count + kSpecularBlock - 1) / kSpecularBlock;
#pragma omp parallel for schedule(dynamic, 1)
  for (long b = 0; b < blocks; ++b) run_block(b * kSpecularBlock, std::min(count, (b + 1) * kSpecularBlock));
}

}  // namespace vlit
