// A finished sweep reported again (report.hpp says why and how).
#include "lituya/sweep/report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "lituya/common/csv_writer.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/common/json_file.hpp"
#include "lituya/common/output_folder.hpp"
#include "lituya/post/plot.hpp"
#include "lituya/sweep/measures.hpp"
#include "lituya/sweep/progress.hpp"
#include "lituya/sweep/repeats.hpp"
#include "lituya/sweep/scene_edit.hpp"

namespace lituya::sweep {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSummaryFile = "sweep.json";
constexpr const char* kSummaryFormat = "lituya-sweep-summary";

// A key's value as the run table shows it: numbers in their shortest exact form (as the run's
// folder name and sweep.csv have them), strings as they are.
std::string value_text(const Json& value) {
  if (value.is_number()) return csv_number(value.get<double>());
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  return value.dump();
}

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

}  // namespace

SweepResult read_sweep_summary(const fs::path& folder) {
  const fs::path file = folder / kSummaryFile;
  std::ifstream in(file);
  if (!in)
    throw InputError(folder.string(), 0,
                     "not a sweep folder: it has no " + std::string(kSummaryFile) +
                         " (a sweep writes one when it ends)");
  SweepResult result;
  result.folder = folder;
  result.summary = file;
  try {
    const Json j = Json::parse(in);
    if (j.value("format", std::string()) != kSummaryFormat)
      throw InputError(file.string(), 0,
                       "expected a sweep summary (format = \"" + std::string(kSummaryFormat) +
                           "\"), found another JSON file");
    result.parameters = j.at("parameters").get<std::vector<std::string>>();
    for (const std::string& key : result.parameters) result.labels.push_back(key_label(key));
    result.measures = j.at("measures").get<std::vector<std::string>>();
    if (j.contains("repeat_key")) {
      const auto key = std::find(result.parameters.begin(), result.parameters.end(),
                                 j.at("repeat_key").get<std::string>());
      if (key != result.parameters.end())
        result.repeat_parameter = static_cast<int>(key - result.parameters.begin());
    }
    for (const Json& r : j.at("runs")) {
      RunRecord run;
      run.number = r.at("number").get<int>();
      run.folder = folder / r.at("folder").get<std::string>();
      const Json& values = r.at("values");
      for (const std::string& key : result.parameters) {
        const Json& value = values.at(key);
        run.values.push_back(value_text(value));
        // As the scene copy had it (sweep.csv shows strings without these quotes).
        run.literals.push_back(value.is_string() ? "\"" + run.values.back() + "\""
                                                 : run.values.back());
      }
      run.status = status_from_text(r.at("status").get<std::string>());
      run.kept = r.value("kept", false);
      const Json& wall = r.at("wall_time");
      run.wall_time = wall.is_number() ? wall.get<double>() : NAN;
      const Json& measures = r.at("measures");
      for (const std::string& m : result.measures) {
        const auto v = measures.find(m);
        run.measures.push_back(v != measures.end() && v->is_number() ? v->get<double>() : NAN);
      }
      run.message = r.value("message", std::string());
      result.runs.push_back(std::move(run));
    }
  } catch (const Json::exception& e) {
    throw InputError(
        file.string(), 0,
        std::string("expected a sweep summary as `lituya sweep` writes it: ") + e.what());
  }
  return result;
}

MergedSweep merge_sweeps(const std::vector<fs::path>& folders) {
  if (folders.empty()) throw std::invalid_argument("merge_sweeps needs at least one folder");
  MergedSweep merged;
  merged.result = read_sweep_summary(folders.front());
  SweepResult& all = merged.result;
  merged.sources.push_back({folders.front(), 0, 0});
  int last = 0;
  for (const RunRecord& run : all.runs) last = std::max(last, run.number);
  merged.sources.back().first = all.runs.empty() ? 0 : all.runs.front().number;
  merged.sources.back().last = last;
  for (size_t f = 1; f < folders.size(); ++f) {
    SweepResult more = read_sweep_summary(folders[f]);
    if (more.parameters != all.parameters || more.repeat_parameter != all.repeat_parameter) {
      throw InputError(more.summary.string(), 0,
                       "its keys (" + join(more.parameters) + ") differ from those of " +
                           all.summary.string() + " (" + join(all.parameters) +
                           "): only sweeps of the same keys, the repeat key too, can be merged");
    }
    // Keep the measures both have, in the first sweep's order.
    std::vector<size_t> keep_all, keep_more;
    for (size_t m = 0; m < all.measures.size(); ++m) {
      const auto it = std::find(more.measures.begin(), more.measures.end(), all.measures[m]);
      if (it == more.measures.end()) continue;
      keep_all.push_back(m);
      keep_more.push_back(static_cast<size_t>(it - more.measures.begin()));
    }
    if (keep_all.empty())
      throw InputError(more.summary.string(), 0,
                       "it has no measure in common with " + all.summary.string());
    const auto keep = [](std::vector<double>& values, const std::vector<size_t>& columns) {
      std::vector<double> kept;
      for (size_t m : columns) kept.push_back(values[m]);
      values = std::move(kept);
    };
    std::vector<std::string> measures;
    for (size_t m : keep_all) measures.push_back(all.measures[m]);
    all.measures = measures;
    for (RunRecord& run : all.runs) keep(run.measures, keep_all);
    RunSource source{folders[f], last + 1, last};
    for (RunRecord& run : more.runs) {
      keep(run.measures, keep_more);
      run.number = ++last;
      all.runs.push_back(std::move(run));
    }
    source.last = last;
    merged.sources.push_back(source);
  }
  return merged;
}

