#pragma once
// What a sweep runs: a scene, the keys of it to vary with their values, how the values combine
// into runs, and the measures to plot. It comes from the command line (`lituya sweep
// SCENE.toml --parameter KEY --values V1,V2,...`, the pair repeated for several keys) or from a
// sweep file (`lituya sweep SWEEP.toml`, format "lituya-sweep"); every sweep writes its
// definition as a sweep file (sweep.toml in its folder), so that it can be run again as it was.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lituya::sweep {

// One key of the scene and the values it takes.
struct SweepParameter {
  std::string key;                  // e.g. "material.beads.friction_angle"
  std::vector<std::string> values;  // as written: numbers, strings, true/false
  int line = 0;                     // of its entry in the sweep file; 0 on the command line
};

// How the values of several keys make runs: every combination (the first key varies slowest),
// or the i-th value of every key together (all keys then have as many values).
enum class Combination { kGrid, kZip };
// "grid", "zip".
std::string combination_name(Combination combination);

// What a repeat changes (repeats.hpp): the last stage's Courant number by 2e-4 of itself, or
// the mesh, made again with another seed of gmsh's random numbers ([mesh] seed).
enum class RepeatBy { kCourant, kMesh };
// The key whose sweep is a mesh refinement study.
inline constexpr const char* kCellSizeKey = "mesh.cell_size";
// "courant", "mesh"; and back (nullopt for any other name), for the sweep file and the
// command line alike.
std::string repeat_by_name(RepeatBy by);
std::optional<RepeatBy> repeat_by_from_name(const std::string& name);

struct SweepDefinition {
  std::filesystem::path scene;             // the scene file
  std::vector<SweepParameter> parameters;  // at least one
  Combination combination = Combination::kGrid;
  std::vector<std::string> measures;  // measure names (see measures.hpp); empty: the default
  std::filesystem::path output;       // the sweep folder; empty: default_output()
  std::filesystem::path source;       // the sweep file, empty when given on the command line
  // Each run made this many times, the last stage's Courant number changed by 2e-4 of itself
  // per repeat (repeats.hpp); 1: no repeats. `repeats_line`: its line in the sweep file.
  int repeats = 1;
  int repeats_line = 0;
  // What each repeat changes; unset: as repeat_by_for says.
  std::optional<RepeatBy> repeat_by;
};

// What the repeats of `definition` change: its repeat_by when given; otherwise the mesh when
// the sweep refines it (a key mesh.cell_size among its parameters), the Courant number when it
// does not. Why the mesh there: a refinement step is judged against the repeats' spread, and
// on examples/case_b_2d another mesh of the same cell size moves the first crests 5 to 100
// times more than a change of the time step does (verification/speed_accuracy_case_b/
// README.md, "A mesh ensemble"), so a step judged against the Courant spread alone looks
// resolved when it is not.
RepeatBy repeat_by_for(const SweepDefinition& definition);

// The most runs a sweep may have (a grid grows fast).
inline constexpr std::size_t kMaxRuns = 1000;

// The runs of the sweep, each as the index of its value in every parameter, in run order.
// InputError (at the sweep file's line, or naming --values) when there is no parameter, a key
// is given twice, a zip has lists of different lengths, or there would be more than kMaxRuns
// runs.
std::vector<std::vector<std::size_t>> combinations(const SweepDefinition& definition);

// The values of --values: a comma separated list whose items are single values or ranges
// START:STOP:STEP (numbers; STOP is included when the steps land on it, to 1e-9 of STEP).
// "10,14:22:4" gives 10, 14, 18, 22. InputError naming --values on an empty item, a zero or
// backward STEP, or more than 1000 values.
std::vector<std::string> parse_value_list(const std::string& text);

// Splits "a,b,c" (--measure may list several), dropping empty items.
std::vector<std::string> split_list(const std::string& text);

// True when `file` is a TOML file with format = "lituya-sweep".
bool is_sweep_file(const std::filesystem::path& file);

// Reads a sweep file. One key, as written by sweeps of one key:
//   format = "lituya-sweep"
//   version = 1
//   scene = "scene.toml"                        # relative to the sweep file
//   parameter = "material.beads.friction_angle"
//   values = [10, 14, 18, 22]                   # numbers, strings or booleans
//   measures = ["gauge_first_crest"]            # optional
//   output = "sweep_phi"                        # optional, relative to the sweep file
//   repeats = 3                                 # optional: each run 3 times (repeats.hpp)
//   repeat_by = "mesh"                          # optional: what a repeat changes, "courant"
//                                               # or "mesh" (another gmsh seed); default:
//                                               # "mesh" when mesh.cell_size is swept,
//                                               # "courant" otherwise (repeat_by_for)
// Several keys: instead of parameter and values, one [[parameter]] entry per key, and how they
// combine (optional, default "grid"):
//   combine = "grid"                            # every combination; "zip": i-th values together
//   [[parameter]]
//   key = "material.beads.friction_angle"
//   values = [20, 30]
//   [[parameter]]
//   key = "mesh.cell_size"
//   values = [0.02, 0.01]
// InputError naming the file and line for a missing or wrong key, a key given twice, zip lists
// of different lengths, or too many runs.
SweepDefinition read_sweep_file(const std::filesystem::path& file);

// The folder a sweep writes into when none is given: for a sweep file, a folder named after
// it next to it (case_b_phi.toml -> case_b_phi/); otherwise sweep_<KEY>/ next to the scene
// (the keys joined by '+' for several).
std::filesystem::path default_output(const SweepDefinition& definition);

// The text of the sweep file that records a sweep: the absolute scene path, the keys,
// `literals` (per parameter, the TOML text of each value), how they combine and the measure
// names. A sweep of one key is written in the one-key form.
std::string sweep_file_text(const SweepDefinition& definition,
                            const std::vector<std::vector<std::string>>& literals,
                            const std::vector<std::string>& measure_names);

}  // namespace lituya::sweep
