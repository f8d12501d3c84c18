// The shard rule of `vlit bake --shard` (batch/shard.h): every input in exactly one shard, the
// same shard whatever the order of the inputs, and the environments of Slurm, Kubernetes and GNU
// parallel read as documented.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <random>
#include <set>

#include "batch/shard.h"
#include "core/input_error.h"

using namespace vlit;

namespace {

std::vector<std::string> asset_keys(int n) {
  std::vector<std::string> keys;
  for (int i = 0; i < n; ++i)
    keys.push_back("lib/" + std::to_string(i % 7) + "/asset" + std::to_string(i) + (i % 3 ? ".glb" : ".gltf"));
  return keys;
}

EnvironmentLookup environment(std::map<std::string, std::string> vars) {
  auto shared = std::make_shared<std::map<std::string, std::string>>(std::move(vars));
  return [shared](const char* name) -> const char* {
    const auto it = shared->find(name);
    return it == shared->end() ? nullptr : it->second.c_str();
  };
}

}  // namespace

TEST_CASE("FNV-1a 64 matches its published test vectors") {
  CHECK(fnv1a_64("") == 0xcbf29ce484222325ull);
  CHECK(fnv1a_64("a") == 0xaf63dc4c8601ec8cull);
  CHECK(fnv1a_64("foobar") == 0x85944171f73967e8ull);
}

TEST_CASE("shard rule: pinned values, so that a change of rule (which would re-split running batches) is seen") {
  // Computed by an independent Python reimplementation of the rule (docs/batch-sharding.md).
  CHECK(splitmix64_finalizer(fnv1a_64("Duck/glTF/Duck.gltf")) == 0xde988335232ab2c1ull);
  CHECK(splitmix64_finalizer(fnv1a_64("Duck/glTF-Quantized/Duck.gltf")) == 0xd9e100357ee60373ull);
  CHECK(shard_of_key("Duck/glTF/Duck.gltf", 4) == 1);
  CHECK(shard_of_key("Duck/glTF-Quantized/Duck.gltf", 4) == 3);
  CHECK(shard_of_key("a.glb", 7) == 2);
  CHECK(shard_of_key("lib/3/asset10.glb", 1000) == 808);
  CHECK(shard_of_key("a.glb", 1) == 0);
}

TEST_CASE("every input is in exactly one of N shards, for N = 1 .. 9") {
  const auto keys = asset_keys(500);
  for (std::size_t n = 1; n <= 9; ++n) {
    std::map<std::string, int> times;
    for (std::size_t shard = 0; shard < n; ++shard)
      for (const auto& key : keys)
        if (shard_of_key(key, n) == shard) ++times[key];
    CAPTURE(n);
    CHECK(times.size() == keys.size());
    CHECK(std::all_of(times.begin(), times.end(), [](const auto& t) { return t.second == 1; }));
  }
}

TEST_CASE("a shard's inputs do not depend on their order, nor on the other inputs") {
  auto keys = asset_keys(300);
  auto members = [](const std::vector<std::string>& ks, std::size_t shard) {
    std::set<std::string> m;
    for (const auto& k : ks)
      if (shard_of_key(k, 4) == shard) m.insert(k);
    return m;
  };
  const auto before = members(keys, 2);
  std::mt19937 rng(17);
  std::shuffle(keys.begin(), keys.end(), rng);
  CHECK(members(keys, 2) == before);
  // Half the batch gone: the remaining inputs stay in their shards.
  keys.resize(150);
  for (const auto& k : members(keys, 2)) CHECK(before.count(k) == 1);
}

TEST_CASE("shards are balanced, also on names whose bytes differ only in high bits") {
  // 1000 names over 4 shards: each within 20 % of 250.
  std::vector<std::size_t> sizes(4);
  for (int i = 0; i < 1000; ++i) {
    std::string name = "a";  // built piece by piece: GCC 12 warns falsely (-Wrestrict) on "a" + std::string&&
    name += std::to_string(i);
    name += ".glb";
    ++sizes[shard_of_key(name, 4)];
  }
  for (std::size_t s : sizes) {
    CAPTURE(s);
    CHECK(s > 200);
    CHECK(s < 300);
  }
  // FNV-1a's hash mod 4 depends only on the two low bits of each byte: tile_048.glb,
  // tile_804.glb, ... ('0' '4' '8' are equal mod 4) would all share one shard, and with the
  // names from 1 5 9, the 54 tiles would fill 2 shards of 4. The finalizer uses all four.
  std::vector<std::size_t> tiles(4);
  for (const char* digits : {"048", "159"})
    for (int i = 0; i < 27; ++i) {
      std::string name = "tile_";
      for (int k = 0, rest = i; k < 3; ++k, rest /= 3) name += digits[rest % 3];
      name += ".glb";
      ++tiles[shard_of_key(name, 4)];
    }
  for (std::size_t s : tiles) {
    CAPTURE(s);
    CHECK(s >= 5);
  }
}

