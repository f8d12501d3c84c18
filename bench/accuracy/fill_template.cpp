// The template filler of fill_template.h.
#include "fill_template.h"

#include <algorithm>
#include <stdexcept>

namespace vlit::bench::accuracy {
namespace {

struct Filler {
  const std::string& text;
  const Values& values;
  const std::string& name;

  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    const long line = 1 + std::count(text.begin(), text.begin() + long(at), '\n');
    throw std::runtime_error(name + ":" + std::to_string(line) + ": " + what);
  }

  // Fills text[begin, end) into out.
  void fill(std::size_t begin, std::size_t end, std::string& out) const {
    std::size_t at = begin;
    while (at < end) {
      const std::size_t open = text.find("{{", at);
      if (open == std::string::npos || open >= end) {
        out.append(text, at, end - at);
        return;
      }
      out.append(text, at, open - at);
      const std::size_t close = text.find("}}", open + 2);
      if (close == std::string::npos || close >= end) fail(open, "unclosed '{{'");
      const std::string tag = text.substr(open + 2, close - open - 2);
      if (tag.empty()) fail(open, "empty tag '{{}}'");
      if (tag[0] == '/') fail(open, "'{{" + tag + "}}' closes no block");
      if (tag[0] == '#' || tag[0] == '^') {
        const std::string key = tag.substr(1);
        const std::string end_tag = "{{/" + key + "}}";
        const std::size_t inner_end = text.find(end_tag, close + 2);
        if (inner_end == std::string::npos || inner_end >= end) fail(open, "block '{{" + tag + "}}' has no '" + end_tag + "'");
        const auto it = values.find(key);
        const bool set = it != values.end() && !it->second.empty();
        if (set == (tag[0] == '#')) fill(close + 2, inner_end, out);
        at = inner_end + end_tag.size();
        continue;
      }
      const auto it = values.find(tag);
      if (it == values.end()) fail(open, "no value named '" + tag + "'");
      out += it->second;
      at = close + 2;
    }
  }
};

}  // namespace

std::string fill_template(const std::string& text, const Values& values, const std::string& template_name) {
  std::string out;
  Filler{text, values, template_name}.fill(0, text.size(), out);
  return out;
}

}  // namespace vlit::bench::accuracy
