#pragma once
// Repeats: each run of a sweep made several times with the Courant number of the scene's last
// stage changed in its fourth significant digit, and each measure reported as the mean and
// spread of those runs (`lituya sweep ... --repeats N`, or `repeats = N` in a sweep file).
//
// Why: some readings are not well-conditioned functions of the inputs. Case B's first crest at
// X1 on a crossed mesh read 47.4-56.7 mm in six runs whose release Courant numbers differed by
// at most 1e-3 (a change far below any truncation error), against 47.8-48.3 mm on the plain
// mesh (verification/speed_accuracy_case_b/README.md, "Crossed meshes: X1's first crest is
// chaotic"). One run per setting then says nothing about the setting: three single runs once
// agreed to 0.7 % by chance and were read as convergence. A setting's effect, or a refinement
// step, is resolved only where it exceeds that scatter.
//
// How (`--repeat-by courant`, the default): repeat k (k = 0 ... N-1) sets the last stage's
// Courant number to C (1 - 2e-4 k), C the
// scene's value (or the solver's default 0.5): the time step changes by a few parts in ten
// thousand, the physics and its discretisation do not. The perturbed key is appended to the
// sweep's keys (it varies fastest) and marked as the repeat key; the earlier stages are the
// same in every repeat, so they are run once and reused (sweep.hpp). The summary groups runs
// by the values of the other keys; the mesh convergence (convergence.hpp) takes each cell
// size's mean and says when the last refinement's change is within twice its standard error.
//
// A mesh is one sample too (`--repeat-by mesh`). Repeat k sets [mesh] seed = s + k, s the
// scene's seed (1 when it gives none, gmsh's default): gmsh makes another triangulation of the
// same geometry at the same cell size, often with most interior nodes elsewhere (not always:
// gmsh meshes some simple shapes the same for several seeds), and every stage
// runs again. Why: on examples/case_b_2d at 0.015 m the Courant repeats scatter X1's first
// crest by 0.4-0.8 %, five meshes of 0.98-1.02 times that size by 6 %
// (verification/speed_accuracy_case_b/README.md, "A mesh ensemble"): a change of mesh
// topology moves a reading far more than a change of the time step, and a refinement step
// judged against the Courant scatter alone can look resolved when it is not.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace lituya::sweep {

struct SweepResult;

inline constexpr int kMaxRepeats = 20;
// Empty when 1 <= repeats <= kMaxRepeats; else "must be 1 (no repeats) to 20 (got N)", for the
// command line's, the sweep file's and run_sweep's messages alike.
std::string repeats_range_error(int repeats);
// The relative change of the Courant number from one repeat to the next.
inline constexpr double kRepeatCourantStep = 2e-4;

// "stage.<name>.courant" of the scene's last [[stage]] (by its name, else its index).
// InputError naming the scene when it has no [[stage]].
std::string repeat_key(const toml::table& scene, const std::filesystem::path& scene_file);

// The key of the mesh repeats.
inline constexpr const char* kMeshSeedKey = "mesh.seed";

// The values of the mesh repeats: first_seed + k, k = 0 ... repeats - 1, as TOML integers.
std::vector<std::string> mesh_seed_values(long long first_seed, int repeats);

// The values of the repeat key: courant (1 - kRepeatCourantStep k), k = 0 ... repeats - 1,
// written with ten significant digits as TOML floats ("1.0", not "1").
std::vector<std::string> repeat_values(double courant, int repeats);

// Mean, standard deviation (n - 1 in the denominator; NaN for one value), smallest and largest
// of the finite values; count = how many there were.
struct Spread {
  int count = 0;
  double mean = 0, sd = 0, min = 0, max = 0;
};
Spread spread_of(const std::vector<double>& values);

// "label=value ..." of a run's keys other than the repeat key and key `skip` (npos: none), in
// the order of the keys: the runs with the same text differ only in those keys.
struct RunRecord;
std::string group_of(const SweepResult& result, const RunRecord& run,
                     std::size_t skip = static_cast<std::size_t>(-1));

// One measure over the repeats of one combination of the other keys.
struct RepeatSummaryRow {
  std::string group;    // "key=value ..." of the other keys, empty when there are none
  std::string measure;  // as in sweep.csv
  Spread spread;
};

// The sweep's repeat key, empty without repeats.
std::string repeat_key_of(const SweepResult& result);

// One row per combination of the other keys and measure, in run order; empty when the sweep
// has no repeats.
std::vector<RepeatSummaryRow> repeat_summary(const SweepResult& result);

// DIR/repeats.csv (file-formats manual).
void write_repeat_table(const std::filesystem::path& file,
                        const std::vector<RepeatSummaryRow>& rows);

// The table printed at the end of the sweep's report; `repeat_key` (the sweep's, as in
// SweepResult::parameters) says what the repeats changed.
std::string format_repeats(const std::vector<RepeatSummaryRow>& rows,
                           const std::string& repeat_key);

// For mesh repeats, one line for each combination of the other keys whose runs had fewer
// different meshes than runs that made one (case/geometry.vtu, compared whatever the
// numbering: mesh_fingerprint.hpp), e.g. "the repeats with cell_size=0.02: 3 runs on 2
// different meshes (...)": gmsh meshes some geometries the same for several seeds, and the
// spread of such a group understates the scatter over meshes. Empty for Courant repeats and
// when every run had its own mesh. Reads the meshes, so it is called for the report's text
// only (the tables need no mesh).
std::string format_shared_meshes(const SweepResult& result);

}  // namespace lituya::sweep
