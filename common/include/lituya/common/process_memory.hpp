#pragma once
#include <cstddef>

namespace lituya {
// Peak resident set size of this process in bytes (VmHWM), 0 if unknown.
std::size_t peak_memory_bytes();
// Current resident set size in bytes (VmRSS), 0 if unknown.
std::size_t current_memory_bytes();
}  // namespace lituya
