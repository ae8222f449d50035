// The message of the InputError that a callable throws, or "" when it throws none: lets a
// test assert in one line that bad input is rejected with a message naming file and line.
#pragma once

#include <string>

#include "lituya/common/input_error.hpp"

namespace lituya {

template <class F>
std::string input_error_message(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace lituya
