#include "lituya/common/quoted_list.hpp"

#include <gtest/gtest.h>

namespace {

using lituya::quoted_list;

TEST(QuotedList, QuotesEachNameAndSeparatesThemWithCommas) {
  EXPECT_EQ(quoted_list({"sand"}), "\"sand\"");
  EXPECT_EQ(quoted_list({"sand", "water", "gravel"}), "\"sand\", \"water\", \"gravel\"");
}

TEST(QuotedList, SaysNothingWhenThereIsNothingToOffer) {
  // An error message reads "(defined: nothing)", never "(defined: )".
  EXPECT_EQ(quoted_list({}), "nothing");
}

}  // namespace
