#pragma once
// `lituya sweep`: one scene run once per value of one of its parameters, as a parametric
// study does (the paper's Case B: the first wave crest at the gauges against the friction
// angle). For each value the sweep writes a copy of the scene with that value into
// DIR/run_NN_<value>/scene.toml and runs pre + solve + post on it (the case in
// DIR/run_NN_<value>/case/), then reads its measures (measures.hpp) from the post tables.
// A run that fails is recorded with its message and the sweep goes on with the next value.
// At the end: DIR/sweep.csv (one row per run), DIR/sweep.png (each measure against the
// parameter) and DIR/sweep.toml (the sweep's definition, to run it again).
//
// Every scene copy is checked by the scene reader before anything is written: when no value
// gives a valid scene (a misspelt key, say), the sweep stops with an InputError and writes
// nothing; a value that alone is invalid becomes a failed run.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "lituya/sweep/definition.hpp"

namespace lituya::sweep {

struct SweepOptions {
  int threads = 1;                    // OpenMP threads of each solve
  bool overwrite = false;             // --force: write into a sweep folder that already holds files
  std::ostream* progress = nullptr;   // the sweep's progress line and one line per run
  bool progress_is_terminal = false;  // redraw the progress line in place
  std::ostream* report = nullptr;     // the table of results at the end
  bool dry_run = false;  // check the scene copies and the measures, report the plan, run
                         // nothing and write nothing
};

enum class RunStatus { kOk, kInputError, kRunStopped, kError };
// "ok", "input error", "run stopped", "error" (the status column of sweep.csv).
std::string status_text(RunStatus status);

struct RunRecord {
  int number = 0;                // from 1, in the order of the values
  std::string value;             // as given
  std::string literal;           // as written into the scene copy
  std::filesystem::path folder;  // DIR/run_NN_<value>
  RunStatus status = RunStatus::kOk;
  std::string message;           // what went wrong, empty when ok
  double wall_time = 0;          // s: pre + solve + post
  std::vector<double> measures;  // one per measure; NaN: no value
};

struct SweepResult {
  std::string parameter;
  std::string label;                  // its short name, e.g. "friction_angle"
  std::vector<std::string> measures;  // measure names = sweep.csv columns
  std::vector<RunRecord> runs;
  std::filesystem::path folder, table, plot;
  bool plotted = false;  // false when gnuplot is missing or failed
  bool all_ok() const;
};

// Runs the sweep (with dry_run: only its checks; the runs then have wall_time 0 and the
// status of their scene copy). InputError (naming the scene, the sweep file or the option) for a
// wrong key, value or measure, or an output folder that holds files without `overwrite`; such
// errors are raised before anything is written. Errors of single runs are recorded in the result.
SweepResult run_sweep(const SweepDefinition& definition, const SweepOptions& options);

// "run_03_18" (number 3 of up to 99 runs, value 18): the number padded to the digits of
// `count` (at least 2), the value with characters other than letters, digits and ._+-
// replaced by '_' and cut to 40 characters.
std::string run_folder_name(int number, int count, const std::string& value);

// The table printed at the end: one row per run, then the messages of the failed runs.
std::string format_table(const SweepResult& result);

}  // namespace lituya::sweep
