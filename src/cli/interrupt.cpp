#include "cli/interrupt.h"

#include <csignal>

#include <unistd.h>

#include "io/atomic_write.h"

namespace vlit::cli {
namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void on_interrupt(int) {
  if (!g_interrupted.exchange(true)) return;
  // Second signal: only async-signal-safe calls from here on.
  remove_temporary_in_progress();
  static const char kMessage[] = "\nerror: interrupted again; stopped at once (the file being baked has no output)\n";
  [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  ::_exit(130);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

const std::atomic<bool>& interrupt_requested() { return g_interrupted; }

}  // namespace vlit::cli
