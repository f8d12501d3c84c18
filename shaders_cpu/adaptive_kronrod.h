// Globally adaptive Gauss-Kronrod 7/15 quadrature over the curves of a contour: the one
// integrator of the exact specular kernels (area_specular_exact.h integrates polygon edges with it,
// disk_specular_exact.h rim arcs and chords, linear_specular_exact.h the segment as one curve).
//
// Computes Σ_c w_c ∫ f(c, t) dt over pieces [t0, t1] of each curve c's parameter t.
//
// Method: each piece is integrated by the 15-point Kronrod rule; the embedded 7-point Gauss rule
// gives its error estimate |K15 - G7| (both times the curve's weight w_c). refine() bisects the
// piece with the largest estimate until Σ error <= max(tolerance |Σ value|, floor), the work list
// is full, or the worst piece is too narrow to bisect in R. The initial pieces are the caller's:
// add_graded() cuts an interval around the integrand's known peaks so the adaptivity starts near
// them resolved. A caller that can bound |∫ f| over a piece may add it deferred: it counts as value
// 0 with its bound as error, and refine() evaluates it (instead of bisecting) only when it is the
// worst piece; where the bounds are already below the target, it is never evaluated.
//
// Contract:
//  - no heap: the work list is a fixed array of kMaxPieces pieces (40 bytes each in double), a
//    local variable of the kernel; pieces beyond it are dropped by add(), so the caller bounds the
//    initial cuts (add_graded's kMaxCuts) well below kMaxPieces;
//  - deterministic: the same calls in the same order give the same bits (the running sums are
//    recounted every 64 bisections and the result summed in work-list order);
//  - f(c, t) must be finite on every piece; weight(c) is the same w_c as given to add().
// Sources: the Kronrod extension of the 7-point Gauss rule (Kronrod 1965; nodes and weights to
// 33 digits as tabulated in QUADPACK, Piessens et al. 1983, which also describes the global
// bisection strategy used here). Accuracy: that of its callers, measured in docs/area-lights.md.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace vlit {

namespace kronrod_detail {

// Gauss-Kronrod 7/15 on [-1, 1]: Kronrod nodes (positive half, the last is 0) and weights; the
// Gauss nodes are the odd-indexed Kronrod nodes.
template <class R>
struct Kronrod15 {
  static constexpr R x[8] = {R(0.991455371120812639206854697526329), R(0.949107912342758524526189684047851),
                             R(0.864864423359769072789712788640926), R(0.741531185599394439863864773280788),
                             R(0.586087235467691130294144845693013), R(0.405845151377397166906606412076961),
                             R(0.207784955007898467600689403773245), R(0)};
  static constexpr R wk[8] = {R(0.022935322010529224963732008058970), R(0.063092092629978553290700663189204),
                              R(0.104790010322250183839876322541518), R(0.140653259715525918745189590510238),
                              R(0.169004726639267902826583426598550), R(0.190350578064785409913256402421014),
                              R(0.204432940075298892414161999234649), R(0.209482141084727828012999174891714)};
  static constexpr R wg[4] = {R(0.129484966168869693270611432679082), R(0.279705391489276667901467771423780),
                              R(0.381830050505118944950369775488975), R(0.417959183673469387755102040816327)};
};

}  // namespace kronrod_detail

template <class R, int kMaxPieces>
class AdaptiveKronrod {
 public:
  struct Piece {
    R t0, t1, value, error;
    int curve;
    bool deferred;  // not evaluated yet: value 0, error the caller's bound
  };

  // Adds ∫_{t0}^{t1} f(t) dt of curve `curve`, times `weight`, as one piece (dropped when the work
  // list is full).
  template <class F>
  void add(const F& f, int curve, R t0, R t1, R weight) {
    if (size_ >= kMaxPieces) return;
    Piece& p = heap_[size_];
    p.t0 = t0; p.t1 = t1; p.curve = curve; p.deferred = false;
    evaluate(f, p);
    p.value *= weight;
    p.error *= std::abs(weight);
    push();
  }

  // Adds [t0, t1] of curve `curve` unevaluated, with `bound` >= |weight ∫_{t0}^{t1} f dt| as its
  // error (dropped when the work list is full).
  void add_deferred(int curve, R t0, R t1, R bound) {
    if (size_ >= kMaxPieces) return;
    heap_[size_] = Piece{t0, t1, R(0), bound, curve, true};
    push();
  }

