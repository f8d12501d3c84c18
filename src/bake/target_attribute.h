// Which vertex attribute a bake may write: one glTF allows to hold a colour. glTF 2.0 (section
// 3.7.2.1, "Meshes / Overview") names the colour sets COLOR_n (n = 0, 1, ...) and lets an
// application add its own attributes whose names start with an underscore (_LIGHT, _AO, ...).
// Every other name is either another built-in semantic with its own type (NORMAL, TEXCOORD_0, ...)
// or not allowed, so a bake into it would write an invalid glTF.
#pragma once

#include <string>

namespace vlit {

// Empty when `name` is COLOR_n (n a decimal number without leading zeros) or _NAME (an
// underscore and at least one more character); otherwise one sentence naming the value and what
// is allowed, for an error message.
std::string target_attribute_problem(const std::string& name);

}  // namespace vlit
