#pragma once
// The verification runner: runs each case of verification/ (quick or full variant) through
// pre, solve and post, measures what the case's reference gives, and writes a report
// (Markdown + PNG + machine-readable summary.json) with measured vs reference vs tolerance.
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace lituya::verify {

struct RunnerOptions {
  std::filesystem::path report_folder = "verification-report";
  // Default: <prefix>/share/lituya/verification for an installed binary, else the source
  // tree's verification/ (default_verification_folder()).
  std::filesystem::path verification_folder;
  bool full = false;
  bool overwrite = false;
  int threads = 1;
  std::vector<std::string> only;  // case names; empty = all
  // Per case: a line when it starts, one with PASS/FAIL and its wall time when it ends, and
  // its checks; then the totals. nullptr: none (--quiet).
  std::ostream* progress = &std::cout;
};

// The cases of an installed binary (<bin>/../share/lituya/verification, found from
// /proc/self/exe) when that folder exists, else the source tree the binary was built from.
std::filesystem::path default_verification_folder();

// Returns true when every check of every case passed.
bool run_verification(const RunnerOptions& options);

}  // namespace lituya::verify
