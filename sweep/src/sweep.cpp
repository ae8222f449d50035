#include "lituya/sweep/sweep.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/common/output_folder.hpp"
#include "lituya/post/plot.hpp"
#include "lituya/post/postprocess.hpp"
#include "lituya/pre/preprocess.hpp"
#include "lituya/pre/scene.hpp"
#include "lituya/solver/solve.hpp"
#include "lituya/sweep/measures.hpp"
#include "lituya/sweep/progress.hpp"
#include "lituya/sweep/scene_edit.hpp"

namespace lituya::sweep {

namespace fs = std::filesystem;

namespace {

// The message of an InputError without its "file:line: " prefix.
std::string bare_message(const InputError& e) {
  const std::string prefix =
      e.file() + (e.line() > 0 ? ":" + std::to_string(e.line()) : std::string()) + ": ";
  const std::string what = e.what();
  return what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  if (from.empty()) return text;
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// A CSV field without the characters that would split it.
std::string csv_text(const std::string& text) {
  std::string out;
  for (char c : text) out += c == ',' ? ';' : c == '"' ? '\'' : (c == '\n' || c == '\r') ? ' ' : c;
  return out;
}

std::string csv_number(double v) {
  if (!std::isfinite(v)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

std::string short_number(double v) {
  if (!std::isfinite(v)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

bool numeric(const KeyTarget& target, const std::vector<std::string>& literals) {
  // A key the scene does not set takes its type from the values: numbers when all are.
  for (const std::string& l : literals)
    if (l.empty() || l[0] == '"' || l == "true" || l == "false") return false;
  return target.type == ValueType::kInteger || target.type == ValueType::kNumber || !target.present;
}

// What a copy of the scene says about itself, at its end.
std::vector<std::string> copy_note(const SweepDefinition& d, const KeyTarget& target,
                                   const RunRecord& run, size_t count) {
  std::vector<std::string> note{
      "lituya sweep: run " + std::to_string(run.number) + " of " + std::to_string(count) + ", " +
          d.parameter + " = " + run.literal +
          (target.present ? " (the scene has " + target.current + ")"
                          : " (not set in the scene, added here)"),
      "copy of " + fs::absolute(d.scene).lexically_normal().string() +
          "; its file references (mesh.geometry, post.reference, post.gauge_reference) are "
          "made absolute"};
  return note;
}

// Checks each copy with the scene reader, in a scratch file: the sweep folder is written only
// once the sweep can run. Marks the runs whose copy is not valid; returns the reader's
// messages without their location (empty for a valid copy).
std::vector<std::string> check_copies(const std::vector<std::string>& copies,
                                      std::vector<RunRecord>& runs) {
  std::vector<std::string> messages(copies.size());
  const fs::path scratch =
      fs::temp_directory_path() / ("lituya_sweep_check_" + std::to_string(::getpid()) + ".toml");
  for (size_t i = 0; i < copies.size(); ++i) {
    write_file_atomically(scratch, copies[i]);
    try {
      pre::read_scene(scratch);
    } catch (const InputError& e) {
      const fs::path copy = runs[i].folder / "scene.toml";
      runs[i].status = RunStatus::kInputError;
      messages[i] = replace_all(bare_message(e), scratch.string(), copy.string());
      runs[i].message =
          copy.string() + (e.line() > 0 ? ":" + std::to_string(e.line()) : "") + ": " + messages[i];
    }
  }
  std::error_code ignore;
  fs::remove(scratch, ignore);
  return messages;
}

std::string quoted_list(const std::vector<std::string>& items) {
  std::string list;
  for (const std::string& item : items) list += (list.empty() ? "\"" : ", \"") + item + "\"";
  return list.empty() ? "nothing" : list;
}

void write_table(const fs::path& file, const SweepResult& result) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "run," << csv_text(result.parameter);
    for (const std::string& m : result.measures) out << "," << csv_text(m);
    out << ",wall_time_s,status,message\n";
    for (const RunRecord& r : result.runs) {
      out << r.number << ","
          << csv_text(r.literal.size() > 1 && r.literal[0] == '"' ? r.value : r.literal);
      for (double v : r.measures) out << "," << csv_number(v);
      out << "," << csv_number(r.wall_time) << "," << status_text(r.status) << ","
          << csv_text(r.message) << "\n";
    }
  });
}

// Each measure against the parameter, lines through points (against the run number when the
// parameter is not a number). Without measures: the wall time of the runs.
bool write_plot(const SweepResult& result, const fs::path& scene, bool numeric_parameter) {
  const int x = numeric_parameter ? 2 : 1;
  const std::string xlabel =
      numeric_parameter ? result.parameter : "run (" + result.parameter + ": see sweep.csv)";
  std::vector<post::PlotSeries> series;
  auto add = [&](int column, const std::string& label, int colour) {
    series.push_back({result.table, x, column, label, false, 0, 0, colour});
    series.push_back({result.table, x, column, "", true, 0, 0, colour});
  };
  const int first_measure = 3;
  for (size_t m = 0; m < result.measures.size(); ++m)
    add(first_measure + static_cast<int>(m), result.measures[m], static_cast<int>(m) + 1);
  std::string ylabel = "measure (m)";
  if (result.measures.empty()) {
    add(first_measure, "wall time of the run", 1);
    ylabel = "wall time (s)";
  }
  return post::plot_xy(
      result.plot, "lituya sweep of " + result.parameter + " (" + scene.filename().string() + ")",
      xlabel, ylabel, series);
}

std::string run_line(const RunRecord& run, size_t count, const std::string& label,
                     const std::vector<std::string>& measures) {
  std::string line = "run " + std::to_string(run.number) + "/" + std::to_string(count) + " " +
                     label + ": " + status_text(run.status);
  if (run.status == RunStatus::kOk) {
    line += " in " + format_duration(run.wall_time);
    for (size_t m = 0; m < measures.size(); ++m)
      line += "  " + measures[m] + " = " + short_number(run.measures[m]);
  } else {
    line += ": " + run.message;
  }
  return line;
}

void run_one(RunRecord& run, const std::vector<Measure>& measures, const SweepOptions& options,
             std::ostream& ticks) {
  const fs::path scene = run.folder / "scene.toml";
  const fs::path case_folder = run.folder / "case";
  pre::preprocess(scene, case_folder, options.overwrite);
  solver::SolveOptions solve;
  solve.threads = options.threads;
  solve.overwrite = options.overwrite;
  solve.progress = &ticks;
  solver::solve_case(case_folder, solve);
  if (fs::exists(case_folder / "post.toml"))
    post::postprocess(case_folder, case_folder / "post", options.overwrite);
  for (size_t m = 0; m < measures.size(); ++m)
    run.measures[m] = take_measure(measures[m], case_folder / "post");
}

}  // namespace

std::string status_text(RunStatus status) {
  switch (status) {
    case RunStatus::kOk:
      return "ok";
    case RunStatus::kInputError:
      return "input error";
    case RunStatus::kRunStopped:
      return "run stopped";
    case RunStatus::kError:
      return "error";
  }
  return "error";
}

bool SweepResult::all_ok() const {
  return std::all_of(runs.begin(), runs.end(),
                     [](const RunRecord& r) { return r.status == RunStatus::kOk; });
}

std::string run_folder_name(int number, int count, const std::string& value) {
  const int digits = std::max(2, static_cast<int>(std::to_string(std::max(count, 1)).size()));
  char prefix[32];
  std::snprintf(prefix, sizeof prefix, "run_%0*d_", digits, number);
  std::string name;
  for (char c : value) {
    const bool keep =
        std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '+' || c == '-';
    name += keep ? c : '_';
  }
  if (name.size() > 40) name.resize(40);
  return prefix + name;
}

std::string format_table(const SweepResult& result) {
  const std::string& parameter = result.label;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> header{"run", parameter};
  for (const std::string& m : result.measures) header.push_back(m + " (m)");
  header.insert(header.end(), {"wall time", "status"});
  rows.push_back(header);
  for (const RunRecord& r : result.runs) {
    std::vector<std::string> row{std::to_string(r.number), r.value};
    for (double v : r.measures) row.push_back(short_number(v));
    row.push_back(r.status == RunStatus::kInputError ? "-" : format_duration(r.wall_time));
    row.push_back(status_text(r.status));
    rows.push_back(row);
  }
  std::vector<size_t> width(header.size(), 0);
  for (const auto& row : rows)
    for (size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  std::ostringstream out;
  for (const auto& row : rows) {
    std::string line;
    for (size_t c = 0; c < row.size(); ++c) {
      std::string cell = row[c];
      if (c + 1 < row.size()) cell += std::string(width[c] - cell.size() + 2, ' ');
      line += cell;
    }
    out << line << "\n";
  }
  for (const RunRecord& r : result.runs)
    if (r.status != RunStatus::kOk)
      out << "run " << r.number << " (" << parameter << " = " << r.value << "): " << r.message
          << "\n";
  return out.str();
}

SweepResult run_sweep(const SweepDefinition& definition, const SweepOptions& options) {
  // Everything is checked before the sweep folder is written.
  const SceneText scene(definition.scene);
  const KeyTarget target = scene.locate(definition.parameter);
  if (definition.values.empty())
    throw InputError(definition.source.empty() ? "--values" : definition.source.string(), 0,
                     "no values to sweep");
  const std::vector<std::string> literals = scene.literals(target, definition.values);
  const PostContent post = post_content(scene.table());
  const std::vector<Measure> measures =
      definition.measures.empty()
          ? default_measures(post)
          : parse_measures(definition.measures, post, scene.file().string());

  SweepResult result;
  result.parameter = definition.parameter;
  result.label = target.label;
  for (const Measure& m : measures) result.measures.push_back(m.name);
  result.folder = default_output(definition);
  result.table = result.folder / "sweep.csv";
  result.plot = result.folder / "sweep.png";

  const size_t count = definition.values.size();
  std::vector<std::string> copies;
  for (size_t i = 0; i < count; ++i) {
    RunRecord run;
    run.number = static_cast<int>(i) + 1;
    run.value = definition.values[i];
    run.literal = literals[i];
    run.folder = result.folder / run_folder_name(run.number, static_cast<int>(count), run.value);
    run.measures.assign(measures.size(), NAN);
    copies.push_back(
        scene.with_value(target, run.literal, copy_note(definition, target, run, count)));
    result.runs.push_back(run);
  }
  const std::vector<std::string> invalid = check_copies(copies, result.runs);
  if (std::none_of(result.runs.begin(), result.runs.end(),
                   [](const RunRecord& r) { return r.status == RunStatus::kOk; })) {
    if (target.new_table)
      throw InputError(scene.file().string(), 0,
                       "'" + definition.parameter + "': the scene has no table [" +
                           definition.parameter.substr(0, definition.parameter.find('.')) +
                           "] (it has: " + quoted_list(target.siblings) +
                           "), and the scene reader does not accept one: " + invalid[0]);
    if (!target.present)
      throw InputError(scene.file().string(), target.line,
                       "'" + definition.parameter + "': the scene does not set '" + target.leaf +
                           "' in " + target.where + " (it sets: " + quoted_list(target.siblings) +
                           "), and the scene reader does not accept it there: " + invalid[0]);
    throw InputError(scene.file().string(), target.line,
                     "sweeping '" + definition.parameter +
                         "': no value gives a valid scene; with the first, " + target.leaf + " = " +
                         result.runs[0].literal + ": " + invalid[0]);
  }

  if (options.dry_run) {
    if (options.report) {
      *options.report << "sweep of " << definition.parameter << " over " << count
                      << " values (scene " << definition.scene.string() << "), into "
                      << result.folder.string() << ":\n";
      for (const RunRecord& r : result.runs)
        *options.report << "  " << r.folder.filename().string() << "  " << target.label << " = "
                        << r.literal << "  "
                        << (r.status == RunStatus::kOk ? "valid" : "input error: " + r.message)
                        << "\n";
      *options.report << "measures: ";
      for (size_t m = 0; m < result.measures.size(); ++m)
        *options.report << (m ? ", " : "") << result.measures[m];
      *options.report << (result.measures.empty() ? "none (wall time only)\n" : "\n")
                      << "dry run: nothing was run or written\n";
    }
    return result;
  }
  prepare_output_folder(result.folder, options.overwrite);
  write_file_atomically(result.folder / "sweep.toml",
                        sweep_file_text(definition, literals, result.measures));

  SweepProgress progress(options.progress, options.progress_is_terminal, static_cast<int>(count));
  TickStream ticks([&progress] { progress.tick(); });
  SweepResult written = result;  // the rows of sweep.csv: the runs done so far
  written.runs.clear();
  for (size_t i = 0; i < count; ++i) {
    RunRecord& run = result.runs[i];
    const std::string label = target.label + "=" + run.value;
    fs::create_directories(run.folder);
    write_file_atomically(run.folder / "scene.toml", copies[i]);
    progress.start_run(label);
    const auto start = std::chrono::steady_clock::now();
    const bool valid = run.status == RunStatus::kOk;
    if (valid) {
      try {
        run_one(run, measures, options, ticks);
      } catch (const InputError& e) {
        run.status = RunStatus::kInputError;
        run.message = e.what();
      } catch (const RunError& e) {
        run.status = RunStatus::kRunStopped;
        run.message = e.what();
      } catch (const std::exception& e) {
        run.status = RunStatus::kError;
        run.message = e.what();
      }
      run.wall_time =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    progress.end_run(run_line(run, count, label, result.measures), run.wall_time, valid);
    written.runs.push_back(run);
    write_table(result.table, written);
  }
  progress.finish();

  result.plotted = write_plot(result, definition.scene, numeric(target, literals));
  if (options.report) {
    *options.report << "\nsweep of " << definition.parameter << " over " << count
                    << " values (scene " << definition.scene.string() << "):\n"
                    << format_table(result) << "table: " << result.table.string() << "\n";
    if (result.plotted) *options.report << "plot:  " << result.plot.string() << "\n";
    *options.report << "runs:  " << result.folder.string()
                    << "/run_*/ (scene.toml, and the case in case/)\n";
  }
  return result;
}

}  // namespace lituya::sweep
