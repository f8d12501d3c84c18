// Linear (tube) light: the light type and the per-point local frame shared by every linear kernel.
//
// What it computes: for a segment Q0->Q1 and a shading point P, the frame in which all linear
// kernels integrate. Writing L(t) = L0 + t Ld (L0 = Q0 - P, Ld = Q1 - Q0, Picott 1992 eq. 3), let
// u = Ld/|Ld|, F the foot of the perpendicular from P onto the line, H = F - P (|H| = h) and
// s = (P + L(t) - F).u the signed position along the line measured from the foot. Then
//   L(s) = H + s u,   |L|^2 = h^2 + s^2,   L.N = a + b s (a = H.N, b = u.N),
//   Rv.L = ar + br s (ar = Rv.H, br = Rv.u),   dt = ds / |Ld|.
// In this frame the paper's quadratic C + D t + E t^2 becomes h^2 + s^2, and its discriminant
// 4CE - D^2 = 4 E^2 h^2 (sidebar "Linear-light diffuse integration calculations"): the collinear
// trap (4CE - D^2 -> 0) is simply h -> 0, which the kernels handle with forms that stay finite
// and accurate at h = 0 (see linear_diffuse_closed.h and docs/linear-lights.md).
//
// Sources: Picott 1992 eq. 3-4 and both linear-light sidebars. Conventions: conventions.h.
//
// Per-light vs per-point: only Ld, |Ld| = sqrt(E) and u are properties of the light. Every other
// quantity (the paper's A..E of both sidebars except E = Ld.Ld resp. A = Ld.Ld) depends on
// L0 = Q0 - P and therefore on the shading point (docs/linear-lights.md, erratum E1).
//
// Numerics:
// - The frame is set up (and the kernels compute) in double even for the float instantiation:
//   the differences of float inputs Q0 - P, Q1 - P are exact in double, so a float caller loses
//   nothing to cancellation when P is far from the origin compared with its distance to the light.
// - All lengths are divided by scale = max(|L0|, |L1|); kernels multiply by scale^-n at the end.
//   Normalised lengths are <= 1, which keeps h^2, |L|^(n+1) etc. far from under/overflow.
// - Horizon clipping (conventions.h) happens here, in t, from the endpoint values L0.N and L1.N
//   (no cancellation): the visible interval is [sa, sb] in s, of length delta.
// - Degenerate configurations are classified once, with the double-precision setup:
//   zero_length (|Ld| <= eps * scale: the light is a point light at its midpoint, exact to
//   O((|Ld|/|L|)^2)) and on_segment (h <= 4 eps scale and the foot inside [s0, s1]: P lies on the
//   segment, see linear_diffuse_closed.h for the value this defines).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "conventions.h"
#include "core/robust_math.h"
#include "core/vec3.h"

