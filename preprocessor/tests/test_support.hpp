#pragma once
// Helpers shared by the preprocessor tests: paths to the sources, throw-away folders, and a
// check that an InputError names the expected file and line.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "lituya/common/input_error.hpp"

namespace lituya::pre::testing {

inline std::filesystem::path source_dir() {
  return LITUYA_SOURCE_DIR;
}
inline std::filesystem::path test_data(const std::string& name) {
  return source_dir() / "preprocessor" / "tests" / "data" / name;
}

// A fresh folder under the system temp folder, removed with its content at the end.
class TempFolder {
 public:
  TempFolder() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("lituya_pre_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

inline std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Runs `action`, expects an InputError whose file ends with `file_suffix`, whose line is
// `line` (0: not checked) and whose message contains every one of `words`; returns it.
inline std::string expect_input_error(const std::function<void()>& action,
                                      const std::string& file_suffix, int line,
                                      const std::vector<std::string>& words = {}) {
  try {
    action();
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_TRUE(e.file().ends_with(file_suffix)) << "file: " << e.file() << "\n" << message;
    if (line > 0) {
      EXPECT_EQ(e.line(), line) << message;
    }
    EXPECT_NE(message.find(e.file()), std::string::npos) << message;
    for (const auto& w : words)
      EXPECT_NE(message.find(w), std::string::npos) << "missing '" << w << "' in: " << message;
    return message;
  }
  ADD_FAILURE() << "expected an InputError about " << file_suffix;
  return {};
}

}  // namespace lituya::pre::testing
