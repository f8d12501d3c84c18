// The accuracy report's measuring machinery, shared by the per-model reports: case sets in double
// and float with their long-double references, a timed run of one method over a set, the error
// statistics, and the Section a report fills (its rows, each found later by its key, and its
// stiff-case table). The program that assembles the document is bench/accuracy_report.cpp; what
// the numbers mean is written once, in docs/accuracy.md.in.
//
// Error: |value - reference| / max(|reference|, floor), floor = 1e-12 x the largest |reference| of
// the set (ordinary) or of the named stiff case. Time: ns per evaluation, one thread, median of
// Options::reps runs over the whole batch.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

namespace vlit::bench::accuracy {

using LD = long double;
namespace fs = std::filesystem;

struct Options {
  bool quick = false;
  fs::path out_dir;
  std::string asset;
  int reps = 5;
  fs::path blender_dir;  // Cycles bakes of bench/blender_bake.py (scripts/blender-compare.sh); may be empty
};

struct Stats {
  double med = 0, p99 = 0, max = 0, ns = 0;
  int nonfinite = 0;
  int count = 0;
};

struct Run {
  std::vector<double> err;   // per case (inf if non-finite, NaN if the method does not apply)
  std::vector<double> value;
  double ns = 0;
  int nonfinite = 0;
};

inline Stats summarize(const Run& r) {
  Stats s;
  std::vector<double> e;
  for (double x : r.err)
    if (!std::isnan(x)) e.push_back(x);
  s.count = int(e.size());
  s.ns = r.ns;
  s.nonfinite = r.nonfinite;
  if (e.empty()) return s;
  std::sort(e.begin(), e.end());
  s.med = e[e.size() / 2];
  s.p99 = e[std::min(e.size() - 1, size_t(std::ceil(0.99 * double(e.size()))) - 1)];
  s.max = e.back();
  return s;
}

// Relative error with an absolute floor: |v - ref| / max(|ref|, floor).
inline double rel_err(double v, LD ref, double floor) {
  if (!std::isfinite(v)) return INFINITY;
  return double(std::fabs(LD(v) - ref) / std::max(std::fabs(ref), LD(floor)));
}

template <class X, class F, class A>
Run timed_run(const std::vector<X>& xs, const std::vector<LD>& ref, const std::vector<double>& floor, int reps,
              const F& f, const A& applies) {
  Run r;
  r.value.assign(xs.size(), 0);
  std::vector<double> times;
  for (int rep = 0; rep < reps; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    std::size_t n = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      if (!applies(xs[i])) continue;
      r.value[i] = double(f(xs[i], i));
      ++n;
    }
    const auto t1 = std::chrono::steady_clock::now();
    times.push_back(n ? std::chrono::duration<double, std::nano>(t1 - t0).count() / double(n) : 0);
  }
  std::sort(times.begin(), times.end());
  r.ns = times[times.size() / 2];
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (!applies(xs[i])) { r.err.push_back(NAN); continue; }
    if (!std::isfinite(r.value[i])) ++r.nonfinite;
    r.err.push_back(rel_err(r.value[i], ref[i], floor[i]));
  }
  return r;
}

// A case set in both precisions with its reference values and error floors.
template <template <class> class X>
struct CaseSet {
  std::vector<X<double>> d;
  std::vector<X<float>> f;
  std::vector<LD> ref;
  std::vector<double> floor;
  std::vector<int> group;  // stiff sets: index of the named case
  std::vector<std::string> group_names;
  std::vector<std::string> group_text;
};

// floor = 1e-12 x the largest |reference| of the case's group (or of the whole set).
template <template <class> class X>
void set_floors(CaseSet<X>& s) {
  std::map<int, LD> top;
  for (std::size_t i = 0; i < s.ref.size(); ++i) {
    const int g = s.group.empty() ? 0 : s.group[i];
    top[g] = std::max(top[g], std::fabs(s.ref[i]));
  }
  s.floor.resize(s.ref.size());
  for (std::size_t i = 0; i < s.ref.size(); ++i)
    s.floor[i] = std::max(double(1e-12L * top[s.group.empty() ? 0 : s.group[i]]), 1e-300);
}

// One method on one case set. `key` names the row for the document (docs/accuracy.md.in) and
// never changes with the printed label `method`.
struct Row {
  std::string key, method, set, promise;
  Stats d, f;
  bool plot = true;
};

// Stiff table: per method, per named case, max error in double and float, and non-finite counts.
struct StiffTable {
  std::vector<std::string> case_names, case_text;
  std::vector<std::string> keys, methods;                    // per method: row key, printed label
  std::vector<std::vector<std::array<double, 2>>> max_err;  // [method][case] {double, float}
  std::vector<int> nonfinite;                                // per method
};

// Every case in double and in float (typed(case, T{}) gives X<T>) with its long-double reference
// and error floors; `group`: the named case of each (stiff sets) or empty.
template <template <class> class X, class Case, class Typed, class Reference>
CaseSet<X> make_case_set(const std::vector<Case>& cases, const std::vector<int>& group, const Typed& typed,
                         const Reference& reference) {
  CaseSet<X> s;
  for (const Case& c : cases) {
    s.d.push_back(typed(c, double{}));
    s.f.push_back(typed(c, float{}));
    s.ref.push_back(reference(c));
  }
  s.group = group;
  set_floors(s);
  return s;
}

