// What every result records about the program that made it.
#include "lituya/common/provenance.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <string>

namespace {

TEST(Provenance, VersionAndCommitAreFilledIn) {
  EXPECT_FALSE(std::string(lituya::lituya_version()).empty());
  EXPECT_FALSE(std::string(lituya::lituya_commit()).empty());
  // The generated header was substituted: no @...@ placeholders left.
  EXPECT_EQ(std::string(lituya::lituya_commit()).find('@'), std::string::npos);
  EXPECT_EQ(lituya::version_line(), std::string("lituya ") + lituya::lituya_version() +
                                        " (commit " + lituya::lituya_commit() + ")");
}

TEST(Provenance, DatesAreUtcIso8601) {
  // 2001-09-09T01:46:40Z is 1e9 s after the epoch.
  EXPECT_EQ(lituya::utc_iso8601(std::chrono::system_clock::from_time_t(1000000000)),
            "2001-09-09T01:46:40Z");
  EXPECT_TRUE(std::regex_match(lituya::utc_now_iso8601(),
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
}

}  // namespace