namespace vlit {

// Segment light Q0 -> Q1 of intensity Ip per unit of the parameter t in [0, 1] (conventions.h).
template <class T>
struct LinearLight {
  Vec3<T> q0, q1;
  T falloff{2};  // distance falloff exponent n of eq. 1 and 4, any real in [0, 3]
};

// The scalar type the frame is set up in: double for float and double inputs.
template <class T>
using LinearSetup = std::conditional_t<(sizeof(T) < sizeof(double)), double, T>;

// The scalar type the kernels compute in once the frame is built: double for float and double.
// The float instantiation computes in double and rounds once at the end, because in float
// (eps 6e-8) the Phong power multiplies the rounding error of cos α by m (m = 1000 gives ~6e-5,
// above the 1e-5 float bar) and 1/h^(n+1) overflows float for P within ~1e-13 of the line
// (docs/linear-lights.md, "Float"). The cost is scalar double arithmetic in the kernels.
// Build switch VLIT_LINEAR_FLOAT_NATIVE (for the measurement in docs/linear-lights.md only): the
// float instantiation computes in float after the double setup.
#ifdef VLIT_LINEAR_FLOAT_NATIVE
template <class T>
using LinearCompute = T;
#else
template <class T>
using LinearCompute = LinearSetup<T>;
#endif

// Everything a linear kernel needs about one (light, point) pair, in normalised lengths.
template <class A>
struct LinearFrame {
  bool empty = true;         // nothing to do: P at both endpoints, or no part of the light visible
  bool zero_length = false;  // |Ld| negligible: use the point-light limit (mid_* fields)
  bool on_segment = false;   // P lies on the segment (h below rounding noise, foot inside)
  double scale = 1;          // length unit: max(|L0|, |L1|) in world units
  A ell{0};                  // |Ld| / scale
  A h{0};                    // distance from P to the line / scale
  A s0{0}, s1{0};            // positions of Q0, Q1 along u, from the foot of the perpendicular
  A sa{0}, sb{0}, delta{0};  // visible (horizon-clipped) interval [sa, sb] and its length
  A a{0}, b{0};              // L.N = a + b s   (a = H.N, b = u.N), normalised
  A ar{0}, br{0};            // Rv.L = ar + br s (ar = Rv.H, br = Rv.u), normalised
  // Point-light limit (zero_length): the midpoint direction, normalised.
  A mid_r{0};                // |L(1/2)| / scale
  A mid_cos_n{0};            // N.L̂(1/2)
  A mid_cos_rv{0};           // Rv.L̂(1/2)
};

// Builds the frame. T is the caller's scalar type, A = LinearCompute<T>.
template <class T>
LinearFrame<LinearCompute<T>> make_linear_frame(const LinearLight<T>& light, const ShadingPoint<T>& sp) {
  using S = LinearSetup<T>;
  using A = LinearCompute<T>;
  constexpr S kEps = std::numeric_limits<S>::epsilon();
  LinearFrame<A> f;
  const Vec3<S> p = static_cast<Vec3<S>>(sp.p);
  const Vec3<S> n = static_cast<Vec3<S>>(sp.n);
  const Vec3<S> rv = static_cast<Vec3<S>>(sp.rv);
  Vec3<S> l0 = static_cast<Vec3<S>>(light.q0) - p;  // exact for float inputs
  Vec3<S> l1 = static_cast<Vec3<S>>(light.q1) - p;
  const S scale = std::max(length(l0), length(l1));
  if (!(scale > S(0)) || !std::isfinite(scale)) return f;  // P at both endpoints (or bad input)
  l0 = l0 / scale;
  l1 = l1 / scale;
  f.scale = double(scale);
  const Vec3<S> ld = l1 - l0;
  const S ell = length(ld);

  if (ell <= kEps) {  // point-light limit at the midpoint
    const Vec3<S> lm = (l0 + l1) * S(0.5);
    const S rm = length(lm);
    if (!(rm > S(0))) return f;
    f.empty = false;
    f.zero_length = true;
    f.mid_r = A(rm);
    f.mid_cos_n = A(dot(n, lm) / rm);
    f.mid_cos_rv = A(dot(rv, lm) / rm);
    return f;
  }

  const Vec3<S> u = ld / ell;
  const S s0 = dot(l0, u);
  const S s1 = dot(l1, u);
  const S h = length(cross(l0, u));
  const Vec3<S> hv = l0 - u * s0;  // H = F - P
  f.ell = A(ell);
  f.h = A(h);
  f.s0 = A(s0);
  f.s1 = A(s1);
  f.a = A(dot(hv, n));
  f.b = A(dot(u, n));
  f.ar = A(dot(hv, rv));
  f.br = A(dot(u, rv));
  f.on_segment = h <= S(4) * kEps && s0 <= S(0) && s1 >= S(0);

  // Horizon clipping in t from the endpoint values (exact signs, no cancellation).
  const S c0 = dot(l0, n);
  const S c1 = dot(l1, n);
  S ta = 0, tb = 1;
  if (c0 >= S(0) && c1 >= S(0)) {
    if (c0 == S(0) && c1 == S(0)) return f;  // segment lies in the tangent plane
  } else if (c0 <= S(0) && c1 <= S(0)) {
    return f;  // entirely below the horizon
  } else {
    const S tc = c0 / (c0 - c1);  // c0, c1 of strictly opposite signs: tc in (0, 1)
    if (c0 > S(0)) tb = tc; else ta = tc;
  }
  const S sa = ta == S(0) ? s0 : s0 + ta * ell;
  const S sb = tb == S(1) ? s1 : s0 + tb * ell;
  f.sa = A(sa);
  f.sb = A(std::max(sa, sb));
  f.delta = A((tb - ta) * ell);
  f.empty = !(f.delta > A(0));
  return f;
}

// The same frame set up in long double and rounded to A = LinearCompute<T> field by field, for the
// exact specular. In the setup above, H = L0 - u (L0.u) and ar = Rv.H carry an absolute error of
// a few eps |L0| (the rounding of u, times |L0|), i.e. a relative error eps |L0| / h in ar / h: the
// lobe's height C^m then moves by m eps |L0| / h (measured: 8e-12 relative for m = 704 on the
// random set of tests/kernels/linear/linear_specular_closed_test.cpp, in the closed and in the
// adaptive form alike). Set up with 11 more bits and rounded once, each field is accurate to a
// few eps in its own magnitude. Where long double is double (MSVC), this is make_linear_frame.
template <class T>
LinearFrame<LinearCompute<T>> make_linear_frame_precise(const LinearLight<T>& light, const ShadingPoint<T>& sp) {
  using L = long double;
  using A = LinearCompute<T>;
  const LinearLight<L> light_l{static_cast<Vec3<L>>(light.q0), static_cast<Vec3<L>>(light.q1), L(light.falloff)};
  const ShadingPoint<L> sp_l{static_cast<Vec3<L>>(sp.p), static_cast<Vec3<L>>(sp.n), static_cast<Vec3<L>>(sp.rv),
                             L(sp.shininess)};
  const LinearFrame<L> f = make_linear_frame(light_l, sp_l);
  LinearFrame<A> r;
  r.empty = f.empty;
  r.zero_length = f.zero_length;
  r.on_segment = f.on_segment;
  r.scale = double(f.scale);
  r.ell = A(f.ell);
  r.h = A(f.h);
  r.s0 = A(f.s0);
  r.s1 = A(f.s1);
  r.sa = A(f.sa);
  r.sb = A(f.sb);
  r.delta = A(f.delta);
  r.a = A(f.a);
  r.b = A(f.b);
  r.ar = A(f.ar);
  r.br = A(f.br);
  r.mid_r = A(f.mid_r);
  r.mid_cos_n = A(f.mid_cos_n);
  r.mid_cos_rv = A(f.mid_cos_rv);
  return r;
}

// scale^-n in double (the kernels' results are multiplied by it), for any real n.
inline double linear_scale_factor(double scale, double n) {
  if (n == 0) return 1;
  if (n == 1) return 1 / scale;
  if (n == 2) return 1 / (scale * scale);
  if (n == 3) return 1 / (scale * scale * scale);
  return std::pow(scale, -n);
}

// Converts a normalised diffuse value to T, saturating at the largest finite T: the true value
// can exceed the range of T (e.g. n = 3 at a distance of 1e-13 in float); we never return Inf.
template <class T>
T linear_saturate(double x) {
  const double big = double(std::numeric_limits<T>::max());
  return T(std::min(std::max(x, 0.0), big));
}

}  // namespace vlit
