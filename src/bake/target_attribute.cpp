#include "bake/target_attribute.h"

#include <algorithm>
#include <cctype>

namespace vlit {

std::string target_attribute_problem(const std::string& name) {
  const std::string prefix = "COLOR_";
  if (name.compare(0, prefix.size(), prefix) == 0) {
    const std::string n = name.substr(prefix.size());
    const bool digits = !n.empty() && std::all_of(n.begin(), n.end(), [](unsigned char c) { return std::isdigit(c); });
    if (digits && (n == "0" || n[0] != '0') && n.size() <= 9) return {};
  } else if (name.size() >= 2 && name[0] == '_') {
    return {};
  }
  return "\"" + name + "\" is not an attribute that can hold a colour: use COLOR_n (COLOR_0, COLOR_1, ...) or an "
         "application-specific name starting with an underscore (_LIGHT)";
}

}  // namespace vlit
