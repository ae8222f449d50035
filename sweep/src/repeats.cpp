// Repeats of a sweep's runs and the spread of their measures (repeats.hpp says why and how).
#include "lituya/sweep/repeats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include "lituya/common/csv_writer.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/sweep/measures.hpp"
#include "lituya/sweep/mesh_fingerprint.hpp"
#include "lituya/sweep/progress.hpp"
#include "lituya/sweep/sweep.hpp"

namespace lituya::sweep {

std::string repeats_range_error(int repeats) {
  if (repeats >= 1 && repeats <= kMaxRepeats) return "";
  return "must be 1 (no repeats) to " + std::to_string(kMaxRepeats) + " (got " +
         std::to_string(repeats) + ")";
}

std::string repeat_key(const toml::table& scene, const std::filesystem::path& scene_file) {
  const toml::array* stages = scene["stage"].as_array();
  if (!stages || stages->empty() || !stages->back().is_table())
    throw InputError(scene_file.string(), 0,
                     "--repeats changes the Courant number of the scene's last [[stage]], but "
                     "the scene has no [[stage]]");
  const toml::table& last = *stages->back().as_table();
  if (auto name = last["name"].value<std::string>()) return "stage." + *name + ".courant";
  return "stage." + std::to_string(stages->size() - 1) + ".courant";
}

std::vector<std::string> repeat_values(double courant, int repeats) {
  std::vector<std::string> values;
  for (int k = 0; k < repeats; ++k) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", courant * (1.0 - kRepeatCourantStep * k));
    std::string value = text;
    // A TOML float, also where the value is whole ("1" -> "1.0").
    if (value.find_first_of(".en") == std::string::npos) value += ".0";
    values.push_back(value);
  }
  return values;
}

std::vector<std::string> mesh_seed_values(long long first_seed, int repeats) {
  std::vector<std::string> values;
  for (int k = 0; k < repeats; ++k) values.push_back(std::to_string(first_seed + k));
  return values;
}

Spread spread_of(const std::vector<double>& values) {
  Spread s;
  double sum = 0;
  s.min = std::numeric_limits<double>::infinity();
  s.max = -s.min;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    ++s.count;
    sum += v;
    s.min = std::min(s.min, v);
    s.max = std::max(s.max, v);
  }
  if (s.count == 0) return {0, NAN, NAN, NAN, NAN};
  s.mean = sum / s.count;
  double squares = 0;
  for (double v : values)
    if (std::isfinite(v)) squares += (v - s.mean) * (v - s.mean);
  s.sd = s.count > 1 ? std::sqrt(squares / (s.count - 1)) : NAN;
  return s;
}

std::string group_of(const SweepResult& result, const RunRecord& run, std::size_t skip) {
  std::string group;
  for (std::size_t p = 0; p < run.values.size(); ++p)
    if (p != skip && static_cast<int>(p) != result.repeat_parameter)
      group += (group.empty() ? "" : " ") + result.labels[p] + "=" + run.values[p];
  return group;
}

std::string repeat_key_of(const SweepResult& result) {
  if (result.repeat_parameter < 0) return "";
  return result.parameters.at(static_cast<std::size_t>(result.repeat_parameter));
}

namespace {
// The runs of each combination of the other keys ("key=value ..."), the groups in run order.
std::vector<std::pair<std::string, std::vector<const RunRecord*>>> runs_by_group(
    const SweepResult& result) {
  std::vector<std::pair<std::string, std::vector<const RunRecord*>>> groups;
  std::map<std::string, std::size_t> index;
  for (const RunRecord& run : result.runs) {
    const std::string group = group_of(result, run);
    const auto [at, added] = index.try_emplace(group, groups.size());
    if (added) groups.push_back({group, {}});
    groups[at->second].second.push_back(&run);
  }
  return groups;
}
}  // namespace

std::vector<RepeatSummaryRow> repeat_summary(const SweepResult& result) {
  if (result.repeat_parameter < 0) return {};
  std::vector<RepeatSummaryRow> rows;
  for (const auto& [group, runs] : runs_by_group(result))
    for (std::size_t m = 0; m < result.measures.size(); ++m) {
      std::vector<double> values;
      for (const RunRecord* run : runs)
        values.push_back(run->status == RunStatus::kOk ? run->measures[m] : NAN);
      rows.push_back({group, result.measures[m], spread_of(values)});
    }
  return rows;
}

std::string format_shared_meshes(const SweepResult& result) {
  if (repeat_key_of(result) != kMeshSeedKey) return "";
  std::string text;
  for (const auto& [group, runs] : runs_by_group(result)) {
    std::set<std::uint64_t> meshes;
    int meshed = 0;  // runs that made a mesh
    for (const RunRecord* run : runs)
      if (const auto fingerprint = mesh_fingerprint(run->folder / "case" / "geometry.vtu")) {
        ++meshed;
        meshes.insert(*fingerprint);
      }
    const int different = static_cast<int>(meshes.size());
    if (different >= meshed) continue;
    text += (group.empty() ? std::string("the repeats") : "the repeats with " + group) + ": " +
            std::to_string(meshed) + " runs on " + std::to_string(different) +
            (different == 1 ? " mesh" : " different meshes") +
            " (gmsh's seeds did not change this geometry's triangulation); the spread "
            "understates the scatter over meshes: vary mesh.cell_size slightly instead\n";
  }
  return text;
}

void write_repeat_table(const std::filesystem::path& file,
                        const std::vector<RepeatSummaryRow>& rows) {
  CsvWriter table({"group", "measure", "runs", "mean", "sd", "relative_sd", "min", "max"});
  for (const RepeatSummaryRow& row : rows) {
    const Spread& s = row.spread;
    table.text(row.group).text(row.measure).number(s.count).number(s.mean).number(s.sd);
    table.number(s.mean != 0 ? s.sd / std::abs(s.mean) : NAN).number(s.min).number(s.max);
    table.end_row();
  }
  table.write(file);
}

std::string format_repeats(const std::vector<RepeatSummaryRow>& rows,
                           const std::string& repeat_key) {
  if (rows.empty()) return "";
  std::vector<std::vector<std::string>> lines{
      {"measure", "runs", "mean", "sd", "sd / mean", "smallest", "largest"}};
  const bool grouped = std::any_of(rows.begin(), rows.end(),
                                   [](const RepeatSummaryRow& r) { return !r.group.empty(); });
  if (grouped) lines[0].insert(lines[0].begin(), "with");
  for (const RepeatSummaryRow& row : rows) {
    const Spread& s = row.spread;
    char relative[32] = "-";
    if (std::isfinite(s.sd) && s.mean != 0)
      std::snprintf(relative, sizeof relative, "%.2g %%", 100.0 * s.sd / std::abs(s.mean));
    std::vector<std::string> line{row.measure + " (" + measure_unit(row.measure) + ")",
                                  std::to_string(s.count),
                                  short_number(s.mean),
                                  short_number(s.sd),
                                  relative,
                                  short_number(s.min),
                                  short_number(s.max)};
    if (grouped) line.insert(line.begin(), row.group.empty() ? "-" : row.group);
    lines.push_back(line);
  }
  const std::string changed =
      repeat_key == kMeshSeedKey
          ? "another mesh per repeat, made with another seed of gmsh's random numbers at the same "
            "cell size; the spread is the reading's scatter over meshes"
          : "the last stage's Courant number changed by 2e-4 of itself per repeat; the spread is "
            "the reading's own scatter";
  return "repeats (" + changed + "):\n" + align_columns(lines);
}

}  // namespace lituya::sweep
