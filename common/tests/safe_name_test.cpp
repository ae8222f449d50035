// The safe alphabet for names that become file names, its check in the TOML reader (with file
// and line), and the XML escaping of attribute values.
#include "lituya/common/safe_name.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lituya/common/error_message.hpp"
#include "lituya/common/toml_reader.hpp"
#include "lituya/common/xml_escape.hpp"

namespace {

TEST(SafeName, AcceptsTheDocumentedAlphabet) {
  for (const char* name : {"gravity", "release_2", "Stage-B", "run.1", "a", "0", "x_-."})
    EXPECT_FALSE(lituya::safe_name_problem(name)) << name;
  EXPECT_FALSE(lituya::safe_name_problem(std::string(lituya::kMaxSafeNameLength, 'a')));
}

// Each class of name the findings of issue 9 let through, with the reason given.
TEST(SafeName, RefusesEveryUnsafeClass) {
  const std::pair<std::string, std::string> refused[] = {
      {"", "empty"},
      {"grav/ity", "'/'"},
      {"a\\b", "'\\'"},
      {"a b", "a space"},
      {"a\nb", "a line break"},
      {"a\tb", "a tab"},
      {"a&b", "'&'"},
      {"<x>", "'<'"},
      {"a\"b", "'\"'"},
      {"a'b", "'''"},
      {"a:b", "':'"},
      {"caf\xC3\xA9", "non-ASCII"},
      {std::string("a\x01", 2), "control character 0x01"},
      {"..", "starts with '.'"},
      {".hidden", "starts with '.'"},
      {"-rf", "starts with '-'"},
      {"a..b", "\"..\""},
      {std::string(lituya::kMaxSafeNameLength + 1, 'a'), "65 characters"},
  };
  for (const auto& [name, reason] : refused) {
    const auto problem = lituya::safe_name_problem(name);
    ASSERT_TRUE(problem) << lituya::quoted_for_message(name);
    EXPECT_NE(problem->find(reason), std::string::npos) << *problem;
  }
}

TEST(SafeName, MessagesQuoteNamesOnOneLine) {
  EXPECT_EQ(lituya::quoted_for_message("a\nb\t\"c\"\x01"), "\"a\\nb\\t\\\"c\\\"\\x01\"");
}

TEST(SafeName, TomlReaderRefusesAtTheLineOfTheKey) {
  const auto path = std::filesystem::temp_directory_path() / "lituya_safe_name.toml";
  std::ofstream(path) << "ok = \"release\"\n\nslash = \"grav/ity\"\nempty = \"\"\n"
                         "newline = \"a\\nb\"\n";
  lituya::TomlDocument doc(path);
  const lituya::TomlTable root = doc.root();
  EXPECT_EQ(root.safe_name("ok"), "release");
  std::string msg = lituya::input_error_message([&] { root.safe_name("slash"); });
  EXPECT_NE(msg.find("lituya_safe_name.toml:3:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'/'"), std::string::npos) << msg;
  EXPECT_NE(msg.find(std::string(lituya::safe_name_rule())), std::string::npos) << msg;
  msg = lituya::input_error_message([&] { root.safe_name("empty"); });
  EXPECT_NE(msg.find("lituya_safe_name.toml:4:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("empty"), std::string::npos) << msg;
  msg = lituya::input_error_message([&] { root.safe_name("newline"); });
  EXPECT_NE(msg.find("lituya_safe_name.toml:5:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("\"a\\nb\""), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos) << "the message spans lines: " << msg;
  msg = lituya::input_error_message([&] { root.safe_name("missing"); });
  EXPECT_NE(msg.find("missing required key"), std::string::npos) << msg;
}

TEST(XmlEscape, EscapesMarkupQuotesAndLineBreaks) {
  EXPECT_EQ(lituya::xml_escaped("a&b<c>\"d'"), "a&amp;b&lt;c&gt;&quot;d&apos;");
  EXPECT_EQ(lituya::xml_escaped("x\ny\tz\r"), "x&#10;y&#9;z&#13;");
  EXPECT_EQ(lituya::xml_escaped(std::string("bell\x07", 5)), "bell?");
  EXPECT_EQ(lituya::xml_escaped("plain_name-1.vtu"), "plain_name-1.vtu");
  EXPECT_EQ(lituya::xml_escaped("caf\xC3\xA9"), "caf\xC3\xA9");  // UTF-8 passes unchanged
}

}  // namespace
