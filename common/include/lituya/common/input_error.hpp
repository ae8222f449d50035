#pragma once
// An error in something the user wrote (a scene, a material, a mesh, a case folder).
// The message always names where (file, and line when known) and what was expected, so
// that `lituya` can print it as-is and stop without a crash or a stack trace.
#include <stdexcept>
#include <string>

namespace lituya {

class InputError : public std::runtime_error {
 public:
  // file: the path the user gave; line: 1-based, 0 when not applicable.
  InputError(const std::string& file, int line, const std::string& what_was_wrong);
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

// A run that cannot go on (instability, a point leaving the mesh). Its message names the
// step, the point or node, and the field.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lituya
