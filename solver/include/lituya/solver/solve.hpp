#pragma once
// `lituya solve`: load a case folder, run its stages in order, write VTU output, a log and a
// summary with the throughput of each stage. A run that goes unstable stops with a
// diagnostic (RunError) and keeps the output written up to then.
#include <filesystem>
#include <iosfwd>
#include <vector>

#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

struct SolveOptions {
  std::filesystem::path output_folder;  // default: <case>/output
  int threads = 1;
  bool overwrite = false;
  std::ostream* progress = nullptr;  // progress line and stage summaries
};

std::vector<StageReport> solve_case(const std::filesystem::path& case_folder,
                                    const SolveOptions& options);

}  // namespace lituya::solver