TEST_CASE("--shard I/N: whole numbers, I below N") {
  CHECK(parse_shard("0/1").count == 1);
  const Shard s = parse_shard("3/8");
  CHECK(s.index == 3);
  CHECK(s.count == 8);
  CHECK(s.text() == "3/8");
  for (const char* bad : {"", "3", "4/4", "1/0", "-1/4", "a/4", "1/4x", "1 /4", "/4", "1/"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(parse_shard(bad), InputError);
  }
  try {
    parse_shard("4/4");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("numbered from 0") != std::string::npos);
  }
}

TEST_CASE("--shard auto: Slurm job arrays, minus SLURM_ARRAY_TASK_MIN, divided by the step") {
  auto slurm = [](std::string id, std::string min, std::string max, std::string count, std::string step = "1") {
    return shard_from_environment(environment({{"SLURM_ARRAY_TASK_ID", id}, {"SLURM_ARRAY_TASK_MIN", min},
                                               {"SLURM_ARRAY_TASK_MAX", max}, {"SLURM_ARRAY_TASK_COUNT", count},
                                               {"SLURM_ARRAY_TASK_STEP", step}}));
  };
  CHECK(slurm("0", "0", "3", "4").shard.text() == "0/4");
  CHECK(slurm("3", "0", "3", "4").shard.text() == "3/4");
  CHECK(slurm("1", "1", "16", "16").shard.text() == "0/16");  // --array=1-16
  CHECK(slurm("16", "1", "16", "16").shard.text() == "15/16");
  CHECK(slurm("4", "0", "6", "4", "2").shard.text() == "2/4");  // --array=0-6:2
  CHECK(slurm("2", "0", "3", "4").from.find("SLURM_ARRAY_TASK_ID=2") != std::string::npos);
  CHECK_THROWS_AS(slurm("5", "1", "9", "3"), InputError);  // --array=1,5,9 with step 1: not a range
  CHECK_THROWS_AS(slurm("x", "0", "3", "4"), InputError);
  CHECK_THROWS_AS(shard_from_environment(environment({{"SLURM_ARRAY_TASK_ID", "2"}})), InputError);
}

TEST_CASE("--shard auto: Kubernetes and GNU parallel need VLIT_SHARD_COUNT, VLIT_SHARD_INDEX wins") {
  CHECK(shard_from_environment(environment({{"JOB_COMPLETION_INDEX", "5"}, {"VLIT_SHARD_COUNT", "8"}})).shard.text() == "5/8");
  try {
    shard_from_environment(environment({{"JOB_COMPLETION_INDEX", "5"}}));
    FAIL("no count: must throw");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("VLIT_SHARD_COUNT") != std::string::npos);
  }
  CHECK_THROWS_AS(shard_from_environment(environment({{"JOB_COMPLETION_INDEX", "8"}, {"VLIT_SHARD_COUNT", "8"}})), InputError);
  CHECK(shard_from_environment(environment({{"PARALLEL_SEQ", "1"}, {"VLIT_SHARD_COUNT", "3"}})).shard.text() == "0/3");
  CHECK(shard_from_environment(environment({{"PARALLEL_SEQ", "3"}, {"VLIT_SHARD_COUNT", "3"}})).shard.text() == "2/3");
  CHECK_THROWS_AS(shard_from_environment(environment({{"PARALLEL_SEQ", "4"}, {"VLIT_SHARD_COUNT", "3"}})), InputError);
  // Explicit variables override a scheduler's (e.g. GNU parallel inside a Slurm task).
  CHECK(shard_from_environment(environment({{"VLIT_SHARD_INDEX", "1"}, {"VLIT_SHARD_COUNT", "2"},
                                             {"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_MIN", "0"},
                                             {"SLURM_ARRAY_TASK_COUNT", "4"}}))
            .shard.text() == "1/2");
  CHECK_THROWS_AS(shard_from_environment(environment({})), InputError);
}
