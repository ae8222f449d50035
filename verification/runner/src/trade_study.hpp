#pragma once
// A speed/accuracy study (user manual section 3): one scene solved with one knob at a time
// changed from a base setting, each run's errors against the wall time of its solve on one
// thread, the cheapest runs within each error bound, and the plots of error against wall
// time. What is measured and against what is the problem's (`TradeStudy::measure`): the dam
// break against Ritter (speed_accuracy.cpp), Case B against a fine reference run
// (speed_accuracy_case_b.cpp).
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "case_support.hpp"

namespace lituya::verify {

// A knob: its scene key (as `lituya sweep` names it), its name in tables and file names, a
// label for the plot, its values.
struct StudyKnob {
  std::string key, name, label;
  std::vector<std::string> values;
};

// An error the study ranks its runs by (dimensionless: a fraction of the answer's size).
struct StudyError {
  std::string name;   // CSV column
  std::string label;  // tables and the plot's axis
  std::string plot;   // the plot's file name, without .png
  std::string title;  // the plot's title (first line)
};

// One solve of the study.
struct StudyRun {
  std::string knob;  // the knob changed from the base, or "combined"
  double value = 0;  // the knob's value; for "combined", the error bound it was chosen for
  std::vector<std::string> setting;  // the value of each knob of the study, in keys order
  std::size_t points = 0;            // liquid points
  long steps = 0;                    // all stages
  long release_steps = 0;            // the stage named "release"
  std::vector<double> wall_times;    // s, of each repeat of the solve
  double wall_time = 0;              // s, their median (NaN when the run failed)
  std::vector<double> measured;      // TradeStudy::measure_columns
  std::vector<double> errors;        // TradeStudy::errors
  double volume_change = 0;          // total water volume at the last frame over the first, minus 1
  std::string failure;               // why the run gave no measure (e.g. it went unstable)
};

struct TradeStudy {
  std::string name;     // file names (<name>.csv, .md) and the progress lines' prefix
  std::string problem;  // "Dam break: RMS depth error against Ritter (t = 0.4 s)", for titles
  std::filesystem::path scene;               // the base scene
  std::vector<std::string> keys, names;      // every knob's key and name, the order of a setting
  std::vector<std::string> base;             // the base setting
  std::vector<StudyKnob> knobs;              // the knobs changed, with their values
  std::vector<std::string> measure_columns;  // CSV names of StudyRun::measured
  std::vector<StudyError> errors;
  std::vector<double> bounds = {0.05, 0.10};  // "within 5 %" and "within 10 %"
  // A run counts only if its water kept its volume to this fraction (an error against a
  // depth or a wave height cannot see a compressible water).
  double max_volume_change = 0.01;
  int repeats = 1;           // a solve shorter than repeat_below s is repeated up to this
  double repeat_below = 10;  // many times and the median wall time taken
  bool combined = false;     // run every bound's combined setting too
  std::string notes;         // Markdown written into <name>.md before the tables
  // Fills run.measured and run.errors from the solved case folder; throws when it cannot.
  std::function<void(const std::filesystem::path& case_folder, StudyRun& run)> measure;
};

// The four knobs both studies turn, as `lituya sweep` names them (keys) and as tables and file
// names do (names), in the order of a setting: cell size, points per cell, the release's
// Courant number, the water's bulk modulus.
const std::vector<std::string>& trade_knob_keys();
const std::vector<std::string>& trade_knob_names();

// "cell_size=0.02_points_per_cell=4_..." for `setting`.
std::string setting_name(const TradeStudy& study, const std::vector<std::string>& setting);

// pre + solve of the study's scene with `setting` in `folder` on `threads` threads, repeated
// as TradeStudy::repeats says, then measured. A run that fails is returned with its failure.
StudyRun run_study_setting(const TradeStudy& study, const std::vector<std::string>& setting,
                           const std::filesystem::path& folder, int threads);

// Runs the study (every knob's values, then the combined settings), writes <name>.csv,
// <name>.md, knob_<knob>.csv and one plot per error into context.work, prints the cheapest
// settings, and returns the runs, one per knob and value (the base once per knob).
std::vector<StudyRun> run_trade_study(const TradeStudy& study, const CaseContext& context,
                                      CaseResult& result);

// The values of `knob` in [lo, hi] and, for each, the run's release steps (`steps`) or its
// wall time: the input of a cost exponent check.
std::pair<std::vector<double>, std::vector<double>> knob_cost(const std::vector<StudyRun>& runs,
                                                              const std::string& knob, double lo,
                                                              double hi, bool steps);

// max - min of error `e` over the runs of `knob`; NaN when one of them has no error.
double error_spread(const std::vector<StudyRun>& runs, const std::string& knob, std::size_t e);

}  // namespace lituya::verify
