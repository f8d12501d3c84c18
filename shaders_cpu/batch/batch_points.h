// Structure-of-arrays shading points for the float batch kernels (shaders_cpu/batch/).
//
// A batch kernel evaluates one light at many points: lane v of every array is one surface point.
// Positions stay in double so that every kernel forms light-minus-point differences in double
// before rounding them to float: a mesh far from the origin (offset 1e4) loses nothing to
// cancellation, exactly as the scalar kernels' float instantiations (conventions.h). Normals are
// unit float vectors. Kernels read lanes [begin, end) and write one float per lane.
//
// Determinism: the batch kernels use only +, -, *, /, sqrt, min, max and selects, each correctly
// rounded in IEEE single or double precision, and no fused multiply-add contraction (the file that
// compiles them, src/shading/batch_kernels.cpp, is built with -ffp-contract=off: GCC contracts by
// default, differently in a vector body and its remainder). A lane's result is therefore the same
// whether it is computed in a 16-wide AVX-512 vector, an 8-wide AVX2 vector or the scalar
// remainder loop: the output does not depend on how vertices are split between threads.
// Lane code combines conditions with the non-short-circuit & and | so that the compiler sees
// plain masks (a short-circuit && between a float and a double comparison stops GCC 12).
#pragma once

#include <cstdint>

namespace vlit {

struct BatchPoints {
  const double* px = nullptr;
  const double* py = nullptr;
  const double* pz = nullptr;
  const float* nx = nullptr;  // unit normal
  const float* ny = nullptr;
  const float* nz = nullptr;
  // Unit reflected view direction Rv (conventions.h), for the specular kernels only; may be null
  // for the diffuse ones.
  const double* rx = nullptr;
  const double* ry = nullptr;
  const double* rz = nullptr;
};

// Per-lane outputs: the diffuse response for unit intensity (kd = 1, conventions.h) and a flag
// set when the lane is outside the kernel's float accuracy domain (the caller recomputes flagged
// lanes with the scalar double kernel; each kernel file says when it flags). Optional: kernels
// that recompute their stiff lanes in double themselves (area_diffuse_batch.h) mark them 1 in
// in_double (0 elsewhere), for tests and benchmarks; other kernels leave it untouched.
struct BatchOutput {
  float* diffuse = nullptr;
  std::uint8_t* stiff = nullptr;
  std::uint8_t* in_double = nullptr;
};

// Calls lane(px, py, pz, nx, ny, nz, diffuse, stiff) for every lane v in [begin, end), with the
// lane's inputs by value and its two outputs by reference, as one `omp simd` loop over
// restrict-qualified copies of the arrays: GCC 12 does not vectorise through the structs'
// pointers, and the copies tell it the outputs alias no input. `lane` must be inlinable.
template <class Lane>
inline void for_each_lane(const BatchPoints& pts, long begin, long end, const BatchOutput& out, const Lane& lane) {
  const double* __restrict px = pts.px;
  const double* __restrict py = pts.py;
  const double* __restrict pz = pts.pz;
  const float* __restrict nx = pts.nx;
  const float* __restrict ny = pts.ny;
  const float* __restrict nz = pts.nz;
  float* __restrict diffuse = out.diffuse;
  std::uint8_t* __restrict stiff = out.stiff;
#pragma omp simd
  for (long v = begin; v < end; ++v) lane(px[v], py[v], pz[v], nx[v], ny[v], nz[v], diffuse[v], stiff[v]);
}

}  // namespace vlit