  // Adds [t0, t1] of curve `curve` cut at graded points around each of `count` centres: the centre
  // and centre -+ width 4^k (k = 0, 1, ... while below t1 - t0), those inside (t0, t1); a centre
  // whose width is not positive, or that is not finite, adds no cut. At most kMaxCuts cut points
  // in all (the two ends included).
  template <int kMaxCuts, class F>
  void add_graded(const F& f, int curve, R t0, R t1, const R* centers, const R* widths, int count, R weight) {
    add_graded<kMaxCuts>(f, curve, t0, t1, centers, widths, count, weight, [](R, R) { return R(-1); });
  }

  // As above, but a piece [a, b] for which bound(a, b) >= 0 is added deferred, with error
  // |weight| bound(a, b); bound(a, b) >= |∫_a^b f dt| is the caller's promise (negative: no bound).
  template <int kMaxCuts, class F, class B>
  void add_graded(const F& f, int curve, R t0, R t1, const R* centers, const R* widths, int count, R weight,
                  const B& bound) {
    std::array<R, kMaxCuts> cuts{};
    int k = 0;
    cuts[k++] = t0;
    cuts[k++] = t1;
    const auto cut = [&](R t) { if (t > t0 && t < t1 && k < kMaxCuts) cuts[k++] = t; };
    for (int i = 0; i < count; ++i) {
      if (!(widths[i] > R(0)) || !std::isfinite(centers[i])) continue;
      cut(centers[i]);
      for (R s = widths[i]; s < t1 - t0 && k + 2 <= kMaxCuts; s *= R(4)) { cut(centers[i] - s); cut(centers[i] + s); }
    }
    std::sort(cuts.begin(), cuts.begin() + k);
    for (int i = 0; i + 1 < k; ++i) {
      if (!(cuts[i + 1] > cuts[i])) continue;
      const R b = bound(cuts[i], cuts[i + 1]);
      if (b >= R(0)) add_deferred(curve, cuts[i], cuts[i + 1], b * std::abs(weight));
      else add(f, curve, cuts[i], cuts[i + 1], weight);
    }
  }

  // Bisects the worst piece (or evaluates it, if deferred) until the error target is met (see the
  // header), then returns the sum.
  // integrand(c, t) and weight(c) are the f and weight that add() was given for curve c; floor is
  // an absolute error target for integrals that may be ~0 (0: relative only).
  template <class F, class W>
  R refine(const F& integrand, const W& weight, R tolerance, R floor = R(0)) {
    int splits = 0;
    while (error_ > std::max(tolerance * std::abs(value_), floor) && size_ + 2 <= kMaxPieces) {
      std::pop_heap(heap_.begin(), heap_.begin() + size_, less_error);
      const Piece p = heap_[--size_];
      value_ -= p.value; error_ -= p.error;
      const auto f = [&](R t) { return integrand(p.curve, t); };
      const R mid = (p.t0 + p.t1) / 2;
      if (p.deferred) {  // the worst piece is an unevaluated one: evaluate it whole
        add(f, p.curve, p.t0, p.t1, weight(p.curve));
      } else if (!(mid > p.t0 && mid < p.t1)) {  // cannot be split further: keep it, stop
        heap_[size_] = p;
        push();
        break;
      } else {
        add(f, p.curve, p.t0, mid, weight(p.curve));
        add(f, p.curve, mid, p.t1, weight(p.curve));
      }
      // Running sums drift by rounding; recount them exactly now and then.
      if (++splits % 64 == 0 || !std::isfinite(error_)) {
        value_ = 0; error_ = 0;
        for (int k = 0; k < size_; ++k) { value_ += heap_[k].value; error_ += heap_[k].error; }
      }
    }
    R value = 0;
    for (int k = 0; k < size_; ++k) value += heap_[k].value;
    return value;
  }

 private:
  // Pushes heap_[size_] onto the heap and into the running sums.
  void push() {
    value_ += heap_[size_].value; error_ += heap_[size_].error;
    ++size_;
    std::push_heap(heap_.begin(), heap_.begin() + size_, less_error);
  }

  template <class F>
  static void evaluate(const F& f, Piece& p) {
    using K = kronrod_detail::Kronrod15<R>;
    const R mid = (p.t0 + p.t1) / 2, half = (p.t1 - p.t0) / 2;
    const R f0 = f(mid);
    R k = K::wk[7] * f0, g = K::wg[3] * f0;
    for (int i = 0; i < 7; ++i) {
      const R s = f(mid - half * K::x[i]) + f(mid + half * K::x[i]);
      k += K::wk[i] * s;
      if (i % 2 == 1) g += K::wg[i / 2] * s;
    }
    p.value = k * half;
    p.error = std::abs((k - g) * half);
  }
  static bool less_error(const Piece& a, const Piece& b) { return a.error < b.error; }

  std::array<Piece, kMaxPieces> heap_;
  int size_ = 0;
  R value_ = 0, error_ = 0;
};

}  // namespace vlit
