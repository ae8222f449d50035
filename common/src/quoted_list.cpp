#include "lituya/common/quoted_list.hpp"

namespace lituya {

std::string quoted_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
  return list.empty() ? "nothing" : list;
}

}  // namespace lituya
