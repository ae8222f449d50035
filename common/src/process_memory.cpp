#include "lituya/common/process_memory.hpp"

#include <fstream>
#include <string>

namespace lituya {

namespace {
std::size_t read_status_kib(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(key, 0) == 0) return std::stoull(line.substr(key.size())) * 1024;
  }
  return 0;
}
}  // namespace

std::size_t peak_memory_bytes() {
  return read_status_kib("VmHWM:");
}
std::size_t current_memory_bytes() {
  return read_status_kib("VmRSS:");
}

}  // namespace lituya
