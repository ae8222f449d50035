// Machine-readable summaries: every double exactly, non-finite values as null, strings escaped.
#include "lituya/common/json_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

TEST(JsonFile, KeepsEveryDoubleAndEscapesStrings) {
  lituya::Json summary;
  summary["measured"] = 0.1 + 0.2;
  summary["tiny"] = 4.9406564584124654e-324;
  summary["third"] = 1.0 / 3.0;
  summary["missing"] = lituya::json_number(NAN);
  summary["infinite"] = lituya::json_number(INFINITY);
  summary["message"] = "line 1\n\"quoted\" \\ tab\t";
  const std::string text = lituya::json_text(summary);
  EXPECT_NE(text.find("0.30000000000000004"), std::string::npos) << text;
  EXPECT_NE(text.find("\"missing\": null"), std::string::npos) << text;
  EXPECT_NE(text.find("\"infinite\": null"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("line 1\n\"quoted\" \\ tab\t")"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
  // Keys stay in the order they were set, not sorted.
  EXPECT_LT(text.find("\"measured\""), text.find("\"tiny\""));
  EXPECT_LT(text.find("\"third\""), text.find("\"missing\""));
  EXPECT_LT(text.find("\"missing\""), text.find("\"infinite\""));

  const auto file = std::filesystem::temp_directory_path() / "lituya_json_file_test.json";
  lituya::write_json_file(file, summary);
  std::ifstream in(file);
  const nlohmann::json back = nlohmann::json::parse(in);
  EXPECT_EQ(back["measured"].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(back["tiny"].get<double>(), 4.9406564584124654e-324);
  EXPECT_EQ(back["third"].get<double>(), 1.0 / 3.0);
  EXPECT_TRUE(back["missing"].is_null());
  EXPECT_EQ(back["message"].get<std::string>(), summary["message"].get<std::string>());
  std::filesystem::remove(file);
}

}  // namespace
