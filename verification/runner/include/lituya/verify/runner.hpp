#pragma once
// The verification runner: runs each case of verification/ (quick or full variant) through
// pre, solve and post, measures what the case's reference gives, and writes a report
// (Markdown + PNG + machine-readable summary.json) with measured vs reference vs tolerance.
#include <filesystem>
#include <string>
#include <vector>

namespace lituya::verify {

struct RunnerOptions {
  std::filesystem::path report_folder = "verification-report";
  std::filesystem::path verification_folder;  // default: the source tree's verification/
  bool full = false;
  bool overwrite = false;
  int threads = 1;
  std::vector<std::string> only;  // case names; empty = all
};

// Returns true when every check of every case passed.
bool run_verification(const RunnerOptions& options);

}  // namespace lituya::verify
