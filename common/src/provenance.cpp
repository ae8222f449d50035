#include "lituya/common/provenance.hpp"

#include <ctime>

#include "lituya/common/build_version.hpp"

namespace lituya {

const char* lituya_version() {
  return build::kVersion;
}

const char* lituya_commit() {
  return build::kCommit;
}

std::string version_line() {
  return std::string("lituya ") + build::kVersion + " (commit " + build::kCommit + ")";
}

std::string utc_iso8601(std::chrono::system_clock::time_point time) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(time);
  std::tm utc{};
  gmtime_r(&seconds, &utc);  // the reentrant form: solves may run on several threads
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string utc_now_iso8601() {
  return utc_iso8601(std::chrono::system_clock::now());
}

}  // namespace lituya
