#pragma once
// What every verification case shares: running a scene through pre + solve (+ post), reading
// the output series, and recording a check (measured vs reference vs tolerance).
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lituya/post/postprocess.hpp"
#include "lituya/solver/solve.hpp"

namespace lituya::verify {

struct Check {
  std::string quantity;
  std::string unit;
  double measured = 0;
  double reference = 0;
  double tolerance = 0;  // absolute, in `unit`
  bool passed = false;
};

struct CaseResult {
  std::string name;  // folder name
  std::string title;
  std::string variant;  // quick | full
  std::vector<Check> checks;
  std::vector<std::filesystem::path> plots;  // relative to the report folder
  std::string error;                         // non-empty if the case could not run
  double wall_time = 0;                      // s
  // A documented failure (verification/<case>/known-failure.md): reported as FAIL with the
  // explanation, but it does not fail the run, so CI stays meaningful for the other cases.
  // The file that explains it (known-failure.md, or known-failure-full.md for a failure of the
  // full variant only); empty: not a known failure.
  std::string known_failure_note;
  bool known_failure() const { return !known_failure_note.empty(); }
  // The case folders the case wrote (relative to its work folder) and the hash of each one's
  // case files (solver::case_files_hash), so a report can be matched to its inputs.
  std::vector<std::pair<std::string, std::string>> case_hashes;
  bool passed() const;
};

struct CaseContext {
  std::filesystem::path source;  // verification/<case>/
  std::filesystem::path work;    // report/<case>/ (case folder, plots, CSV)
  std::filesystem::path report;  // the report folder
  bool full = false;
  int threads = 1;
};

// Adds a check; tolerance is absolute.
void add_check(CaseResult& result, const std::string& quantity, const std::string& unit,
               double measured, double reference, double tolerance);

// How the cases solve: overwriting, without setting old output aside (the report is rebuilt
// each time), on `threads` threads.
solver::SolveOptions report_solve_options(int threads);

// pre + solve of `scene` into `case_folder`; returns the case folder.
std::filesystem::path run_scene(const CaseContext& context, const std::filesystem::path& scene,
                                const std::filesystem::path& case_folder);

// pre + solve of scene_<variant>.toml into <work>/case; returns the case folder.
std::filesystem::path run_scene(const CaseContext& context);

// One frame of a point output series.
struct Frame {
  double time = 0;
  std::filesystem::path file;
};
// `kind` is "points" (solid points), "liquid" (water points) or "grid".
std::vector<Frame> read_series(const std::filesystem::path& case_folder, const std::string& stage,
                               const std::string& kind = "points");
// The largest value of `column` in the solver's history of `stage`
// (<case>/output/<stage>_history.csv, about a thousand rows a stage): for example the fastest
// solid point, "max_speed_solid", which the outputs tens of milliseconds apart can miss.
double largest_in_history(const std::filesystem::path& case_folder, const std::string& stage,
                          const std::string& column);
// A point data array of a .vtu (tuples flattened) and its number of components.
std::vector<double> read_point_array(const std::filesystem::path& vtu, const std::string& name,
                                     int& components);
std::vector<double> read_positions(const std::filesystem::path& vtu);  // 3 per point
// The whole .vtu (VTK's reader); throws naming the file when it holds no points.
vtkSmartPointer<vtkUnstructuredGrid> read_unstructured_grid(const std::filesystem::path& vtu);

// The first wave of a gauge record as verification/case_b reads it: from its first sample 5 mm
// above still water to the record's next fall below it (post::first_wave_crest); time, height
// and area NaN when the wave is still standing at the end of the record.
post::WaveCrest complete_first_wave(const std::vector<double>& time,
                                    const std::vector<double>& eta);

// Writes a CSV with a header and rows.
void write_csv(const std::filesystem::path& file, const std::string& header,
               const std::vector<std::vector<double>>& rows);

// A case measured at one cell size in its quick variant (scene_quick.toml) and at two in its
// full variant (scene_full_coarse.toml, scene_full_fine.toml). `run_one(context, scene, label,
// h, result)` runs one scene into <work>/<label>, adds its own checks and returns the measure
// whose relative change from the coarser to the finer full mesh the full variant checks
// against `tolerance` (issue 8: a result that moves with the cell size is not a result). The
// check reads "relative change of <measure> from <coarse> to <fine> m".
struct CellSizes {
  double quick = 0, coarse = 0, fine = 0;  // m
};
using SceneRun = double (*)(const CaseContext& context, const std::string& scene,
                            const std::string& label, double cell_size, CaseResult& result);
void run_at_cell_sizes(const CaseContext& context, CaseResult& result, const CellSizes& h,
                       const std::string& measure, double tolerance, SceneRun run_one);
// " (h = 0.0100 m)": the cell size that labels a check of such a case.
std::string cell_size_tag(double cell_size);

using CaseFunction = std::function<void(const CaseContext&, CaseResult&)>;

void run_bar_vibration(const CaseContext& context, CaseResult& result);
void run_sliding_block(const CaseContext& context, CaseResult& result);
void run_saturated_block(const CaseContext& context, CaseResult& result);
void run_saturated_block_fine(const CaseContext& context, CaseResult& result);
void run_gravity_column(const CaseContext& context, CaseResult& result);
void run_column_collapse(const CaseContext& context, CaseResult& result);
void run_case_a(const CaseContext& context, CaseResult& result);
void run_case_b(const CaseContext& context, CaseResult& result);
void run_case_c(const CaseContext& context, CaseResult& result);
void run_hydrostatic_tank(const CaseContext& context, CaseResult& result);
void run_dam_break(const CaseContext& context, CaseResult& result);
void run_dam_break_late(const CaseContext& context, CaseResult& result);
void run_terzaghi(const CaseContext& context, CaseResult& result);
void run_seepage(const CaseContext& context, CaseResult& result);
void run_infiltration(const CaseContext& context, CaseResult& result);
void run_lock_exchange(const CaseContext& context, CaseResult& result);
void run_sponge(const CaseContext& context, CaseResult& result);
void run_standing_wave(const CaseContext& context, CaseResult& result);

}  // namespace lituya::verify
