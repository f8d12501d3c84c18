#include "batch/shard.h"

#include <charconv>
#include <optional>

#include "core/input_error.h"

namespace vlit {
namespace {

// A whole decimal number, nothing else.
std::optional<std::size_t> parse_count(std::string_view text) {
  std::size_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

}  // namespace

std::string Shard::text() const { return std::to_string(index) + "/" + std::to_string(count); }

std::uint64_t fnv1a_64(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;
  }
  return h;
}

std::uint64_t splitmix64_finalizer(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

std::size_t shard_of_key(std::string_view key, std::size_t count) {
  return static_cast<std::size_t>(splitmix64_finalizer(fnv1a_64(key)) % count);
}

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const auto index = slash == std::string::npos ? std::nullopt : parse_count(std::string_view(text).substr(0, slash));
  const auto count = slash == std::string::npos ? std::nullopt : parse_count(std::string_view(text).substr(slash + 1));
  if (!index || !count || *count == 0)
    throw InputError("--shard", "expected I/N with whole numbers 0 <= I < N (or auto), got \"" + text + "\"");
  if (*index >= *count)
    throw InputError("--shard", "shard index " + std::to_string(*index) + " is not below the count " +
                                    std::to_string(*count) + " (shards are numbered from 0): \"" + text + "\"");
  return {*index, *count};
}

ShardSource shard_from_environment(const EnvironmentLookup& getenv) {
  const std::string where = "--shard auto";
  auto get = [&](const char* name) -> std::optional<std::string> {
    const char* v = getenv(name);
    if (!v || !*v) return std::nullopt;
    return std::string(v);
  };
  auto number = [&](const char* name) -> std::size_t {
    const std::string v = *get(name);
    const auto n = parse_count(v);
    if (!n) throw InputError(where, std::string(name) + "=\"" + v + "\" is not a whole number >= 0");
    return *n;
  };
  auto make = [&](std::size_t index, std::size_t count, std::string from) {
    if (count == 0) throw InputError(where, from + ": the shard count is 0");
    if (index >= count)
      throw InputError(where, from + ": shard index " + std::to_string(index) + " is not below the count " +
                                  std::to_string(count));
    return ShardSource{{index, count}, std::move(from)};
  };
  auto count_for = [&](const std::string& source) -> std::size_t {
    if (!get("VLIT_SHARD_COUNT"))
      throw InputError(where, source + " is set but not the number of shards: set VLIT_SHARD_COUNT (docs/batch-sharding.md)");
    return number("VLIT_SHARD_COUNT");
  };

  if (get("VLIT_SHARD_INDEX")) {
    const std::size_t index = number("VLIT_SHARD_INDEX");
    const std::size_t count = count_for("VLIT_SHARD_INDEX");
    return make(index, count, "VLIT_SHARD_INDEX=" + std::to_string(index) + " VLIT_SHARD_COUNT=" + std::to_string(count));
  }
  if (get("SLURM_ARRAY_TASK_ID")) {
    for (const char* name : {"SLURM_ARRAY_TASK_COUNT", "SLURM_ARRAY_TASK_MIN"})
      if (!get(name)) throw InputError(where, std::string("SLURM_ARRAY_TASK_ID is set but not ") + name);
    const std::size_t id = number("SLURM_ARRAY_TASK_ID"), min = number("SLURM_ARRAY_TASK_MIN");
    const std::size_t count = number("SLURM_ARRAY_TASK_COUNT");
    const std::size_t step = get("SLURM_ARRAY_TASK_STEP") ? number("SLURM_ARRAY_TASK_STEP") : 1;
    std::string from = "SLURM_ARRAY_TASK_ID=" + std::to_string(id) + " SLURM_ARRAY_TASK_MIN=" + std::to_string(min) +
                       " SLURM_ARRAY_TASK_COUNT=" + std::to_string(count) + " SLURM_ARRAY_TASK_STEP=" + std::to_string(step);
    if (step == 0 || id < min || (id - min) % step != 0) throw InputError(where, from + ": not a task of a range");
    if (get("SLURM_ARRAY_TASK_MAX")) {
      const std::size_t max = number("SLURM_ARRAY_TASK_MAX");
      // A list such as --array=1,5,9 has no step that numbers its tasks 0 .. COUNT - 1.
      if (max < min || (max - min) / step + 1 != count)
        throw InputError(where, from + " SLURM_ARRAY_TASK_MAX=" + std::to_string(max) +
                                    ": the job array is not a range (use --array=0-" + std::to_string(count - 1) +
                                    " or pass --shard I/N)");
    }
    return make((id - min) / step, count, std::move(from));
  }
  if (get("JOB_COMPLETION_INDEX")) {
    const std::size_t index = number("JOB_COMPLETION_INDEX");
    const std::size_t count = count_for("JOB_COMPLETION_INDEX (Kubernetes Indexed Job)");
    return make(index, count, "JOB_COMPLETION_INDEX=" + std::to_string(index) + " VLIT_SHARD_COUNT=" + std::to_string(count));
  }
  if (get("PARALLEL_SEQ")) {
    const std::size_t seq = number("PARALLEL_SEQ");
    const std::size_t count = count_for("PARALLEL_SEQ (GNU parallel)");
    if (seq == 0) throw InputError(where, "PARALLEL_SEQ=0: GNU parallel numbers its jobs from 1");
    return make(seq - 1, count, "PARALLEL_SEQ=" + std::to_string(seq) + " VLIT_SHARD_COUNT=" + std::to_string(count));
  }
  throw InputError(where, "no shard in the environment: none of VLIT_SHARD_INDEX, SLURM_ARRAY_TASK_ID, "
                          "JOB_COMPLETION_INDEX, PARALLEL_SEQ is set (docs/batch-sharding.md)");
}

}  // namespace vlit
