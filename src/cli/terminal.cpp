#include "cli/terminal.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>

#include <sys/ioctl.h>
#include <unistd.h>

#include "bake/progress_line.h"

namespace vlit::cli {

void print_warning(const std::string& line) { std::cerr << "warning: " << line << "\n"; }
void print_error(const std::string& line) { std::cerr << "error: " << line << "\n"; }

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

std::size_t terminal_columns() {
  winsize size{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  if (const char* columns = std::getenv("COLUMNS")) {
    const long n = std::strtol(columns, nullptr, 10);
    if (n > 0) return static_cast<std::size_t>(n);
  }
  return 80;
}

Progress::Progress(const std::string& verb, std::string name, bool enabled)
    : label_(verb + " " + name), name_(std::move(name)), enabled_(enabled && stderr_is_terminal()),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

bool Progress::due(bool last) {
  if (!enabled_) return false;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100) && !last) return false;
  last_ = now;
  return true;
}

void Progress::draw(const std::string& full_line, const std::string& name) {
  // One column short of the width: a line that fills the last column wraps on some terminals.
  const std::string line = fit_width(full_line, name, terminal_columns() - 1);
  const std::size_t pad = width_ > line.size() ? width_ - line.size() : 0;
  std::fprintf(stderr, "\r%s%*s", line.c_str(), static_cast<int>(pad), "");
  std::fflush(stderr);
  width_ = line.size();
  drawn_ = true;
}

void Progress::warn_if_long(const std::string& name, double done, double total, double seconds) {
  if (warned_) return;
  const std::string warning = long_bake_warning(name, done, total, seconds);
  if (warning.empty()) return;
  warned_ = true;
  finish();
  print_warning(warning);
}

void Progress::update(std::size_t done, std::size_t total) {
  if (total == 0) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  warn_if_long(name_, static_cast<double>(done), static_cast<double>(total), seconds);
  if (!due(done >= total)) return;
  draw(progress_line(label_, static_cast<double>(done), static_cast<double>(total), seconds), name_);
}

void Progress::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
  width_ = 0;
}

BatchProgress::BatchProgress(std::size_t files, bool enabled) : line_("baking", "", enabled), files_(files) {}

void BatchProgress::draw(bool force) {
  if (!line_.due(force)) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - line_.start_).count();
  line_.draw(batch_progress_line(files_done_, files_, current_, fraction_, seconds), current_);
}

void BatchProgress::start_file(const std::string& name) {
  current_ = name;
  fraction_ = 0;
  file_start_ = std::chrono::steady_clock::now();
  line_.warned_ = false;
  draw(true);
}

void BatchProgress::update_file(std::size_t done, std::size_t total) {
  fraction_ = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - file_start_).count();
  line_.warn_if_long(current_, static_cast<double>(done), static_cast<double>(total), seconds);
  draw(false);
}

void BatchProgress::finish_file() {
  ++files_done_;
  current_.clear();
  fraction_ = 0;
  draw(true);
}

void BatchProgress::clear() { line_.finish(); }

}  // namespace vlit::cli
