// Ctrl-C (SIGINT) and SIGTERM. The first asks the running work to stop: the flag is polled by the
// per-vertex loop (about ten times a second, bake/light_vertices.h) and by the batch loop, and
// the file being baked is abandoned without output. The second ends the process at once with
// status 130, after removing the temporary file of a write in progress (io/atomic_write.h).
#pragma once

#include <atomic>

namespace vlit::cli {

void install_interrupt_handlers();
const std::atomic<bool>& interrupt_requested();

}  // namespace vlit::cli
