// The one CSV writer: RFC 4180 quoting, LF records, numbers that read back exactly.
#include "lituya/common/csv_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>

namespace {

using lituya::csv_field;
using lituya::csv_number;
using lituya::csv_split;
using lituya::CsvWriter;

TEST(CsvWriter, QuotesOnlyFieldsThatNeedIt) {
  EXPECT_EQ(csv_field("front_travel"), "front_travel");
  EXPECT_EQ(csv_field("x=0.5 m"), "x=0.5 m");
  EXPECT_EQ(csv_field(""), "");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_field("cr\r"), "\"cr\r\"");
  EXPECT_EQ(csv_field("\""), "\"\"\"\"");
}

TEST(CsvWriter, WritesAHeaderAndRecordsEndingWithLf) {
  CsvWriter table({"run", "label, with comma", "value"});
  table.integer(1).text("plain").number(0.5).end_row();
  table.integer(2).text("he said \"no\"").number(NAN).end_row();
  table.row({1.0, -2.5, 1e-300});
  EXPECT_EQ(table.str(),
            "run,\"label, with comma\",value\n"
            "1,plain,0.5\n"
            "2,\"he said \"\"no\"\"\",\n"
            "1,-2.5,1e-300\n");
}

TEST(CsvWriter, RefusesARecordOfTheWrongWidth) {
  CsvWriter table({"a", "b"});
  table.number(1);
  EXPECT_THROW(table.end_row(), std::logic_error);
  CsvWriter other({"a", "b"});
  EXPECT_THROW(other.row({1, 2, 3}), std::logic_error);
}

TEST(CsvWriter, NumbersAreShortestAndReadBackExactly) {
  EXPECT_EQ(csv_number(0.1), "0.1");
  EXPECT_EQ(csv_number(0.1 + 0.2), "0.30000000000000004");  // %.10g would write 0.3
  EXPECT_EQ(csv_number(-0.0), "-0");
  EXPECT_EQ(csv_number(1e21), "1e+21");
  EXPECT_EQ(csv_number(123456789.0), "123456789");
  EXPECT_EQ(csv_number(NAN), "");
  EXPECT_EQ(csv_number(INFINITY), "");
  EXPECT_EQ(csv_number(-INFINITY), "");
  const double extremes[] = {std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::max(),
                             std::nextafter(1.0, 2.0),
                             9.81,
                             1.0 / 3.0};
  for (double v : extremes) EXPECT_EQ(std::strtod(csv_number(v).c_str(), nullptr), v) << v;
  // Random doubles over many magnitudes, bit for bit.
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for (int i = 0; i < 20000; ++i) {
    const double v = std::ldexp(mantissa(random), exponent(random));
    const std::string text = csv_number(v);
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
    ASSERT_LE(text.size(), 24u) << text;
  }
}

TEST(CsvWriter, SplitUndoesTheQuoting) {
  const std::vector<std::string> fields = {"plain", "a,b", "say \"hi\"", "", "\"", "x y"};
  CsvWriter table(fields);
  const std::string record = table.str().substr(0, table.str().size() - 1);  // without the LF
  EXPECT_EQ(csv_split(record), fields);
  EXPECT_EQ(csv_split("1,2,\r"), (std::vector<std::string>{"1", "2", ""}));
  EXPECT_EQ(csv_split(""), (std::vector<std::string>{""}));
  EXPECT_EQ(csv_split("\"two\nlines\",3"), (std::vector<std::string>{"two\nlines", "3"}));
}

TEST(CsvWriter, WritesTheFileWhole) {
  const auto file = std::filesystem::temp_directory_path() / "lituya_csv_writer_test.csv";
  CsvWriter table({"time", "eta"});
  table.row({0.25, 0.001});
  table.write(file);
  std::ifstream in(file, std::ios::binary);
  std::stringstream content;
  content << in.rdbuf();
  EXPECT_EQ(content.str(), "time,eta\n0.25,0.001\n");
  std::filesystem::remove(file);
}

}  // namespace
