// SIGINT and SIGTERM only record a request while a StopSignalScope lives; the process goes on
// and the solve decides where to stop.
#include "lituya/common/stop_request.hpp"

#include <gtest/gtest.h>

#include <csignal>

namespace {

TEST(StopRequest, SignalIsRecordedNotFatalInsideTheScope) {
  {
    lituya::StopSignalScope scope;
    EXPECT_FALSE(lituya::stop_requested());
    std::raise(SIGTERM);  // without the handler, this would end the test program
    EXPECT_EQ(lituya::stop_signal(), SIGTERM);
    EXPECT_TRUE(lituya::stop_requested());
  }
  lituya::set_stop_signal(0);
  EXPECT_FALSE(lituya::stop_requested());
}

TEST(StopRequest, ScopeStartsClearAndRestoresThePreviousHandler) {
  lituya::set_stop_signal(SIGINT);
  struct sigaction before {};
  sigaction(SIGINT, nullptr, &before);
  {
    lituya::StopSignalScope scope;
    EXPECT_FALSE(lituya::stop_requested());  // a request of an earlier solve does not carry over
  }
  struct sigaction after {};
  sigaction(SIGINT, nullptr, &after);
  EXPECT_EQ(after.sa_handler, before.sa_handler);
}

TEST(StopRequest, NamesTheSignals) {
  EXPECT_EQ(lituya::signal_name(SIGINT), "SIGINT");
  EXPECT_EQ(lituya::signal_name(SIGTERM), "SIGTERM");
}

}  // namespace
