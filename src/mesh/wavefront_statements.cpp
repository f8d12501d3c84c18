#include "mesh/wavefront_statements.h"

#include <charconv>
#include <cmath>

#include "core/input_error.h"

namespace vlit {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

}  // namespace

std::string wavefront_line(std::size_t line) { return "line " + std::to_string(line); }

double parse_wavefront_number(const std::string& token, const std::string& what, const std::string& file,
                              std::size_t line, bool finite_only) {
  double value = 0;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (first != last && *first == '+') ++first;  // from_chars takes no leading '+'; files write it
  const auto [end, ec] = std::from_chars(first, last, value);
  if (token.empty() || ec != std::errc() || end != last || (finite_only && !std::isfinite(value)))
    throw InputError(file, what + ": '" + token + "' is not a finite number", wavefront_line(line));
  return value;
}

bool split_wavefront_statement(std::string_view text, std::size_t line, WavefrontStatement& out) {
  if (const std::size_t hash = text.find('#'); hash != std::string_view::npos) text = text.substr(0, hash);
  out.line = line;
  out.keyword.clear();
  out.arguments.clear();
  out.rest.clear();
  std::size_t i = 0;
  bool first = true;
  while (i < text.size()) {
    while (i < text.size() && is_space(text[i])) ++i;
    if (i == text.size()) break;
    const std::size_t start = i;
    while (i < text.size() && !is_space(text[i])) ++i;
    const std::string_view token = text.substr(start, i - start);
    if (first) {
      out.keyword.assign(token);
      std::size_t r = i;
      while (r < text.size() && is_space(text[r])) ++r;
      std::size_t e = text.size();
      while (e > r && is_space(text[e - 1])) --e;
      out.rest.assign(text.substr(r, e - r));
      first = false;
    } else {
      out.arguments.emplace_back(token);
    }
  }
  return !out.keyword.empty();
}

}  // namespace vlit
