#pragma once
// `lituya solve`: load a case folder, run its stages in order, write VTU output, a log and a
// summary with the throughput of each stage. A run that goes unstable stops with a
// diagnostic (RunError) and keeps the output written up to then.
//
// The summary always tells the truth about the run in its folder: it is written with
// state = "running" before the first step and rewritten after every stage and at the end
// ("completed", "stopped" by SIGINT/SIGTERM, or "failed"). A run killed outright (SIGKILL, a
// power cut) leaves "running", which `lituya post` refuses as it refuses any run that did not
// complete. With --force the earlier run's output is set aside first, so nothing of it can be
// mistaken for the new run's.
//
// Checkpoints (checkpoint.hpp) go to <output>/checkpoints: one at the end of every stage
// (<stage>_end.checkpoint), and within a stage every [solver] checkpoint_interval_minutes of
// wall time and when SIGINT/SIGTERM stop the run (latest.checkpoint). `resume` goes on from
// the newest of them, `from_stage` from the end of the stage before it; the VTU series, the
// .pvd files, log.txt and summary.toml then go on from those of the earlier run.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

struct SolveOptions {
  std::filesystem::path output_folder;  // default: <case>/output
  int threads = 1;
  bool overwrite = false;
  // With `overwrite` and an output folder that holds files: true moves that folder to
  // <output>.previous (replacing an older one), false deletes it. The verification runner
  // deletes: it re-creates its cases on every run and would otherwise double their size.
  bool keep_previous_output = true;
  std::ostream* progress = nullptr;  // progress line and stage summaries
  // Go on from the newest checkpoint in the output folder (the case files must be those that
  // wrote it). Excludes `overwrite` and `from_stage`.
  bool resume = false;
  // Re-run this stage and those after it from the end-of-stage checkpoint of the stage before
  // it (the files the earlier stages read must be unchanged; this stage and later ones may
  // differ). The output of this stage and later ones is replaced.
  std::string from_stage;
};

// Runs the case. Throws InputError for a bad case (or a checkpoint that cannot continue it:
// missing, damaged, from another build or other case files), RunError when the run goes
// unstable, and
// RunStopped (stop_request.hpp) when SIGINT/SIGTERM asked it to stop; each after writing the
// summary.
std::vector<StageReport> solve_case(const std::filesystem::path& case_folder,
                                    const SolveOptions& options);

inline constexpr const char* kSummaryFile = "summary.toml";

// The hash of the files of a case that the solve reads (stages.toml and the geometry, points,
// materials and liquid points it names), as content_hash.hpp's hash_files. Not post.toml:
// measuring differently does not change the run.
std::string case_files_hash(const std::filesystem::path& case_folder);

// The data files a case names (geometry, points, materials, liquid points), relative to the
// case folder where they lie inside it, sorted and without repeats: what the hashes cover
// besides stages.toml.
std::vector<std::filesystem::path> case_data_files(const CaseDescription& description,
                                                   const std::filesystem::path& case_folder);

// Why the run in `case_folder`/output cannot be trusted as complete: the summary is missing
// (never solved, or killed before it was written), unreadable, or says completed = false
// (running, stopped or failed; the message gives its reason). Nothing when it completed.
// Throws InputError when `case_folder` is not a case folder (no stages.toml).
std::optional<std::string> incomplete_run_problem(const std::filesystem::path& case_folder);

}  // namespace lituya::solver
