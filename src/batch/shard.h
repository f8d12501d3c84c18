// Which inputs of a batch one shard bakes. A batch split over machines (a Slurm job array, a
// Kubernetes Indexed Job, GNU parallel) runs the same `vlit bake INPUTS -o DIR --shard I/N` on every
// machine; each keeps the inputs whose key falls in its shard, so the N shards together bake every
// input exactly once without talking to each other.
//
// The rule (docs/batch-sharding.md): key = the input's path relative to the argument it was found
// under (docs/batch-sharding.md, "Output layout"), '/'-separated, as UTF-8 bytes;
//   shard(key) = splitmix64_finalizer(fnv1a_64(key)) mod N.
// It depends on neither the order of the inputs, nor the machine, nor where the batch's root lies
// on that machine, nor the other inputs: adding files to a batch moves no existing file to
// another shard. The finalizer is there because FNV-1a's low bits depend only on the low bits of
// the bytes (mod 2^k it never mixes upward), which would split names like a1.glb, a3.glb badly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace vlit {

struct Shard {
  std::size_t index = 0;  // 0 .. count - 1
  std::size_t count = 1;
  std::string text() const;  // "I/N"
};

// FNV-1a, 64 bits (offset basis 0xcbf29ce484222325, prime 0x100000001b3).
std::uint64_t fnv1a_64(std::string_view bytes);
// SplitMix64's output function (Steele, Lea, Flood 2014): a bijection that spreads every input bit.
std::uint64_t splitmix64_finalizer(std::uint64_t x);
// The shard, in 0 .. count - 1, of the input with this key; count >= 1.
std::size_t shard_of_key(std::string_view key, std::size_t count);

// "I/N" with 0 <= I < N. Throws InputError("--shard", ...) otherwise.
Shard parse_shard(const std::string& text);

// Reads the environment for --shard auto. Throws InputError("--shard auto", ...) naming the
// variables when none is set or they do not make a shard. The first source found wins:
//   1. VLIT_SHARD_INDEX and VLIT_SHARD_COUNT (anything else, or to override the ones below);
//   2. a Slurm job array: SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN, SLURM_ARRAY_TASK_COUNT and
//      SLURM_ARRAY_TASK_STEP (index = (ID - MIN) / STEP; the array must be a range such as
//      --array=0-7 or 1-16 or 0-30:2, not a list such as 1,5,9);
//   3. a Kubernetes Indexed Job: JOB_COMPLETION_INDEX, with VLIT_SHARD_COUNT set to the Job's
//      completions (Kubernetes does not put the count in the environment);
//   4. GNU parallel: PARALLEL_SEQ (its job number {#}, from 1), with VLIT_SHARD_COUNT.
struct ShardSource {
  Shard shard;
  std::string from;  // the variables used, e.g. "SLURM_ARRAY_TASK_ID=3 ..."
};
using EnvironmentLookup = std::function<const char*(const char*)>;
ShardSource shard_from_environment(const EnvironmentLookup& getenv);

}  // namespace vlit
