// OpenMP's default wait policy lets idle threads spin. When other processes compete for the
// cores (several bakes at once in a pipeline, a CI runner) a spinning thread burns the time slice
// its partner needs, and two threads become several times slower than one (docs/performance.md
// "Running on a shared machine"). libgomp reads OMP_WAIT_POLICY once, before main(), so when the
// user has not chosen a policy, vlit sets "passive" and restarts itself once with the same
// arguments. A user's own OMP_WAIT_POLICY (e.g. "active" on a dedicated machine) is kept.
#pragma once

#include <string>

namespace vlit::cli {

// Returns only when no restart happened: the policy was already set, or the restart failed (the
// process then carries on with the runtime's default).
void prefer_passive_openmp_wait(char** argv);

// "threads: N (OpenMP wait policy P)" for --explain; P is OMP_WAIT_POLICY or "runtime default".
std::string openmp_threads_line();

}  // namespace vlit::cli
