#include "lituya/common/json_file.hpp"

#include <cmath>

#include "lituya/common/atomic_file.hpp"

namespace lituya {

std::string json_text(const Json& value) {
  return value.dump(2) + "\n";
}

void write_json_file(const std::filesystem::path& file, const Json& value) {
  write_file_atomically(file, json_text(value));
}

Json json_number(double value) {
  return std::isfinite(value) ? Json(value) : Json(nullptr);
}

}  // namespace lituya
