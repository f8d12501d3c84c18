// The specular method ladder the linear and area reports measure alike: the paper's peak (eq. 7-8,
// 11-12), the neighbourhood of K samples around it, and the exact lobe integral at each tolerance,
// one row each, with the options --specular sets (SpecularOptions, conventions.h).
#pragma once

#include <cstdio>
#include <initializer_list>
#include <string>

#include "conventions.h"
#include "report_core.h"
#include "report_format.h"

namespace vlit::bench::accuracy {

// specular(options) gives the method (case, case index) -> value for those options;
// `neighbourhood_promise` says what the neighbourhood estimates for this light, `exact_estimate`
// how the exact method estimates its error.
template <template <class> class X, class Specular>
void specular_method_rows(Section& sec, const Options& o, const CaseSet<X>& ordinary, const CaseSet<X>* stiff,
                          const std::string& neighbourhood_promise, std::initializer_list<double> tolerances,
                          const char* exact_estimate, const Specular& specular) {
  const std::string set = "m 1..1e3";
  SpecularOptions peak;
  peak.method = SpecularMethod::kPeak;
  method(sec, o, "peak", "peak", set, "the lobe's maximum (not the integral)", ordinary, stiff, specular(peak), kAlways);
  for (int k : {1, 2, 4, 8, 16}) {
    SpecularOptions nb;
    nb.method = SpecularMethod::kNeighborhood;
    nb.neighborhood_samples = k;
    method(sec, o, "neighbourhood-" + std::to_string(k), "neighbourhood K=" + std::to_string(k), set, neighbourhood_promise,
           ordinary, stiff, specular(nb), kAlways);
  }
  for (double tol : tolerances) {
    SpecularOptions ex;
    ex.method = SpecularMethod::kExact;
    ex.exact_tolerance = tol;
    char name[64], promise[96];
    std::snprintf(name, sizeof name, "exact tol %g%s", tol, tol == 1e-9 ? " (default)" : "");
    std::snprintf(promise, sizeof promise, "relative %g (%s)", tol, exact_estimate);
    method(sec, o, "exact-" + tol_key(tol), name, set, promise, ordinary, stiff, specular(ex), kAlways);
  }
}

}  // namespace vlit::bench::accuracy
