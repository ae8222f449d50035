#pragma once
// `lituya sweep`: one scene run once per value of one of its parameters, or per combination of
// the values of several (a grid of every combination, or paired lists), as a parametric study
// does (the paper's Case B: the first wave crest at the gauges against the friction angle).
// For each run the sweep writes a copy of the scene with its values into
// DIR/run_NN_<values>/scene.toml and runs pre + solve + post on it (the case in
// DIR/run_NN_<values>/case/), then reads its measures (measures.hpp) from the post tables and
// records the run in DIR/run_NN_<values>/run.json. A run that fails is recorded with its
// message and the sweep goes on with the next. At the end: DIR/sweep.csv (one row per run),
// DIR/sweep.json (the same, machine-readable, every number exact), DIR/sweep.png (each measure
// against the first parameter) and DIR/sweep.toml (the sweep's definition, to run it again).
// A sweep over `mesh.cell_size` also writes DIR/convergence.csv: each measure's Richardson
// estimate from its three finest cell sizes (convergence.hpp).
//
// Runs go one after another, or `jobs` at a time, each in a process of its own (fork): gmsh is
// one instance per process and not thread-safe, and a run that crashes then takes only itself
// down. A run's result does not depend on what runs beside it: with the same threads per run,
// a sweep gives the same numbers with any number of jobs.
//
// A key that only a later stage reads leaves the earlier stages as they were: with `reuse`
// (the default), a run whose first stages depend on the same inputs as those of a run that
// finished (solver::stage_inputs_hashes, the same hashes the checkpoints carry) starts from
// that run's end-of-stage checkpoint, as `lituya solve --from-stage` does, instead of running
// those stages again. Its output folder gets that run's frames of those stages (hard links
// where the file system allows, else copies) and its log up to their end. The results are
// bit for bit those of the whole run with the same threads. With `jobs`, a run that can take
// stages from an earlier one waits for it to finish. A key that changes the mesh, a material,
// a boundary or the first stage leaves nothing to reuse: every run then runs whole.
//
// A sweep that was stopped (Ctrl-C, a kill, a time limit) is continued with `resume`: a run
// whose scene copy is unchanged, whose solve completed (summary.toml) on the case files it
// recorded (the case hash) and whose run.json says ok is kept and not run again.
//
// Every scene copy is checked by the scene reader before anything is written: when no run
// gives a valid scene (a misspelt key, say), the sweep stops with an InputError and writes
// nothing; a run whose copy alone is invalid becomes a failed run.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "lituya/sweep/definition.hpp"

namespace lituya::sweep {

struct SweepOptions {
  int threads = 1;         // OpenMP threads of each solve
  int jobs = 1;            // runs side by side, each in a process of its own
  bool overwrite = false;  // --force: write into a sweep folder that already holds files, and
                           // run every run again
  bool resume = false;     // continue the sweep in its folder, keeping the runs that finished
  std::ostream* progress = nullptr;   // the sweep's progress line and one line per run
  bool progress_is_terminal = false;  // redraw the progress line in place
  std::ostream* report = nullptr;     // the table of results at the end
  bool dry_run = false;  // check the scene copies and the measures, report the plan, run
                         // nothing and write nothing
  bool reuse = true;     // start a run from the end state of the stages it shares with a run
                         // that finished (false: --no-reuse, every run runs whole)
};

enum class RunStatus { kOk, kInputError, kRunStopped, kError };
// "ok", "input error", "run stopped", "error" (the status column of sweep.csv).
std::string status_text(RunStatus status);
// The status a status_text names; kError for any other text.
RunStatus status_from_text(const std::string& text);

struct RunRecord {
  int number = 0;                     // from 1, in run order
  std::vector<std::string> values;    // one per parameter, as given
  std::vector<std::string> literals;  // one per parameter, as written into the scene copy
  std::filesystem::path folder;       // DIR/run_NN_<values>
  RunStatus status = RunStatus::kOk;
  bool kept = false;             // resumed sweep: finished before, not run again
  std::string message;           // what went wrong, empty when ok
  double wall_time = 0;          // s: pre + solve + post (of the earlier sweep when kept)
  std::vector<double> measures;  // one per measure; NaN: no value
  // The first stages this run took from run `reused_from` (its number) instead of running
  // them; none when it ran whole.
  int reused_from = 0;
  std::vector<std::string> reused_stages;
  // "friction_angle=18" or "friction_angle=18 cell_size=0.01", with the labels of the keys.
  std::string label(const std::vector<std::string>& labels) const;
};

struct SweepResult {
  std::vector<std::string> parameters;  // the keys
  std::vector<std::string> labels;      // their short names, e.g. "friction_angle"
  Combination combination = Combination::kGrid;
  std::vector<std::string> measures;  // measure names = sweep.csv columns
  std::vector<RunRecord> runs;
  std::filesystem::path folder, table, summary, plot;  // DIR, sweep.csv, sweep.json, sweep.png
  bool plotted = false;                                // false when gnuplot is missing or failed
  // DIR/convergence.csv (convergence.hpp) when the sweep varies `mesh.cell_size` over at least
  // three sizes that finished; empty otherwise.
  std::filesystem::path convergence;
  // The index in `parameters` of the repeat key (repeats.hpp), -1 without repeats; and
  // DIR/repeats.csv, the spread of each measure over the repeats (empty without).
  int repeat_parameter = -1;
  std::filesystem::path repeats;
  bool all_ok() const;
};

// Runs the sweep (with dry_run: only its checks; the runs then have wall_time 0 and the
// status of their scene copy). InputError (naming the scene, the sweep file or the option) for a
// wrong key, value or measure, or an output folder that holds files without `overwrite` or
// `resume`; such errors are raised before anything is written. Errors of single runs are
// recorded in the result.
SweepResult run_sweep(const SweepDefinition& definition, const SweepOptions& options);

// "run_03_18" (number 3 of up to 99 runs, value 18): the number padded to the digits of
// `count` (at least 2), the value with characters other than letters, digits and ._+-
// replaced by '_' and cut to 40 characters. Several values are joined by '_'.
std::string run_folder_name(int number, int count, const std::string& value);

// DIR/sweep.csv: one row per run of `result` (those done so far while a sweep goes on): run,
// every key, the measures, wall_time_s, status, message (file-formats manual).
void write_run_table(const std::filesystem::path& file, const SweepResult& result);

// The table printed at the end: one row per run, then the messages of the failed runs.
std::string format_table(const SweepResult& result);

}  // namespace lituya::sweep