// The named stiff cases as one set: every case of named[g] (a vector `cases` of what make_set
// takes) in group g, with the names and descriptions of the groups.
template <template <class> class X, class Named, class MakeSet>
CaseSet<X> named_case_set(const std::vector<Named>& named, const MakeSet& make_set) {
  std::vector<typename decltype(Named::cases)::value_type> cases;
  std::vector<int> group;
  for (std::size_t g = 0; g < named.size(); ++g)
    for (const auto& c : named[g].cases) {
      cases.push_back(c);
      group.push_back(int(g));
    }
  CaseSet<X> s = make_set(cases, group);
  for (const auto& n : named) {
    s.group_names.push_back(n.name);
    s.group_text.push_back(n.text);
  }
  return s;
}

template <template <class> class X, class F, class A>
void stiff_add(StiffTable& t, const std::string& key, const std::string& name, const CaseSet<X>& s, const F& f,
               const A& applies) {
  const Run rd = timed_run(s.d, s.ref, s.floor, 1, f, applies);
  const Run rf = timed_run(s.f, s.ref, s.floor, 1, f, applies);
  std::vector<std::array<double, 2>> row(s.group_names.size(), {NAN, NAN});
  for (std::size_t i = 0; i < s.ref.size(); ++i) {
    auto& cell = row[s.group[i]];
    if (!std::isnan(rd.err[i])) cell[0] = std::isnan(cell[0]) ? rd.err[i] : std::max(cell[0], rd.err[i]);
    if (!std::isnan(rf.err[i])) cell[1] = std::isnan(cell[1]) ? rf.err[i] : std::max(cell[1], rf.err[i]);
  }
  t.keys.push_back(key);
  t.methods.push_back(name);
  t.max_err.push_back(row);
  t.nonfinite.push_back(rd.nonfinite + rf.nonfinite);
}

// One report section (a light model and a quantity): the ordinary table, the stiff table, and the
// count of NaN/Inf its methods returned.
struct Section {
  std::string key, title;
  int ordinary_cases = 0;  // size of the ordinary (timed) case set
  std::vector<Row> rows;
  StiffTable stiff;
  int nonfinite = 0;
};

// A section measured on `ordinary_cases` ordinary cases and on the named cases of `stiff`.
template <template <class> class X>
Section make_section(const std::string& key, const std::string& title, int ordinary_cases, const CaseSet<X>& stiff) {
  Section s;
  s.key = key;
  s.title = title;
  s.ordinary_cases = ordinary_cases;
  s.stiff.case_names = stiff.group_names;
  s.stiff.case_text = stiff.group_text;
  return s;
}

inline double elapsed_s() {
  static const auto start = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// "[  t s] what ..." on stderr: where a long report run is.
inline void progress(const std::string& what) { std::fprintf(stderr, "[%5.1f s] %s ...\n", elapsed_s(), what.c_str()); }

// Runs one method on the ordinary set (timed) and, if given, on the stiff set (errors only).
template <template <class> class X, class F, class A>
void method(Section& sec, const Options& o, const std::string& key, const std::string& name, const std::string& set,
            const std::string& promise, const CaseSet<X>& ordinary, const CaseSet<X>* stiff, const F& f,
            const A& applies, bool plot = true) {
  Row r{key, name, set, promise, {}, {}, plot};
  const Run rd = timed_run(ordinary.d, ordinary.ref, ordinary.floor, o.reps, f, applies);
  const Run rf = timed_run(ordinary.f, ordinary.ref, ordinary.floor, o.reps, f, applies);
  r.d = summarize(rd);
  r.f = summarize(rf);
  sec.nonfinite += rd.nonfinite + rf.nonfinite;
  sec.rows.push_back(r);
  if (stiff) {
    stiff_add(sec.stiff, key, name, *stiff, f, applies);
    sec.nonfinite += sec.stiff.nonfinite.back();
  }
  std::fprintf(stderr, "[%5.1f s] %-34s %-8s double: med %.1e max %.1e %9.0f ns | float: med %.1e max %.1e %9.0f ns\n",
               elapsed_s(), name.c_str(), set.c_str(), r.d.med, r.d.max, r.d.ns, r.f.med, r.f.max, r.f.ns);
}

inline const auto kAlways = [](const auto&) { return true; };

// The Monte Carlo rows of a section: plain sampling at each of `samples`, then stratified;
// estimator(n, stratified) gives the method, (case, case index) -> value.
template <template <class> class X, class Estimator>
void monte_carlo_rows(Section& sec, const Options& o, const std::string& set, const std::string& plain_promise,
                      const std::string& stratified_promise, std::initializer_list<int> samples,
                      const CaseSet<X>& ordinary, const CaseSet<X>* stiff, const Estimator& estimator) {
  for (bool strat : {false, true})
    for (int n : samples)
      method(sec, o, std::string(strat ? "stratified-" : "mc-") + std::to_string(n),
             std::string(strat ? "stratified " : "Monte Carlo ") + std::to_string(n), set,
             strat ? stratified_promise : plain_promise, ordinary, stiff, estimator(n, strat), kAlways);
}

}  // namespace vlit::bench::accuracy
