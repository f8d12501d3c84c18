// The named stiff configurations and the per-configuration checker shared by the linear tests.
#pragma once

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "linear_reference.h"

namespace vlit::linear_test {

// Named stiff cases (docs/linear-lights.md; one TEST_CASE each in linear_stiff_test.cpp).
inline Config stiff_case(const std::string& name) {
  Config c;
  c.name = name;
  c.p = {0, 0, 0};
  c.n = normalize(Vec3d{0.6, 0.1, 0.8});
  c.rv = normalize(Vec3d{0.8, 0.5, 0.3});
  c.shininess = 40;
  if (name == "collinear") {  // P on the line of the segment, outside it: 4CE - D^2 = 0
    c.q0 = {2, 0, 0};
    c.q1 = {3, 0, 0};
  } else if (name == "near-collinear") {  // h / length = 1e-9
    c.q0 = {2, 1e-9, 0};
    c.q1 = {3, 1e-9, 0};
  } else if (name == "far 1e6") {  // distance / length = 1e6
    c.q0 = {0.6e6, 0.2e6, 0.7e6};
    c.q1 = c.q0 + normalize(Vec3d{0.3, -0.8, 0.2});
    c.rv = normalize(c.q0 + Vec3d{0.2, 0.1, 0});
    c.shininess = 1e3;
  } else if (name == "near 1e-6") {  // P at 1e-6 of a unit segment, foot inside
    c.q0 = {-0.4, 0, 1e-6};
    c.q1 = {0.6, 0, 1e-6};
    c.n = normalize(Vec3d{0.3, 0.1, 1});
  } else if (name == "crossing horizon") {
    c.n = {0, 0, 1};
    c.q0 = {-1, 0.5, -0.5};
    c.q1 = {1, 0.5, 1.5};
    c.rv = normalize(Vec3d{0.2, 0.3, 1});
  } else if (name == "endpoint on tangent plane") {  // L0.N = 0 exactly
    c.n = {0, 0, 1};
    c.q0 = {1, 0.5, 0};
    c.q1 = {0.2, 1, 2};
    c.rv = normalize(Vec3d{1, 0.5, 0.01});
  } else if (name == "grazing normal") {  // the whole segment 1e-7 above the tangent plane
    c.n = {0, 0, 1};
    c.q0 = {1, 0, 1e-7};
    c.q1 = {2, 1, 3e-7};
    c.rv = normalize(Vec3d{1, 0.4, 1e-3});
  } else if (name == "zero-length") {
    c.q0 = {0.3, 0.4, 1.2};
    c.q1 = c.q0;
  } else if (name == "P on the segment") {
    c.q0 = {-1, 0, 0};
    c.q1 = {2, 0, 0};
    c.n = normalize(Vec3d{0.5, 0, 1});
  } else {
    FAIL("unknown stiff case " << name);
  }
  return c;
}

// A light of length `len` (1e-6: tiny, 1e6: huge) at distance ~1 above P, Rv toward its middle.
inline Config sized_light_case(double len, double shininess) {
  Config c;
  c.name = len < 1 ? "tiny 1e-6" : "huge 1e6";
  c.p = {0, 0, 0};
  c.n = normalize(Vec3d{0.1, 0.2, 1});
  c.q0 = {0.3 - len / 2, 0.2, 1};
  c.q1 = {0.3 + len / 2, 0.2, 1};
  c.rv = normalize(Vec3d{0.3, 0.2, 1});
  c.shininess = shininess;
  return c;
}

inline const std::vector<std::string>& stiff_names() {
  static const std::vector<std::string> names{"collinear", "near-collinear", "far 1e6", "near 1e-6",
                                              "crossing horizon", "endpoint on tangent plane",
                                              "grazing normal", "zero-length", "P on the segment"};
  return names;
}

// One row of the accuracy table: worst error of one method over a family of configurations.
struct Worst {
  double err = 0;
  std::string where;
  long double ref = 0;
  double value = 0;
  int count = 0;
};
using Table = std::map<std::string, Worst>;  // key: "<method> | <type> | <ordinary|stiff>"

inline double bar_for(const std::string& method, bool is_float, bool stiff) {
  if (is_float) return stiff ? 1e-3 : 1e-5;
  if (method.rfind("specular exact", 0) == 0) return 1e-8;
  if (method.rfind("specular peak", 0) == 0) return 1e-9;
  return stiff ? 1e-7 : 1e-10;
}

// Records and checks one value against its reference: |k - ref| <= bar |ref| + floor, reported as
// err = |k - ref| / max(|ref|, floor / bar).
inline void record(Table& table, const std::string& method, bool is_float, bool stiff, const std::string& where,
                   double value, long double ref, long double floor) {
  const double bar = bar_for(method, is_float, stiff);
  // A value below the smallest normal number of the type cannot be returned to relative accuracy.
  floor = std::max(floor, (long double)(is_float ? std::numeric_limits<float>::min() : std::numeric_limits<double>::min()));
  const double err = rel_err(value, ref, floor / bar);
  Worst& w = table[method + " | " + (is_float ? "float " : "double") + " | " + (stiff ? "stiff" : "ordinary")];
  ++w.count;
  if (!(err <= w.err)) { w.err = err; w.where = where; w.ref = ref; w.value = value; }
  INFO(where << ", " << method << (is_float ? " (float)" : " (double)") << ": kernel " << value << ", reference "
              << double(ref) << ", error " << err << ", bar " << bar);
  CHECK(std::isfinite(value));
  CHECK(err <= bar);
}

// Evaluates every kernel on one configuration in scalar type T and checks it.
template <class T>
void check_config(const Config& c, bool stiff, Table& table) {
  const bool is_float = sizeof(T) == sizeof(float);
  const bool on_segment = c.name == "P on the segment";
  // Diffuse: closed forms (n = 0..3), forced quadrature at n = 2, quadrature at non-integer n.
  struct D { double n; bool force; const char* method; };
  const D diffuse[] = {{0, false, "diffuse closed n=0"}, {1, false, "diffuse closed n=1"},
                       {2, false, "diffuse closed n=2"}, {3, false, "diffuse closed n=3"},
                       {2, true, "diffuse quadrature n=2"}, {0.5, false, "diffuse quadrature n=0.5"},
                       {1.5, false, "diffuse quadrature n=1.5"}, {2.7, false, "diffuse quadrature n=2.7"}};
  for (const D& d : diffuse) {
    const Typed<T> x = typed<T>(c, d.n);
    LinearDiffuseOptions opt;
    opt.force_quadrature = d.force;
    const SpecularOptions none{SpecularMethod::kNone};
    const T v = shade_linear(x.light, x.sp, none, opt).diffuse;
    long double ref;
    if (on_segment) {
      // Defined value (linear_diffuse_closed.h): 0 for n >= 1, else |b| ∫ |s|^-n over the lit
      // half; here u = +x, b = u.N > 0, the lit half is s in [0, 2], |Ld| = 3.
      const long double b = static_cast<long double>(x.sp.n.x);
      ref = d.n >= 1 ? 0.0L : b * std::pow(2.0L, 1 - (long double)d.n) / (1 - (long double)d.n) / 3;
    } else {
      ref = ref_diffuse(x);
    }
    // (P on the segment: the unclipped integral diverges for n >= 1; use 1 as its scale.)
    const long double floor = (is_float ? 1e-7L : 1e-12L) * (on_segment ? 1.0L : ref_unclipped(x));
    record(table, d.method, is_float, stiff, c.name, double(v), ref, floor);
  }
  // Specular.
  const Typed<T> x = typed<T>(c, 2);
  const long double peak_ref = ref_specular_peak(x);
  SpecularOptions peak{SpecularMethod::kPeak};
  const T vp = shade_linear(x.light, x.sp, peak).specular;
  record(table, "specular peak", is_float, stiff, c.name, double(vp), peak_ref, 1e-15L);
  SpecularOptions exact{SpecularMethod::kExact};
  const T ve = shade_linear(x.light, x.sp, exact).specular;
  // P on the segment: ∫ ds / s^2 diverges at P; the kernels define the value as 0 there, as for the
  // diffuse (linear_specular_exact.h).
  const long double exact_ref = on_segment ? 0.0L : ref_specular_exact(x);
  // Floor: the lobe's maximum times ∫ 1/|L|^n dt, the size of the falloff-weighted integral.
  record(table, "specular exact", is_float, stiff, c.name, double(ve), exact_ref,
         (is_float ? 1e-7L : 1e-12L) * std::max(peak_ref * (on_segment ? 1.0L : ref_unclipped(x)), 1e-300L));
  SpecularOptions nb{SpecularMethod::kNeighborhood};
  const T vn = shade_linear(x.light, x.sp, nb).specular;
  CHECK(std::isfinite(double(vn)));
  CHECK(double(vn) <= double(vp) * (1 + 1e-6) + 1e-30);
}

}  // namespace vlit::linear_test
