// Adaptive composite Gauss-Legendre quadrature used by the linear-light diffuse kernel for
// non-integer falloff (linear_diffuse_quadrature.h; the exact specular uses adaptive_kronrod.h).
//
// What it computes: the integral of a smooth scalar function over [e0, e_last], given initial
// panel edges e0 < e1 < ... that the caller places at the integrand's features (foot of the
// perpendicular, horizon crossing, specular peak, geometric grading around them). Each panel is
// integrated with the 8- and the 16-point Gauss-Legendre rules; a panel whose two results differ
// by more than tol * |estimate of the whole integral| is bisected (the 16-point result, whose
// error is d_far below that difference for analytic integrands, is kept on acceptance).
//
// Sources: standard Gauss-Legendre quadrature (nodes are the roots of P_n, found by Newton's
// iteration in long double at first use; weights 2 / ((1 - x^2) P_n'(x)^2)). Our own code; no
// quadrature library is used in the product (the tests integrate with Boost.Math's; the product
// uses Boost.Math's incomplete beta function only, linear_specular_beta.h).
//
// No allocation: panels live in a fixed-size array on the stack (kMaxPanels). When it is full,
// or a panel reaches kMaxDepth bisections, the panel is accepted as is (the error bound is then
// not guaranteed; tests/kernels/linear cover the configurations the kernels produce).
#pragma once

#include <cmath>

namespace vlit {

template <int N>
struct GaussLegendreRule {
  // Non-negative nodes x[i] (the rule is symmetric) and their weights; for odd N the node 0 is
  // x[0] = 0 and counts once.
  double x[(N + 1) / 2];
  double w[(N + 1) / 2];
};

template <int N>
GaussLegendreRule<N> make_gauss_legendre_rule() {
  GaussLegendreRule<N> rule{};
  constexpr int kHalf = (N + 1) / 2;
  const long double pi = 3.141592653589793238462643383279502884L;
  for (int i = 0; i < kHalf; ++i) {
    // Root i counted from x = 1 downwards; Chebyshev-like initial guess, then Newton.
    long double x = std::cos(pi * (i + 0.75L) / (N + 0.5L));
    long double dp = 1;
    for (int iter = 0; iter < 100; ++iter) {
      long double p0 = 1, p1 = x;  // P_0, P_1
      for (int k = 2; k <= N; ++k) {
        const long double pk = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = N * (x * p1 - p0) / (x * x - 1);  // P_N'(x)
      const long double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-19L) break;
    }
    // Store in ascending order of |x| so that x[0] is the middle node for odd N.
    const int j = kHalf - 1 - i;
    rule.x[j] = double(x);
    rule.w[j] = double(2 / ((1 - x * x) * dp * dp));
  }
  if (N % 2 == 1) rule.x[0] = 0;
  return rule;
}

template <int N>
const GaussLegendreRule<N>& gauss_legendre_rule() {
  static const GaussLegendreRule<N> rule = make_gauss_legendre_rule<N>();
  return rule;
}

// Integral of f over [lo, hi] with the N-point rule.
template <int N, class A, class Fn>
A gauss_legendre_panel(const Fn& f, A lo, A hi) {
  const GaussLegendreRule<N>& rule = gauss_legendre_rule<N>();
  const A mid = (lo + hi) / 2, half = (hi - lo) / 2;
  A sum{0};
  int i = 0;
  if (N % 2 == 1) { sum += A(rule.w[0]) * f(mid); i = 1; }
  for (; i < (N + 1) / 2; ++i) {
    const A dx = half * A(rule.x[i]);
    sum += A(rule.w[i]) * (f(mid - dx) + f(mid + dx));
  }
  return sum * half;
}

inline constexpr int kLinearQuadMaxPanels = 320;
inline constexpr int kLinearQuadMaxDepth = 40;

// Adaptive composite rule over the panels given by edges[0..n_edges-1] (ascending; equal
// neighbours are skipped). rel_tol is relative to the whole integral; abs_tol is a floor.
template <class A, class Fn>
A adaptive_gauss_legendre(const Fn& f, const A* edges, int n_edges, A rel_tol, A abs_tol = A(0)) {
  struct Panel { A lo, hi, g8, g16; int depth; };
  Panel stack[kLinearQuadMaxPanels];
  int top = 0;
  A estimate{0};
  for (int i = 0; i + 1 < n_edges && top < kLinearQuadMaxPanels; ++i) {
    if (!(edges[i + 1] > edges[i])) continue;
    Panel& p = stack[top++];
    p.lo = edges[i];
    p.hi = edges[i + 1];
    p.g8 = gauss_legendre_panel<8>(f, p.lo, p.hi);
    p.g16 = gauss_legendre_panel<16>(f, p.lo, p.hi);
    p.depth = 0;
    estimate += p.g16;
  }
  const A tol = std::fmax(rel_tol * std::fabs(estimate), abs_tol);
  A result{0}, compensation{0};  // Kahan summation of the accepted panels
  while (top > 0) {
    const Panel p = stack[--top];
    const bool accept = std::fabs(p.g16 - p.g8) <= tol || p.depth >= kLinearQuadMaxDepth ||
                        top + 2 > kLinearQuadMaxPanels;
    if (accept) {
      const A y = p.g16 - compensation;
      const A t = result + y;
      compensation = (t - result) - y;
      result = t;
      continue;
    }
    const A mid = (p.lo + p.hi) / 2;
    stack[top++] = {p.lo, mid, gauss_legendre_panel<8>(f, p.lo, mid), gauss_legendre_panel<16>(f, p.lo, mid), p.depth + 1};
    stack[top++] = {mid, p.hi, gauss_legendre_panel<8>(f, mid, p.hi), gauss_legendre_panel<16>(f, mid, p.hi), p.depth + 1};
  }
  return result;
}

// Appends to edges[] the points of a geometric grading of [lo, hi] around the point c (the foot
// of the perpendicular, where the integrand varies on the length scale h): |x - c| = w, 2w, 4w,
// ... (ratio 2, or larger when more than max_new points would be needed). Returns the new count.
// The caller sorts the edges afterwards.
template <class A>
int append_geometric_grading(A* edges, int count, int capacity, A lo, A hi, A c, A w, int max_new) {
  if (!(w > A(0))) return count;
  for (int side = -1; side <= 1; side += 2) {
    // Distances from c, on this side, of the near and the far end of [lo, hi].
    const A d_near = side < 0 ? std::fmax(c - hi, A(0)) : std::fmax(lo - c, A(0));
    const A d_far = side < 0 ? c - lo : hi - c;
    const A d0 = std::fmax(w, d_near);
    if (!(d_far > d0)) continue;
    const A levels = std::ceil(std::log2(d_far / d0));
    const int n_levels = int(std::fmin(levels, A(max_new / 2)));
    const A ratio = std::exp2(std::fmax(A(1), levels / A(n_levels > 0 ? n_levels : 1)));
    A d = d0;
    for (int k = 0; k < n_levels && count < capacity; ++k, d *= ratio) {
      const A x = c + A(side) * d;
      if (x > lo && x < hi) edges[count++] = x;
    }
  }
  return count;
}

// Sorts a short array in place (insertion sort; n is at most a few hundred).
template <class A>
void sort_edges(A* e, int n) {
  for (int i = 1; i < n; ++i) {
    const A v = e[i];
    int j = i - 1;
    while (j >= 0 && e[j] > v) { e[j + 1] = e[j]; --j; }
    e[j + 1] = v;
  }
}

}  // namespace vlit
