// Resuming a batch after a process was killed while writing (SIGKILL, preemption without grace,
// power loss): the hidden temporary it was writing (io/atomic_write.h) is still in the output
// folder. It is never taken for an output, but it takes space; --skip-existing removes those that
// belong to this shard's outputs, which no other shard writes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <set>
#include <string>

namespace vlit {

// Removes every temporary under out_dir (recursively) whose output is in `outputs` (paths as
// lexically normal strings); returns how many were removed.
std::size_t remove_abandoned_temporaries(const std::filesystem::path& out_dir, const std::set<std::string>& outputs);

}  // namespace vlit