std::string format_report(const MergedSweep& merged, const std::vector<double>& cell_sizes,
                          std::vector<MeshConvergenceRow>* convergence) {
  const SweepResult& result = merged.result;
  std::vector<MeshConvergenceRow> rows = mesh_convergence(result, cell_sizes);
  if (!cell_sizes.empty() && rows.empty()) {
    const auto key = std::find(result.parameters.begin(), result.parameters.end(), kCellSizeKey);
    if (key == result.parameters.end())
      throw InputError(merged.sources.front().folder.string(), 0,
                       "--sizes needs a sweep over mesh.cell_size; this one varies other keys");
    std::vector<std::string> present;
    const size_t cell_key = static_cast<size_t>(key - result.parameters.begin());
    for (const RunRecord& run : result.runs)
      if (run.status == RunStatus::kOk &&
          std::find(present.begin(), present.end(), run.values[cell_key]) == present.end())
        present.push_back(run.values[cell_key]);
    std::vector<std::string> asked;
    for (double h : cell_sizes) asked.push_back(short_number(h));
    throw InputError(merged.sources.front().folder.string(), 0,
                     "no measure has finished runs at all of the cell sizes " + join(asked) +
                         " (the runs that finished have " + join(present) + ")");
  }
  std::ostringstream out;
  if (merged.sources.size() > 1)
    for (const RunSource& s : merged.sources)
      out << "runs " << s.first << "-" << s.last << ": " << s.folder.string() << "\n";
  out << format_table(result) << format_repeats(repeat_summary(result), repeat_key_of(result))
      << format_shared_meshes(result)
      << format_convergence(rows, /*chosen_sizes=*/!cell_sizes.empty());
  if (convergence) *convergence = std::move(rows);
  return out.str();
}

namespace {

// "gauge_first_crest:X1" -> "gauge_first_crest_X1": a measure's name in a file name.
std::string file_stem(const std::string& measure) {
  std::string stem = measure;
  for (char& c : stem)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) c = '_';
  return stem;
}

}  // namespace

ReportFiles write_report(const fs::path& folder, const MergedSweep& merged,
                         const std::vector<MeshConvergenceRow>& convergence, bool overwrite) {
  const SweepResult& result = merged.result;
  prepare_output_folder(folder, overwrite);
  ReportFiles files;
  files.runs = folder / "sweep.csv";
  write_run_table(files.runs, result);
  if (result.repeat_parameter >= 0) {
    files.repeats = folder / "repeats.csv";
    write_repeat_table(files.repeats, repeat_summary(result));
  }
  if (convergence.empty()) return files;
  files.convergence = folder / "convergence.csv";
  write_convergence_table(files.convergence, convergence);

  // The plots: each measure against the cell size, for a study of the cell size alone (with
  // or without repeats); with other keys the runs of several groups would share one curve.
  const auto cell_key = std::find(result.parameters.begin(), result.parameters.end(), kCellSizeKey);
  const size_t keys = result.parameters.size() - (result.repeat_parameter >= 0 ? 1 : 0);
  if (keys != 1 || cell_key == result.parameters.end()) return files;
  const size_t cell = static_cast<size_t>(cell_key - result.parameters.begin());
  // convergence_means.csv: per cell size, each measure's mean over its finished runs, and a
  // row at h = 0 with the Richardson extrapolation where the estimate has one of a plausible
  // order (an "order" of 7 is a levelling off, and a point at h = 0 would read as a limit).
  std::map<double, std::vector<std::vector<double>>> by_size;  // h -> measure -> values
  for (const RunRecord& run : result.runs) {
    const double h = run_cell_size(run, cell);
    if (run.status != RunStatus::kOk || !std::isfinite(h)) continue;
    auto& values = by_size[h];
    values.resize(result.measures.size());
    for (size_t m = 0; m < result.measures.size(); ++m)
      if (std::isfinite(run.measures[m])) values[m].push_back(run.measures[m]);
  }
  std::vector<std::string> header{"cell_size_m"};
  for (const std::string& m : result.measures) header.push_back(m);
  for (const std::string& m : result.measures) header.push_back("extrapolated:" + m);
  CsvWriter means(header);
  means.number(0.0);
  for (size_t m = 0; m < result.measures.size(); ++m) means.number(NAN);
  for (const std::string& m : result.measures) {
    double limit = NAN;
    for (const MeshConvergenceRow& row : convergence)
      if (row.measure == m && !(row.estimate.order > kHighestPlausibleOrder))
        limit = row.estimate.extrapolated;
    means.number(limit);
  }
  means.end_row();
  for (const auto& [h, values] : by_size) {
    means.number(h);
    for (const std::vector<double>& v : values) means.number(spread_of(v).mean);
    for (size_t m = 0; m < result.measures.size(); ++m) means.number(NAN);
    means.end_row();
  }
  files.means = folder / "convergence_means.csv";
  means.write(files.means);
  const int runs_x = 2 + static_cast<int>(cell);
  const int first_measure = 2 + static_cast<int>(result.parameters.size());
  for (size_t m = 0; m < result.measures.size(); ++m) {
    const std::string& name = result.measures[m];
    const int measure_column = 2 + static_cast<int>(m);
    const std::vector<post::PlotSeries> series{
        {files.runs, runs_x, first_measure + static_cast<int>(m), "each run", true, 0, 0, 1},
        {files.means, 1, measure_column, "mean of the runs of a size", false, 0, 0, 2},
        {files.means, 1, measure_column + static_cast<int>(result.measures.size()),
         "Richardson extrapolation (monotone, order at most 3)", true, 0, 0, 3}};
    const fs::path png = folder / ("convergence_" + file_stem(name) + ".png");
    if (post::plot_xy(png, name + " against the cell size", "cell size (m)",
                      name + " (" + measure_unit(name) + ")", series))
      files.plots.push_back(png);
  }
  return files;
}

}  // namespace lituya::sweep
