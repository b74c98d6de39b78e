// `--set a.b.c=value` on the command line: changes one value of a scene document
// before it is read, so any scene value can be varied without editing the file.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace skylit {

// `assignment` is `path=value`. The path is dot-separated keys; a number selects an
// array element (`objects.0.material`). Missing objects on the way are created. The
// value is read as JSON if it parses (`4`, `true`, `[1,2,3]`, `"x"`), else taken as a
// string (`tile`). InputError "--set <assignment>: ..." when it cannot be applied.
void apply_override(nlohmann::json& document, const std::string& assignment);

}  // namespace skylit
