// The names an error message offers the user: "a", "b", "c" (or "nothing" when there are
// none), so that a message naming what was expected reads the same in every reader.
#pragma once

#include <string>
#include <vector>

namespace lituya {

std::string quoted_list(const std::vector<std::string>& names);

}  // namespace lituya
