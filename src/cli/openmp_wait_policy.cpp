#include "cli/openmp_wait_policy.h"

#include <omp.h>
#include <unistd.h>

#include <cstdlib>

namespace vlit::cli {

void prefer_passive_openmp_wait(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);  // replaces the process; returns only on failure
}

std::string openmp_threads_line() {
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  return "threads: " + std::to_string(omp_get_max_threads()) + " (OpenMP wait policy " +
         (policy != nullptr ? std::string(policy) : std::string("runtime default")) + ")";
}

}  // namespace vlit::cli
