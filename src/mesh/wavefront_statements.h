// The line syntax shared by Wavefront .obj and .mtl files: one statement per line, a keyword
// followed by whitespace-separated arguments, `#` starts a comment, a line ending in `\` continues
// on the next. Numbers are parsed strictly (the whole token, finite), with errors that name the
// file and the line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vlit {

struct WavefrontStatement {
  std::size_t line = 0;                // 1-based line where the statement starts
  std::string keyword;
  std::vector<std::string> arguments;  // the rest of the line, split at whitespace
  std::string rest;                    // the rest of the line after the keyword, trimmed (names with spaces)
};

// Calls `visit(statement)` for every non-empty statement of `text`, in order.
template <typename Visit>
void for_each_wavefront_statement(std::string_view text, Visit&& visit);

// "line N" for InputError's `where`.
std::string wavefront_line(std::size_t line);

// The whole token as a finite double; throws InputError(file, "<what>: '<token>' is not a finite
// number", "line N") otherwise. With finite_only = false, "inf" and "nan" are returned as such.
double parse_wavefront_number(const std::string& token, const std::string& what, const std::string& file,
                              std::size_t line, bool finite_only = true);

// Splits one logical line (continuations already joined) into a statement; false if it is empty.
bool split_wavefront_statement(std::string_view logical_line, std::size_t line, WavefrontStatement& out);

template <typename Visit>
void for_each_wavefront_statement(std::string_view text, Visit&& visit) {
  std::size_t pos = 0, line = 1;
  std::string logical;
  WavefrontStatement statement;
  while (pos < text.size()) {
    const std::size_t start_line = line;
    logical.clear();
    for (;;) {  // one logical line: physical lines joined while they end in a backslash
      std::size_t end = text.find('\n', pos);
      if (end == std::string_view::npos) end = text.size();
      std::string_view physical = text.substr(pos, end - pos);
      pos = end + 1;
      ++line;
      if (!physical.empty() && physical.back() == '\r') physical.remove_suffix(1);
      if (!physical.empty() && physical.back() == '\\' && pos < text.size()) {
        physical.remove_suffix(1);
        logical.append(physical);
        logical.push_back(' ');
        continue;
      }
      logical.append(physical);
      break;
    }
    if (split_wavefront_statement(logical, start_line, statement)) visit(statement);
  }
}

}  // namespace vlit
