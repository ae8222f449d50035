#include "lituya/common/input_error.hpp"

#include <sstream>

namespace lituya {

namespace {
std::string format_location(const std::string& file, int line, const std::string& what) {
  std::ostringstream where;
  where << file;
  if (line > 0) where << ':' << line;
  where << ": " << what;
  return where.str();
}
}  // namespace

InputError::InputError(const std::string& file, int line, const std::string& what_was_wrong)
    : std::runtime_error(format_location(file, line, what_was_wrong)), file_(file), line_(line) {}

}  // namespace lituya
