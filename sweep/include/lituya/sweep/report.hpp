#pragma once
// A finished sweep reported again, without running anything: `lituya sweep DIR [--merge DIR2
// ...] [--sizes H1,H2,H3]` reads DIR/sweep.json (and that of each DIR2), and prints the runs,
// the repeats' spread (repeats.hpp) and the mesh convergence (convergence.hpp) of them all.
//
// Why: a refinement study is rarely one sweep. Its finest size takes an hour a run and is run
// on its own, often from a copy of the scene that writes fewer fields; and the Richardson
// estimate is wanted from sizes other than the three finest (to see whether one size is off
// the trend, as Case B's 0.01 m was: verification/speed_accuracy_case_b/README.md). Before
// this, such estimates were made by a script that repeated convergence.cpp's procedure.
//
// How: the sweeps must vary the same keys (in the same order, the repeat key too, so that
// their runs group alike); the measures reported are those all of them have. The runs are
// numbered on from one sweep to the next (the first sweep's keep their numbers), and the
// report says which numbers came from which folder.
#include <filesystem>
#include <string>
#include <vector>

#include "lituya/sweep/convergence.hpp"
#include "lituya/sweep/sweep.hpp"

namespace lituya::sweep {

// The sweep recorded in `folder`/sweep.json: its keys, measures and runs (values as text,
// measures NaN where the run gave none). InputError naming the file when it is missing, is
// not a sweep summary, or lacks a field.
SweepResult read_sweep_summary(const std::filesystem::path& folder);

// Where the runs of a merged sweep came from: runs first ... last of `folder`.
struct RunSource {
  std::filesystem::path folder;
  int first = 0, last = 0;
};

struct MergedSweep {
  SweepResult result;
  std::vector<RunSource> sources;
};

// The runs of several sweeps as one (at least one). InputError naming the sweep.json of the
// first sweep whose keys differ from the first's, or when no measure is common to all.
MergedSweep merge_sweeps(const std::vector<std::filesystem::path>& folders);

// The report: where the runs came from, the run table, the repeats' spread and the mesh
// convergence (`cell_sizes`: three sizes, or empty for the three finest). InputError (naming
// the first folder) when `cell_sizes` are given and no measure has finished runs at all three.
std::string format_report(const MergedSweep& merged, const std::vector<double>& cell_sizes,
                          std::vector<MeshConvergenceRow>* convergence = nullptr);

// What write_report() wrote; a path is empty when the file was not written.
struct ReportFiles {
  std::filesystem::path runs;         // sweep.csv: the merged runs
  std::filesystem::path repeats;      // repeats.csv (sweeps with repeats)
  std::filesystem::path convergence;  // convergence.csv (at least three cell sizes)
  std::filesystem::path means;        // convergence_means.csv (a sweep of the cell size alone)
  std::vector<std::filesystem::path> plots;  // convergence_<measure>.png (when gnuplot runs)
};

// The report's tables in `folder` (created; InputError when it holds files, unless
// `overwrite`): sweep.csv, repeats.csv and convergence.csv in a sweep's own columns, and, for
// a sweep of the cell size alone, each measure against the cell size: every run, the mean of
// each size and the Richardson extrapolation at h = 0 (convergence_means.csv and one PNG a
// measure, convergence_<measure>.png with ':' made '_').
ReportFiles write_report(const std::filesystem::path& folder, const MergedSweep& merged,
                         const std::vector<MeshConvergenceRow>& convergence, bool overwrite);

}  // namespace lituya::sweep
