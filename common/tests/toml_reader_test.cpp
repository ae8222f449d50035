#include "lituya/common/toml_reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lituya/common/error_message.hpp"
#include "lituya/common/input_error.hpp"

namespace {

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

// Runs `f` and returns the InputError message (empty if none was thrown).
using lituya::input_error_message;

TEST(TomlReader, ReadsTypedValuesAndRanges) {
  auto path = write_file("lituya_toml_ok.toml",
                         "format = \"x\"\nversion = 1\nn = 3\nd = 2.5\ns = \"a\"\nv = [1, 2.0]\n");
  lituya::TomlDocument doc(path);
  auto root = doc.root();
  EXPECT_EQ(lituya::TomlDocument::check_header(root, "x", 1), 1);
  EXPECT_DOUBLE_EQ(root.number("n"), 3.0);  // an integer is accepted as a number
  EXPECT_DOUBLE_EQ(root.number_in("d", 0, 10), 2.5);
  EXPECT_EQ(root.string("s"), "a");
  EXPECT_EQ(root.numbers("v"), (std::vector<double>{1.0, 2.0}));
  EXPECT_DOUBLE_EQ(root.number_or("missing", 7.0), 7.0);
  root.finish();
}

TEST(TomlReader, UnknownKeyNamesFileAndLine) {
  auto path = write_file("lituya_toml_unknown.toml", "a = 1\n\nfrction_angle = 30\n");
  lituya::TomlDocument doc(path);
  auto root = doc.root();
  root.number("a");
  std::string msg = input_error_message([&] { root.finish(); });
  EXPECT_NE(msg.find("lituya_toml_unknown.toml:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("frction_angle"), std::string::npos) << msg;
}

TEST(TomlReader, WrongTypeAndRangeAndSyntax) {
  auto path = write_file("lituya_toml_bad.toml", "a = \"ten\"\nb = 2.0\n");
  lituya::TomlDocument doc(path);
  auto root = doc.root();
  std::string msg = input_error_message([&] { root.number("a"); });
  EXPECT_NE(msg.find(":1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must be a number"), std::string::npos) << msg;
  msg = input_error_message([&] { root.number_in("b", 0.0, 1.0); });
  EXPECT_NE(msg.find(":2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("outside the allowed range"), std::string::npos) << msg;
  msg = input_error_message([&] { root.number("c"); });
  EXPECT_NE(msg.find("missing required key 'c'"), std::string::npos) << msg;

  auto syntax = write_file("lituya_toml_syntax.toml", "a = 1\nb = = 2\n");
  msg = input_error_message([&] { lituya::TomlDocument d(syntax); });
  EXPECT_NE(msg.find("lituya_toml_syntax.toml:2"), std::string::npos) << msg;
  msg = input_error_message([&] { lituya::TomlDocument d("/nonexistent/lituya.toml"); });
  EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
}

// TOML spells inf and nan as floats; gravity = [0, -inf] once passed `lituya pre`. Every
// number getter refuses them, at the line of the key (of the element, in a split array).
TEST(TomlReader, NonFiniteNumbersAreRefused) {
  auto path = write_file("lituya_toml_nonfinite.toml",
                         "a = inf\nb = nan\nc = -inf\ng = [0.0, -inf]\n"
                         "h = [0.0,\n     nan]\n");
  lituya::TomlDocument doc(path);
  auto root = doc.root();
  const std::pair<const char*, int> scalars[] = {{"a", 1}, {"b", 2}, {"c", 3}};
  for (const auto& [key, line] : scalars) {
    for (auto get : {+[](const lituya::TomlTable&t, const char*k) { t.number(k); },
                     +[](const lituya::TomlTable&t, const char*k) { t.number_or(k, 1.0); },
                     +[](const lituya::TomlTable&t, const char*k) { t.number_in(k, -1, 1); }}) {
      std::string msg = input_error_message([&] { get(root, key); });
      EXPECT_NE(msg.find("lituya_toml_nonfinite.toml:" + std::to_string(line) + ":"),
                std::string::npos)
          << msg;
      EXPECT_NE(msg.find("not a finite number"), std::string::npos) << msg;
    }
  }
  std::string msg = input_error_message([&] { root.numbers("g"); });
  EXPECT_NE(msg.find("lituya_toml_nonfinite.toml:4:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("-inf"), std::string::npos) << msg;
  msg = input_error_message([&] { root.numbers("h"); });
  EXPECT_NE(msg.find("lituya_toml_nonfinite.toml:6:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nan"), std::string::npos) << msg;
  // A literal beyond the double range: refused by the parser or as non-finite, never inf.
  auto big = write_file("lituya_toml_big.toml", "k = 1e400\n");
  msg = input_error_message([&] { lituya::TomlDocument(big).root().number("k"); });
  EXPECT_NE(msg.find("lituya_toml_big.toml:1"), std::string::npos) << msg;
}

TEST(TomlReader, HeaderFormatAndVersionChecked) {
  auto path = write_file("lituya_toml_header.toml", "format = \"lituya-scene\"\nversion = 9\n");
  lituya::TomlDocument doc(path);
  std::string msg = input_error_message(
      [&] { lituya::TomlDocument::check_header(doc.root(), "lituya-scene", 1); });
  EXPECT_NE(msg.find("version 9 is not supported"), std::string::npos) << msg;
  msg = input_error_message(
      [&] { lituya::TomlDocument::check_header(doc.root(), "lituya-stages", 1); });
  EXPECT_NE(msg.find("expected \"lituya-stages\""), std::string::npos) << msg;
}

}  // namespace
