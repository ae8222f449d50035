// What `lituya post` is told about the run in a case folder (solve.hpp,
// incomplete_run_problem): only a summary that says completed = true passes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lituya/common/error_message.hpp"
#include "lituya/solver/solve.hpp"

namespace {

namespace fs = std::filesystem;
using lituya::solver::incomplete_run_problem;

class RunState : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("lituya_run_state_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(folder_);
    fs::create_directories(folder_ / "output");
    std::ofstream(folder_ / "stages.toml") << "format = \"lituya-stages\"\n";
  }
  void TearDown() override { fs::remove_all(folder_); }
  void summary(const std::string& text) {
    std::ofstream(folder_ / "output" / "summary.toml")
        << "format = \"lituya-summary\"\nversion = 2\n"
        << text;
  }
  std::string problem() const { return incomplete_run_problem(folder_).value_or(""); }
  fs::path folder_;
};

TEST_F(RunState, CompletedRunPasses) {
  summary("state = \"completed\"\ncompleted = true\n");
  EXPECT_EQ(problem(), "");
}

TEST_F(RunState, SummaryOfFormatVersion1StillPasses) {
  // Runs solved before the state was recorded: completed = true is all they have.
  summary("completed = true\n");
  EXPECT_EQ(problem(), "");
}

TEST_F(RunState, MissingSummaryIsIncomplete) {
  EXPECT_NE(problem().find("not found"), std::string::npos) << problem();
}

TEST_F(RunState, StoppedRunGivesItsReason) {
  summary("state = \"stopped\"\ncompleted = false\nreason = \"stopped by SIGINT in stage 'a'\"\n");
  EXPECT_NE(problem().find("state \"stopped\": stopped by SIGINT"), std::string::npos) << problem();
}

TEST_F(RunState, FailedRunGivesItsError) {
  summary("completed = false\nerror = \"step 12: velocity not finite\"\n");
  EXPECT_NE(problem().find("velocity not finite"), std::string::npos) << problem();
}

TEST_F(RunState, RunningMeansKilledOrStillRunning) {
  summary("state = \"running\"\ncompleted = false\n");
  EXPECT_NE(problem().find("killed or is still running"), std::string::npos) << problem();
}

TEST_F(RunState, TruncatedSummaryIsIncomplete) {
  summary("state = \"comp");
  EXPECT_NE(problem().find("cannot be read"), std::string::npos) << problem();
}

TEST_F(RunState, FolderThatIsNotACaseIsAnInputError) {
  fs::remove(folder_ / "stages.toml");
  EXPECT_NE(lituya::input_error_message([&] {
              incomplete_run_problem(folder_);
            }).find("not a case folder"),
            std::string::npos);
  EXPECT_NE(lituya::input_error_message([&] {
              incomplete_run_problem(folder_ / "missing");
            }).find("not found"),
            std::string::npos);
}

}  // namespace
