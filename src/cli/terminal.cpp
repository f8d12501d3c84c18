#include "cli/terminal.h"

#include <cstdio>
#include <iostream>

#include <unistd.h>

#include "bake/progress_line.h"

namespace vlit::cli {

void print_warning(const std::string& line) { std::cerr << "warning: " << line << "\n"; }
void print_error(const std::string& line) { std::cerr << "error: " << line << "\n"; }

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled && stderr_is_terminal()),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

bool Progress::due(bool last) {
  if (!enabled_) return false;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100) && !last) return false;
  last_ = now;
  return true;
}

void Progress::draw(const std::string& line) {
  const std::size_t pad = width_ > line.size() ? width_ - line.size() : 0;
  std::fprintf(stderr, "\r%s%*s", line.c_str(), static_cast<int>(pad), "");
  std::fflush(stderr);
  width_ = line.size();
  drawn_ = true;
}

void Progress::update(std::size_t done, std::size_t total) {
  if (total == 0 || !due(done >= total)) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  draw(progress_line(label_, static_cast<double>(done), static_cast<double>(total), seconds));
}

void Progress::finish() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
  width_ = 0;
}

BatchProgress::BatchProgress(std::size_t files, bool enabled) : line_("baking", enabled), files_(files) {}

void BatchProgress::draw(bool force) {
  if (!line_.due(force)) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - line_.start_).count();
  line_.draw(batch_progress_line(files_done_, files_, current_, fraction_, seconds));
}

void BatchProgress::start_file(const std::string& name) {
  current_ = name;
  fraction_ = 0;
  draw(true);
}

void BatchProgress::update_file(std::size_t done, std::size_t total) {
  fraction_ = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0;
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
