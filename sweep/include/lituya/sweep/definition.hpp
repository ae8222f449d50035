#pragma once
// What a sweep runs: a scene, one key of it, the values to give that key, and the measures to
// plot. It comes from the command line (`lituya sweep SCENE.toml --parameter KEY --values
// V1,V2,...`) or from a sweep file (`lituya sweep SWEEP.toml`, format "lituya-sweep"); every
// sweep writes its definition as a sweep file (sweep.toml in its folder), so that it can be
// run again as it was.
#include <filesystem>
#include <string>
#include <vector>

namespace lituya::sweep {

struct SweepDefinition {
  std::filesystem::path scene;        // the scene file
  std::string parameter;              // the key, e.g. "material.beads.friction_angle"
  std::vector<std::string> values;    // as written: numbers, strings, true/false
  std::vector<std::string> measures;  // measure names (see measures.hpp); empty: the default
  std::filesystem::path output;       // the sweep folder; empty: default_output()
  std::filesystem::path source;       // the sweep file, empty when given on the command line
};

// The values of --values: a comma separated list whose items are single values or ranges
// START:STOP:STEP (numbers; STOP is included when the steps land on it, to 1e-9 of STEP).
// "10,14:22:4" gives 10, 14, 18, 22. InputError naming --values on an empty item, a zero or
// backward STEP, or more than 1000 values.
std::vector<std::string> parse_value_list(const std::string& text);

// Splits "a,b,c" (--measure may list several), dropping empty items.
std::vector<std::string> split_list(const std::string& text);

// True when `file` is a TOML file with format = "lituya-sweep".
bool is_sweep_file(const std::filesystem::path& file);

// Reads a sweep file:
//   format = "lituya-sweep"
//   version = 1
//   scene = "scene.toml"                        # relative to the sweep file
//   parameter = "material.beads.friction_angle"
//   values = [10, 14, 18, 22]                   # numbers, strings or booleans
//   measures = ["gauge_first_crest"]            # optional
//   output = "sweep_phi"                        # optional, relative to the sweep file
// InputError naming the file and line for a missing or wrong key.
SweepDefinition read_sweep_file(const std::filesystem::path& file);

// The folder a sweep writes into when none is given: for a sweep file, a folder named after
// it next to it (case_b_phi.toml -> case_b_phi/); otherwise sweep_<parameter>/ next to the
// scene.
std::filesystem::path default_output(const SweepDefinition& definition);

// The text of the sweep file that records a sweep: the absolute scene path, the parameter,
// `literals` (the TOML text of each value) and the measure names.
std::string sweep_file_text(const SweepDefinition& definition,
                            const std::vector<std::string>& literals,
                            const std::vector<std::string>& measure_names);

}  // namespace lituya::sweep
