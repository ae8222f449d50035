#include "lituya/sweep/sweep.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/csv_writer.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/common/json_file.hpp"
#include "lituya/common/output_folder.hpp"
#include "lituya/common/provenance.hpp"
#include "lituya/common/quoted_list.hpp"
#include "lituya/common/stop_request.hpp"
#include "lituya/post/plot.hpp"
#include "lituya/post/postprocess.hpp"
#include "lituya/pre/gmsh_mesh.hpp"
#include "lituya/pre/preprocess.hpp"
#include "lituya/pre/scene.hpp"
#include "lituya/solver/case_description.hpp"
#include "lituya/solver/checkpoint.hpp"
#include "lituya/solver/solve.hpp"
#include "lituya/sweep/convergence.hpp"
#include "lituya/sweep/measures.hpp"
#include "lituya/sweep/progress.hpp"
#include "lituya/sweep/repeats.hpp"
#include "lituya/sweep/scene_edit.hpp"

namespace lituya::sweep {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRunFile = "run.json";
// What the state after each of a run's first stages depends on (stage reuse, below).
constexpr const char* kStageInputsFile = "stage_inputs.json";
constexpr const char* kKeptMessage = "kept: finished in an earlier run of this sweep";

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

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool numeric(const KeyTarget& target, const std::vector<std::string>& literals) {
  // A key the scene does not set takes its type from the values: numbers when all are.
  for (const std::string& l : literals)
    if (l.empty() || l[0] == '"' || l == "true" || l == "false") return false;
  return target.type == ValueType::kInteger || target.type == ValueType::kNumber || !target.present;
}

// A value as sweep.csv shows it: a string without its TOML quotes, anything else as written.
std::string plain_value(const RunRecord& run, size_t p) {
  const std::string& literal = run.literals[p];
  return literal.size() > 1 && literal[0] == '"' ? run.values[p] : literal;
}

// A value as sweep.json holds it: a number, a boolean or a string, as the scene copy has it.
Json json_value(const RunRecord& run, size_t p) {
  try {
    const toml::table t = toml::parse("v = " + run.literals[p]);
    const toml::node& v = *t.get("v");
    if (auto i = v.value_exact<int64_t>()) return *i;
    if (auto x = v.value_exact<double>()) return json_number(*x);
    if (auto b = v.value_exact<bool>()) return *b;
    if (auto s = v.value_exact<std::string>()) return *s;
  } catch (const toml::parse_error&) {
  }
  return run.values[p];
}

// What a copy of the scene says about itself, at its end.
std::vector<std::string> copy_note(const SweepDefinition& d, const std::vector<KeyTarget>& targets,
                                   const RunRecord& run, size_t count) {
  std::vector<std::string> note{"lituya sweep: run " + std::to_string(run.number) + " of " +
                                std::to_string(count)};
  for (size_t p = 0; p < targets.size(); ++p)
    note.push_back(d.parameters[p].key + " = " + run.literals[p] +
                   (targets[p].present ? " (the scene has " + targets[p].current + ")"
                                       : " (not set in the scene, added here)"));
  note.push_back("copy of " + fs::absolute(d.scene).lexically_normal().string() +
                 "; its file references (mesh.geometry, post.reference, post.gauge_reference) "
                 "are made absolute");
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

std::string run_message(const RunRecord& run) {
  return run.kept ? kKeptMessage : run.message;
}

}  // namespace

void write_run_table(const fs::path& file, const SweepResult& result) {
  std::vector<std::string> header{"run"};
  header.insert(header.end(), result.parameters.begin(), result.parameters.end());
  header.insert(header.end(), result.measures.begin(), result.measures.end());
  header.insert(header.end(), {"wall_time_s", "status", "message"});
  CsvWriter table(header);
  for (const RunRecord& r : result.runs) {
    table.integer(r.number);
    for (size_t p = 0; p < r.values.size(); ++p) table.text(plain_value(r, p));
    for (double v : r.measures) table.number(v);
    table.number(r.wall_time).text(status_text(r.status)).text(run_message(r));
    table.end_row();
  }
  table.write(file);
}

namespace {

// sweep.json: the sweep and every run, machine-readable, each number as the run gave it.
void write_summary(const SweepResult& result, const SweepDefinition& definition,
                   const std::vector<RepeatSummaryRow>& repeats,
                   const std::vector<MeshConvergenceRow>& convergence) {
  Json runs = Json::array();
  for (const RunRecord& r : result.runs) {
    Json values = Json::object(), measures = Json::object();
    for (size_t p = 0; p < r.values.size(); ++p) values[result.parameters[p]] = json_value(r, p);
    for (size_t m = 0; m < r.measures.size(); ++m)
      measures[result.measures[m]] = json_number(r.measures[m]);
    runs.push_back({{"number", r.number},
                    {"folder", r.folder.filename().string()},
                    {"values", values},
                    {"status", status_text(r.status)},
                    {"kept", r.kept},
                    {"wall_time", json_number(r.wall_time)},
                    {"measures", measures},
                    {"reused_from", r.reused_from},
                    {"reused_stages", r.reused_stages},
                    {"message", r.message}});
  }
  Json summary = {{"format", "lituya-sweep-summary"},
                  {"version", 1},
                  {"lituya_version", lituya_version()},
                  {"commit", lituya_commit()},
                  {"date", utc_now_iso8601()},
                  {"scene", fs::absolute(definition.scene).lexically_normal().string()},
                  {"parameters", result.parameters},
                  {"combine", combination_name(result.combination)},
                  {"measures", result.measures},
                  {"all_ok", result.all_ok()},
                  {"runs", runs}};
  if (!convergence.empty()) {
    Json rows = Json::array();
    for (const MeshConvergenceRow& row : convergence) {
      const RichardsonEstimate& e = row.estimate;
      rows.push_back(
          {{"group", row.group},
           {"measure", row.measure},
           {"runs", row.runs},
           {"cell_sizes", e.cell_size},
           {"values", {json_number(e.value[0]), json_number(e.value[1]), json_number(e.value[2])}},
           {"change_fine", json_number(e.change_fine)},
           {"behaviour", behaviour_text(e.behaviour)},
           {"observed_order", json_number(e.order)},
           {"extrapolated", json_number(e.extrapolated)},
           {"gci_fine", json_number(e.gci_fine)},
           {"repeats", {row.spread[0].count, row.spread[1].count, row.spread[2].count}},
           {"sd",
            {json_number(row.spread[0].sd), json_number(row.spread[1].sd),
             json_number(row.spread[2].sd)}},
           {"note", e.note}});
    }
    summary["mesh_convergence"] = rows;
  }
  if (result.repeat_parameter >= 0) {
    summary["repeat_key"] = result.parameters[static_cast<size_t>(result.repeat_parameter)];
    Json rows = Json::array();
    for (const RepeatSummaryRow& row : repeats)
      rows.push_back({{"group", row.group},
                      {"measure", row.measure},
                      {"runs", row.spread.count},
                      {"mean", json_number(row.spread.mean)},
                      {"sd", json_number(row.spread.sd)},
                      {"min", json_number(row.spread.min)},
                      {"max", json_number(row.spread.max)}});
    summary["repeats"] = rows;
  }
  write_json_file(result.summary, summary);
}

// A run's record in its folder: how the parent learns the result of a run made in a process of
// its own, and what a resumed sweep keeps.
void write_run_file(const RunRecord& run, const std::vector<std::string>& measure_names) {
  Json measures = Json::object();
  for (size_t m = 0; m < run.measures.size(); ++m)
    measures[measure_names[m]] = json_number(run.measures[m]);
  write_json_file(run.folder / kRunFile, {{"number", run.number},
                                          {"values", run.values},
                                          {"status", status_text(run.status)},
                                          {"message", run.message},
                                          {"wall_time", json_number(run.wall_time)},
                                          {"measures", measures},
                                          {"reused_from", run.reused_from},
                                          {"reused_stages", run.reused_stages}});
}

// Reads a run's record into `run`; false when it is missing, unreadable or of another run.
bool read_run_file(RunRecord& run, const std::vector<std::string>& measure_names) {
  std::ifstream in(run.folder / kRunFile);
  if (!in) return false;
  try {
    const Json j = Json::parse(in);
    if (j.at("number").get<int>() != run.number ||
        j.at("values").get<std::vector<std::string>>() != run.values)
      return false;
    run.status = status_from_text(j.at("status").get<std::string>());
    run.message = j.at("message").get<std::string>();
    const Json& wall = j.at("wall_time");
    run.wall_time = wall.is_number() ? wall.get<double>() : NAN;
    const Json& measures = j.at("measures");
    for (size_t m = 0; m < measure_names.size(); ++m) {
      const auto v = measures.find(measure_names[m]);
      run.measures[m] = v != measures.end() && v->is_number() ? v->get<double>() : NAN;
    }
    // Absent from the run.json of a sweep made before stage reuse.
    run.reused_from = j.value("reused_from", 0);
    run.reused_stages = j.value("reused_stages", std::vector<std::string>());
    return true;
  } catch (const Json::exception&) {
    return false;
  }
}

// Each measure against the first parameter, lines through points (against the run number when
// it is not a number, or when a grid of more than two keys would mix curves). A grid of two
// number keys draws each measure against the second key, one curve per value of the first:
// the second varies fastest, so each curve's runs are consecutive rows of sweep.csv and its line
// is not broken by the rows of the other curves. Without measures: the wall time of the runs.
bool write_plot(const SweepResult& result, const SweepDefinition& definition,
                const std::vector<bool>& numeric_parameter) {
  // The repeat key is not plotted against: the repeats lie on top of each other.
  const size_t keys = result.parameters.size() - (result.repeat_parameter >= 0 ? 1 : 0);
  const bool two_key_grid = keys == 2 && result.combination == Combination::kGrid &&
                            numeric_parameter[0] && numeric_parameter[1];
  const bool against_first =
      numeric_parameter[0] && (keys == 1 || result.combination == Combination::kZip);
  const int x = two_key_grid ? 3 : against_first ? 2 : 1;
  const std::string xlabel = two_key_grid    ? result.parameters[1]
                             : against_first ? result.parameters[0]
                                             : "run (values: see sweep.csv)";
  std::vector<post::PlotSeries> series;
  int colour = 0;
  auto add = [&](int column, const std::string& label) {
    if (!two_key_grid) {
      ++colour;
      series.push_back({result.table, x, column, label, false, 0, 0, colour});
      series.push_back({result.table, x, column, "", true, 0, 0, colour});
      return;
    }
    // One curve per value of the first key (column 2).
    std::vector<std::string> seen;
    for (const RunRecord& r : result.runs) {
      if (std::find(seen.begin(), seen.end(), r.literals[0]) != seen.end()) continue;
      seen.push_back(r.literals[0]);
      ++colour;
      const double value = std::strtod(r.literals[0].c_str(), nullptr);
      const std::string curve = label + ", " + result.labels[0] + " = " + plain_value(r, 0);
      series.push_back({result.table, x, column, curve, false, 2, value, colour});
      series.push_back({result.table, x, column, "", true, 2, value, colour});
    }
  };
  // sweep.csv: run, every key (the repeat key too), then the measures.
  const int first_measure = 2 + static_cast<int>(result.parameters.size());
  for (size_t m = 0; m < result.measures.size(); ++m)
    add(first_measure + static_cast<int>(m), result.measures[m]);
  std::string ylabel = "measure (m)";
  // One axis for all measures: name the other unit when one of them has it.
  for (const std::string& m : result.measures)
    if (measure_unit(m) != "m")
      ylabel = "measure (m; " + measure_unit(m) + " for " + m.substr(0, m.find(':')) + ")";
  if (result.measures.empty()) {
    add(first_measure, "wall time of the run");
    ylabel = "wall time (s)";
  }
  std::string keys_text;
  for (const std::string& key : result.parameters)
    keys_text += (keys_text.empty() ? "" : ", ") + key;
  return post::plot_xy(
      result.plot,
      "lituya sweep of " + keys_text + " (" + definition.scene.filename().string() + ")", xlabel,
      ylabel, series);
}

// "'gravity'" or "'gravity', 'settle'".
std::string stage_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
  return list;
}

std::string run_line(const RunRecord& run, size_t count, const std::string& label,
                     const std::vector<std::string>& measures) {
  std::string line = "run " + std::to_string(run.number) + "/" + std::to_string(count) + " " +
                     label + ": " + status_text(run.status);
  if (run.status == RunStatus::kOk) {
    line += run.kept ? " (kept: finished in an earlier run of this sweep, not run again)"
                     : " in " + format_duration(run.wall_time);
    if (run.reused_from > 0)
      line += " (stages " + stage_list(run.reused_stages) + " reused from run " +
              std::to_string(run.reused_from) + ")";
    for (size_t m = 0; m < measures.size(); ++m)
      line += "  " + measures[m] + " = " + short_number(run.measures[m]);
  } else {
    line += ": " + run.message;
  }
  return line;
}

void take_measures(RunRecord& run, const std::vector<Measure>& measures) {
  for (size_t m = 0; m < measures.size(); ++m)
    run.measures[m] = take_measure(measures[m], run.folder / "case" / "post");
}

// Stage reuse. Each run, once `pre` has written its case, records the hashes of what the state
// after each of its first stages depends on (solver::stage_inputs_hashes) in its folder. A run
// looks for the finished run that shares the most first stages with it (equal hashes), waits
// for it to finish if it is still going (runs side by side), and starts from its end-of-stage
// checkpoint. A run is finished when its run.json exists: the parent removes the run.json of
// every run to make before any starts, and writes one for a run whose process died without.

// The hashes a run recorded after its pre; nothing before then.
std::optional<std::vector<std::string>> read_stage_inputs(const RunRecord& run) {
  std::ifstream in(run.folder / kStageInputsFile);
  if (!in) return std::nullopt;
  try {
    const Json j = Json::parse(in);
    if (j.at("number").get<int>() != run.number) return std::nullopt;
    return j.at("hashes").get<std::vector<std::string>>();
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

bool finished(const RunRecord& run) {
  return fs::exists(run.folder / kRunFile);
}

// Waits (polling) until `ready` or a stop signal; a stopped sweep must not leave a run waiting.
template <class Ready>
void wait_until(const Ready& ready, const RunRecord& run, const RunRecord& other) {
  while (!ready()) {
    if (const int signal = stop_signal())
      throw RunStopped(signal, "stopped by " + signal_name(signal) + " while run " +
                                   std::to_string(run.number) + " waited for run " +
                                   std::to_string(other.number));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

// Where a run starts: after the first `stages` stages of `source`, from `checkpoint`.
struct Reuse {
  const RunRecord* source = nullptr;
  size_t stages = 0;
  fs::path checkpoint;
};

// Whether `checkpoint` can start stage `stages` of a run whose state after its first `stages`
// stages has the hash `hash`: this build wrote it (check_checkpoint), after the same first
// stages, with the same threads (with other threads the result would differ in the last bits
// from a whole run).
bool usable_checkpoint(const fs::path& checkpoint, const std::string& hash, size_t stages,
                       int threads) {
  try {
    if (!fs::exists(checkpoint)) return false;
    const solver::CheckpointHeader header = solver::read_checkpoint_header(checkpoint);
    solver::check_checkpoint(checkpoint, header, hash, false);
    return header.threads == threads && !header.within_stage &&
           header.stage == static_cast<int>(stages);
  } catch (const std::exception&) {
    return false;
  }
}

// The run among `candidates` whose end state after the most first stages is this run's, and
// its checkpoint; nothing when none shares a stage. Ties go to the lowest run number. With
// `wait` (runs side by side), waits for a candidate's pre (its hashes) and, before using it,
// for the candidate to finish; without, the candidates are finished (run one after another)
// and one that is not (its run.json could not be written) is passed over, not waited for.
Reuse find_reuse(const RunRecord& run, const std::vector<std::string>& hashes,
                 const std::vector<std::string>& stage_names, const std::vector<RunRecord>& runs,
                 const std::vector<size_t>& candidates, int threads, bool wait) {
  struct Shared {
    size_t stages;
    const RunRecord* run;
  };
  std::vector<Shared> shared;
  for (size_t c : candidates) {
    const RunRecord& other = runs[c];
    if (other.number == run.number) continue;
    std::optional<std::vector<std::string>> theirs;
    if (wait)
      wait_until([&] { return (theirs = read_stage_inputs(other)) || finished(other); }, run,
                 other);
    else if (!finished(other))
      continue;
    else
      theirs = read_stage_inputs(other);
    // A run kept from an earlier sweep may predate the hashes file: its case tells them. A run
    // of this sweep without one failed before its solve.
    if (!theirs && !other.kept) continue;
    if (!theirs) try {
        theirs = solver::stage_inputs_hashes(other.folder / "case");
      } catch (const std::exception&) {
        continue;
      }
    // At most all stages but the last: the run must run at least one stage of its own.
    size_t k = 0;
    while (k + 1 < stage_names.size() && k + 1 < theirs->size() &&
           (*theirs)[k + 1] == hashes[k + 1])
      ++k;
    if (k > 0) shared.push_back({k, &other});
  }
  std::stable_sort(shared.begin(), shared.end(), [](const Shared& a, const Shared& b) {
    return a.stages != b.stages ? a.stages > b.stages : a.run->number < b.run->number;
  });
  for (const Shared& s : shared) {
    if (wait) wait_until([&] { return finished(*s.run); }, run, *s.run);
    // A source that failed in a later stage still ended the earlier ones.
    for (size_t k = s.stages; k > 0; --k) {
      const fs::path checkpoint =
          solver::end_of_stage_checkpoint(s.run->folder / "case" / "output", stage_names[k - 1]);
      if (usable_checkpoint(checkpoint, hashes[k], k, threads)) return {s.run, k, checkpoint};
    }
  }
  return {};
}

// A file of the source's output that the new run shares: a hard link (no extra disk; every
// Lituya write replaces a file by a rename, so neither run can change the other's), else a copy.
void link_or_copy(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_hard_link(from, to, ec);
  if (ec) fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

// Whether `file` (in the output folder) belongs to stage `stage`: its frames and .pvd series,
// <stage>_<set>_NNNN.vtu and <stage>_<set>.pvd (the names the output writer gives them), and
// its history table <stage>_history.csv (probe_recorder.hpp).
bool stage_output_file(const std::string& file, const std::string& stage) {
  if (file == stage + "_history.csv") return true;
  for (const char* set : {"_points", "_liquid", "_grid"}) {
    const std::string prefix = stage + set;
    if (file == prefix + ".pvd") return true;
    const size_t head = prefix.size() + 1, tail = 4;
    if (file.size() > head + tail && file.compare(0, head, prefix + "_") == 0 &&
        file.compare(file.size() - tail, tail, ".vtu") == 0 &&
        std::all_of(file.begin() + static_cast<std::ptrdiff_t>(head),
                    file.end() - static_cast<std::ptrdiff_t>(tail),
                    [](char c) { return c >= '0' && c <= '9'; }))
      return true;
  }
  return false;
}

// Makes `output` (the new run's output folder) what `solve --from-stage` needs to go on from
// `reuse`, as if the source's run had been made in it: the source's output folder without what
// belongs to its later stages (their frames, series, histories and checkpoints, which
// --from-stage would remove anyway), without the run's own files (log, summary, the whole-run
// series points.pvd and the others, which the solve writes again from the checkpoint's
// record) and without a within-stage checkpoint. What is left, the shared stages' output and
// whatever spans the run (probe tables, which --from-stage cuts to the shared stages), is
// linked or copied. The log starts with the source's log up to the end of the shared stages and
// a line that says where they came from. An earlier output is set aside as `solve --force`
// does.
void seed_output(const Reuse& reuse, const std::vector<std::string>& stage_names,
                 const fs::path& output, const std::string& note) {
  const fs::path source = reuse.source->folder / "case" / "output";
  // The stages whose output is not taken: this run's later ones, and the source's (they may
  // have other names when the key renames a stage).
  std::vector<std::string> later(stage_names.begin() + static_cast<std::ptrdiff_t>(reuse.stages),
                                 stage_names.end());
  for (const solver::Stage& stage : solver::read_case((source.parent_path()).string()).stages)
    if (std::find(stage_names.begin(),
                  stage_names.begin() + static_cast<std::ptrdiff_t>(reuse.stages),
                  stage.name) == stage_names.begin() + static_cast<std::ptrdiff_t>(reuse.stages))
      later.push_back(stage.name);
  if (fs::is_directory(output) && !fs::is_empty(output)) {
    const fs::path previous = fs::path(output).concat(".previous");
    fs::remove_all(previous);
    fs::rename(output, previous);
  }
  fs::create_directories(output / solver::kCheckpointFolder);
  for (size_t k = 0; k < reuse.stages; ++k) {
    const fs::path checkpoint = solver::end_of_stage_checkpoint(source, stage_names[k]);
    if (fs::exists(checkpoint))
      link_or_copy(checkpoint, solver::end_of_stage_checkpoint(output, stage_names[k]));
  }
  for (auto entry = fs::recursive_directory_iterator(source);
       entry != fs::recursive_directory_iterator(); ++entry) {
    const fs::path relative = entry->path().lexically_relative(source);
    if (entry->is_directory()) {
      if (relative == solver::kCheckpointFolder)
        entry.disable_recursion_pending();
      else
        fs::create_directories(output / relative);
      continue;
    }
    if (!entry->is_regular_file()) continue;
    const std::string name = relative.generic_string();
    const bool own = name == "log.txt" || name == solver::kSummaryFile || name == "points.pvd" ||
                     name == "liquid.pvd" || name == "grid.pvd";
    const bool of_later = std::any_of(later.begin(), later.end(), [&](const std::string& stage) {
      return stage_output_file(name, stage);
    });
    if (!own && !of_later) link_or_copy(entry->path(), output / relative);
  }
  std::string log;
  std::ifstream in(source / "log.txt");
  const std::string end = "stage '" + stage_names[reuse.stages - 1] + "': ";
  std::string kept;
  for (std::string line; std::getline(in, line);) {
    kept += line + "\n";
    if (line.rfind(end, 0) == 0) {
      log = kept;
      break;
    }
  }
  write_file_atomically(output / "log.txt", log + note + "\n");
}

void run_one(RunRecord& run, const std::vector<Measure>& measures, const SweepOptions& options,
             bool overwrite, std::ostream* ticks, const std::vector<RunRecord>& runs,
             const std::vector<size_t>& candidates, double& waited) {
  const fs::path scene = run.folder / "scene.toml";
  const fs::path case_folder = run.folder / "case";
  pre::preprocess(scene, case_folder, overwrite);
  solver::SolveOptions solve;
  solve.threads = options.threads;
  solve.overwrite = overwrite;
  solve.progress = ticks;
  if (options.reuse) {
    const std::vector<std::string> hashes = solver::stage_inputs_hashes(case_folder);
    write_json_file(run.folder / kStageInputsFile, {{"number", run.number}, {"hashes", hashes}});
    std::vector<std::string> stage_names;
    for (const solver::Stage& stage : solver::read_case(case_folder.string()).stages)
      stage_names.push_back(stage.name);
    const auto wait_start = std::chrono::steady_clock::now();
    // A single stage is always run: there is nothing to look for (nor to wait for).
    const Reuse reuse = stage_names.size() < 2
                            ? Reuse{}
                            : find_reuse(run, hashes, stage_names, runs, candidates,
                                         options.threads, options.jobs > 1);
    waited = seconds_since(wait_start);
    if (reuse.source) {
      run.reused_from = reuse.source->number;
      run.reused_stages.assign(stage_names.begin(),
                               stage_names.begin() + static_cast<std::ptrdiff_t>(reuse.stages));
      seed_output(reuse, stage_names, case_folder / "output",
                  "lituya sweep: run " + std::to_string(run.number) + " reused stages " +
                      stage_list(run.reused_stages) + " from run " +
                      std::to_string(reuse.source->number) + " (" +
                      fs::absolute(reuse.source->folder).lexically_normal().string() +
                      "): their end state from " +
                      fs::relative(reuse.checkpoint, reuse.source->folder).generic_string() +
                      " and their frames; the lines above are that run's");
      solve.overwrite = false;
      solve.from_stage = stage_names[reuse.stages];
    }
  }
  solver::solve_case(case_folder, solve);
  if (fs::exists(case_folder / "post.toml"))
    post::postprocess(case_folder, case_folder / "post", overwrite);
  take_measures(run, measures);
}

// Runs one run and records it in its folder; errors of the run become its status.
// `candidates`: the runs it may take its first stages from (stage reuse).
void execute(RunRecord& run, const std::vector<Measure>& measures,
             const std::vector<std::string>& measure_names, const SweepOptions& options,
             bool overwrite, std::ostream* ticks, const std::vector<RunRecord>& runs,
             const std::vector<size_t>& candidates) {
  const auto start = std::chrono::steady_clock::now();
  // The time spent waiting for another run to finish is not this run's.
  double waited = 0;
  try {
    run_one(run, measures, options, overwrite, ticks, runs, candidates, waited);
  } catch (const InputError& e) {
    run.status = RunStatus::kInputError;
    run.message = e.what();
  } catch (const RunError& e) {
    run.status = RunStatus::kRunStopped;
    run.message = e.what();
  } catch (const RunStopped& e) {
    run.status = RunStatus::kRunStopped;
    run.message = e.what();
  } catch (const std::exception& e) {
    run.status = RunStatus::kError;
    run.message = e.what();
  }
  run.wall_time = seconds_since(start) - waited;
  write_run_file(run, measure_names);
}

// Whether a resumed sweep keeps `run` as its earlier sweep left it: the scene copy is the one
// this sweep would write, the solve completed on the case files it recorded (the hash in
// summary.toml), and run.json says ok. Its measures are taken again from the post tables
// (the measures asked for may have changed); `post` runs again only when a table is missing.
bool keep_finished_run(RunRecord& run, const std::string& copy,
                       const std::vector<Measure>& measures,
                       const std::vector<std::string>& measure_names) {
  std::ifstream scene(run.folder / "scene.toml", std::ios::binary);
  if (!scene) return false;
  std::ostringstream text;
  text << scene.rdbuf();
  if (text.str() != copy) return false;
  const fs::path case_folder = run.folder / "case";
  try {
    if (solver::incomplete_run_problem(case_folder)) return false;
    const toml::table summary =
        toml::parse_file((case_folder / "output" / solver::kSummaryFile).string());
    if (summary["case_hash"].value_or(std::string()) != solver::case_files_hash(case_folder))
      return false;
  } catch (const std::exception&) {
    return false;
  }
  RunRecord earlier = run;
  if (!read_run_file(earlier, measure_names) || earlier.status != RunStatus::kOk) return false;
  try {
    try {
      take_measures(run, measures);
    } catch (const InputError&) {
      if (!fs::exists(case_folder / "post.toml")) throw;
      post::postprocess(case_folder, case_folder / "post", true);
      take_measures(run, measures);
    }
  } catch (const std::exception&) {
    return false;
  }
  run.kept = true;
  run.wall_time = earlier.wall_time;
  run.reused_from = earlier.reused_from;
  run.reused_stages = earlier.reused_stages;
  return true;
}

// A run going in a process of its own.
struct Child {
  pid_t pid;
  size_t run;
  std::chrono::steady_clock::time_point start;
};

std::string process_end(int status) {
  if (WIFSIGNALED(status))
    return "the run's process was ended by signal " + std::to_string(WTERMSIG(status)) + " (" +
           strsignal(WTERMSIG(status)) + ")";
  return "the run's process ended with exit code " + std::to_string(WEXITSTATUS(status));
}

// The Courant repeats: stage.<last>.courant with the values of repeat_values, from the scene's
// Courant number (or the solver's default).
SweepParameter courant_repeats(const SceneText& scene, const SweepDefinition& definition) {
  SweepParameter repeat;
  repeat.key = repeat_key(scene.table(), scene.file());
  const KeyTarget target = scene.locate(repeat.key);
  double courant = solver::Stage{}.courant;
  if (target.present) {
    try {
      courant = std::stod(target.current);
    } catch (const std::exception&) {
      throw InputError(
          scene.file().string(), target.line,
          "'" + repeat.key + "' must be a number for --repeats (got " + target.current + ")");
    }
  }
  repeat.values = repeat_values(courant, definition.repeats);
  return repeat;
}

// The mesh repeats: mesh.seed with the values of mesh_seed_values, from the scene's seed (or
// gmsh's default, 1).
SweepParameter mesh_repeats(const SceneText& scene, const SweepDefinition& definition) {
  SweepParameter repeat;
  repeat.key = kMeshSeedKey;
  const KeyTarget target = scene.locate(repeat.key);
  long long first = 1;  // gmsh's own seed when the scene gives none
  if (target.present) {
    std::size_t end = 0;
    try {
      first = std::stoll(target.current, &end);
    } catch (const std::exception&) {
      end = 0;
    }
    if (end == 0 || end != target.current.size())
      throw InputError(
          scene.file().string(), target.line,
          "'mesh.seed' must be a whole number for --repeat-by mesh (got " + target.current + ")");
  }
  if (first < 1 || first + definition.repeats - 1 > pre::kLargestMeshSeed)
    throw InputError(scene.file().string(), target.line,
                     "--repeat-by mesh needs the seeds " + std::to_string(first) + " to " +
                         std::to_string(first + definition.repeats - 1) +
                         ", but 'mesh.seed' runs from 1 to " +
                         std::to_string(pre::kLargestMeshSeed));
  repeat.values = mesh_seed_values(first, definition.repeats);
  return repeat;
}

// Repeats (repeats.hpp): appends the repeat key (Courant or mesh, as repeat_by_for
// says) to `definition` and makes each combination `definition.repeats` runs, the repeat
// varying fastest. Input errors name the sweep file (or --repeats) or the scene.
void add_repeat_key(const SceneText& scene, SweepDefinition& definition,
                    std::vector<std::vector<size_t>>& combos) {
  const std::string where = definition.source.empty() ? "--repeats" : definition.source.string();
  const std::string range = repeats_range_error(definition.repeats);
  if (!range.empty()) throw InputError(where, definition.repeats_line, "repeats " + range);
  definition.repeat_by = repeat_by_for(definition);  // before the repeat key joins the keys
  const bool by_mesh = definition.repeat_by == RepeatBy::kMesh;
  SweepParameter repeat =
      by_mesh ? mesh_repeats(scene, definition) : courant_repeats(scene, definition);
  for (const SweepParameter& parameter : definition.parameters)
    if (parameter.key == repeat.key)
      throw InputError(
          where, parameter.line,
          "'" + repeat.key + "' is the key that repeats change (" +
              (by_mesh ? "the mesh's seed, one more per repeat" : "by 2e-4 of itself per repeat") +
              "); sweep it or repeat the runs, not both");
  definition.parameters.push_back(repeat);
  std::vector<std::vector<size_t>> repeated;
  for (const std::vector<size_t>& combo : combos)
    for (int k = 0; k < definition.repeats; ++k) {
      repeated.push_back(combo);
      repeated.back().push_back(static_cast<size_t>(k));
    }
  if (repeated.size() > kMaxRuns)
    throw InputError(where, definition.repeats_line,
                     std::to_string(combos.size()) + " runs x " +
                         std::to_string(definition.repeats) +
                         " repeats = " + std::to_string(repeated.size()) + " runs, more than " +
                         std::to_string(kMaxRuns));
  combos = std::move(repeated);
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

RunStatus status_from_text(const std::string& text) {
  for (RunStatus s :
       {RunStatus::kOk, RunStatus::kInputError, RunStatus::kRunStopped, RunStatus::kError})
    if (status_text(s) == text) return s;
  return RunStatus::kError;
}

std::string RunRecord::label(const std::vector<std::string>& labels) const {
  std::string text;
  for (size_t p = 0; p < values.size(); ++p) text += (p ? " " : "") + labels[p] + "=" + values[p];
  return text;
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
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> header{"run"};
  header.insert(header.end(), result.labels.begin(), result.labels.end());
  for (const std::string& m : result.measures) header.push_back(m + " (" + measure_unit(m) + ")");
  header.insert(header.end(), {"wall time", "status"});
  rows.push_back(header);
  for (const RunRecord& r : result.runs) {
    std::vector<std::string> row{std::to_string(r.number)};
    row.insert(row.end(), r.values.begin(), r.values.end());
    for (double v : r.measures) row.push_back(short_number(v));
    row.push_back(r.status == RunStatus::kInputError || !std::isfinite(r.wall_time)
                      ? "-"
                      : format_duration(r.wall_time));
    row.push_back(status_text(r.status) + (r.kept ? " (kept)" : ""));
    rows.push_back(row);
  }
  std::ostringstream out;
  out << align_columns(rows);
  for (const RunRecord& r : result.runs)
    if (r.status != RunStatus::kOk)
      out << "run " << r.number << " (" << r.label(result.labels) << "): " << r.message << "\n";
  return out.str();
}

SweepResult run_sweep(const SweepDefinition& user_definition, const SweepOptions& options) {
  // Everything is checked before the sweep folder is written.
  const SceneText scene(user_definition.scene);
  std::vector<std::vector<size_t>> combos = combinations(user_definition);
  // With repeats, the sweep's keys gain the repeat key (repeats.hpp), varying fastest.
  SweepDefinition definition = user_definition;
  if (definition.repeats > 1) add_repeat_key(scene, definition, combos);
  std::vector<KeyTarget> targets;
  std::vector<std::vector<std::string>> literals;
  std::vector<bool> numeric_parameter;
  for (const SweepParameter& parameter : definition.parameters) {
    targets.push_back(scene.locate(parameter.key));
    // The repeat values are the sweep's own TOML literals (floats for the Courant number,
    // integers for the seed): a scene's `courant = 1` (an integer) must not make them a type
    // error the user cannot fix on the command line.
    const bool repeat_key = definition.repeats > 1 && &parameter == &definition.parameters.back();
    literals.push_back(repeat_key ? parameter.values
                                  : scene.literals(targets.back(), parameter.values));
    numeric_parameter.push_back(numeric(targets.back(), literals.back()));
  }
  const PostContent post = post_content(scene.table());
  const std::vector<Measure> measures =
      definition.measures.empty()
          ? default_measures(post)
          : parse_measures(definition.measures, post, scene.file().string());

  SweepResult result;
  for (size_t p = 0; p < targets.size(); ++p) {
    result.parameters.push_back(definition.parameters[p].key);
    result.labels.push_back(targets[p].label);
  }
  result.combination = definition.combination;
  if (definition.repeats > 1) result.repeat_parameter = static_cast<int>(targets.size()) - 1;
  for (const Measure& m : measures) result.measures.push_back(m.name);
  result.folder = default_output(user_definition);
  result.table = result.folder / "sweep.csv";
  result.summary = result.folder / "sweep.json";
  result.plot = result.folder / "sweep.png";

  const size_t count = combos.size();
  std::vector<std::string> copies;
  for (size_t i = 0; i < count; ++i) {
    RunRecord run;
    run.number = static_cast<int>(i) + 1;
    std::vector<KeySetting> settings;
    std::string folder_value;
    for (size_t p = 0; p < targets.size(); ++p) {
      run.values.push_back(definition.parameters[p].values[combos[i][p]]);
      run.literals.push_back(literals[p][combos[i][p]]);
      settings.push_back({targets[p], run.literals.back()});
      folder_value += (p ? "_" : "") + run.values.back();
    }
    run.folder = result.folder / run_folder_name(run.number, static_cast<int>(count), folder_value);
    run.measures.assign(measures.size(), NAN);
    copies.push_back(scene.with_values(settings, copy_note(definition, targets, run, count)));
    result.runs.push_back(run);
  }
  const std::vector<std::string> invalid = check_copies(copies, result.runs);
  if (std::none_of(result.runs.begin(), result.runs.end(),
                   [](const RunRecord& r) { return r.status == RunStatus::kOk; })) {
    const KeyTarget& target = targets[0];
    const std::string& key = definition.parameters[0].key;
    if (targets.size() > 1)
      throw InputError(scene.file().string(), 0,
                       "no run of the sweep gives a valid scene; with the first (" +
                           result.runs[0].label(result.labels) + "): " + invalid[0]);
    if (target.new_table)
      throw InputError(scene.file().string(), 0,
                       "'" + key + "': the scene has no table [" + key.substr(0, key.find('.')) +
                           "] (it has: " + quoted_list(target.siblings) +
                           "), and the scene reader does not accept one: " + invalid[0]);
    if (!target.present)
      throw InputError(scene.file().string(), target.line,
                       "'" + key + "': the scene does not set '" + target.leaf + "' in " +
                           target.where + " (it sets: " + quoted_list(target.siblings) +
                           "), and the scene reader does not accept it there: " + invalid[0]);
    throw InputError(scene.file().string(), target.line,
                     "sweeping '" + key + "': no value gives a valid scene; with the first, " +
                         target.leaf + " = " + result.runs[0].literals[0] + ": " + invalid[0]);
  }

  if (options.dry_run) {
    if (options.report) {
      std::string keys;
      for (const std::string& k : result.parameters) keys += (keys.empty() ? "" : ", ") + k;
      *options.report << "sweep of " << keys << " over " << count << " runs (scene "
                      << definition.scene.string()
                      << (targets.size() > 1
                              ? ", combine = " + combination_name(definition.combination)
                              : std::string())
                      << "), into " << result.folder.string() << ":\n";
      for (const RunRecord& r : result.runs) {
        *options.report << "  " << r.folder.filename().string() << " ";
        for (size_t p = 0; p < targets.size(); ++p)
          *options.report << " " << targets[p].label << " = " << r.literals[p];
        *options.report << "  "
                        << (r.status == RunStatus::kOk ? "valid" : "input error: " + r.message)
                        << "\n";
      }
      *options.report << "measures: ";
      for (size_t m = 0; m < result.measures.size(); ++m)
        *options.report << (m ? ", " : "") << result.measures[m];
      *options.report << (result.measures.empty() ? "none (wall time only)\n" : "\n")
                      << "dry run: nothing was run or written\n";
    }
    return result;
  }
  if (options.resume) {
    fs::create_directories(result.folder);
  } else {
    std::error_code ec;
    if (!options.overwrite && fs::exists(result.folder / "sweep.toml", ec))
      throw InputError(result.folder.string(), 0,
                       "holds an earlier sweep; pass --resume to continue it (the runs that "
                       "finished are kept) or --force to run every run again");
    prepare_output_folder(result.folder, options.overwrite);
  }
  write_file_atomically(
      result.folder / "sweep.toml",
      sweep_file_text(
          user_definition,
          std::vector<std::vector<std::string>>(
              literals.begin(),
              literals.begin() + static_cast<std::ptrdiff_t>(user_definition.parameters.size())),
          result.measures));

  // A run that is not kept runs into its folder whatever an earlier sweep left there.
  const bool overwrite = options.overwrite || options.resume;
  const int jobs = std::max(1, options.jobs);
  SweepProgress progress(options.progress, options.progress_is_terminal, static_cast<int>(count),
                         jobs);
  TickStream ticks([&progress] { progress.tick(); });
  SweepResult written = result;  // the rows of sweep.csv: the runs done so far, in order
  written.runs.clear();
  auto finish = [&](size_t i, bool timed) {
    const RunRecord& run = result.runs[i];
    const std::string label = run.label(result.labels);
    progress.end_run(label, run_line(run, count, label, result.measures), run.wall_time, timed);
    const auto at = std::upper_bound(
        written.runs.begin(), written.runs.end(), run,
        [](const RunRecord& a, const RunRecord& b) { return a.number < b.number; });
    written.runs.insert(at, run);
    write_run_table(result.table, written);
  };

  // The runs to make: invalid copies and kept runs are recorded at once.
  std::vector<size_t> todo;
  for (size_t i = 0; i < count; ++i) {
    RunRecord& run = result.runs[i];
    fs::create_directories(run.folder);
    const std::string label = run.label(result.labels);
    if (run.status != RunStatus::kOk) {
      write_file_atomically(run.folder / "scene.toml", copies[i]);
      progress.start_run(label);
      finish(i, false);
    } else if (options.resume && keep_finished_run(run, copies[i], measures, result.measures)) {
      progress.start_run(label);
      finish(i, false);
    } else {
      // A record of an earlier, unfinished try must not pass for this run's, nor its hashes
      // (stage reuse) for those of this run's case.
      std::error_code ignore;
      fs::remove(run.folder / kRunFile, ignore);
      fs::remove(run.folder / kStageInputsFile, ignore);
      write_file_atomically(run.folder / "scene.toml", copies[i]);
      todo.push_back(i);
    }
  }

  // The runs a run may take its first stages from: those kept from the earlier sweep and those
  // made before it. Runs start in this order, so a run waits only for runs already going.
  auto candidates = [&](size_t at) {
    std::vector<size_t> list;
    for (size_t i = 0; i < count; ++i)
      if (result.runs[i].kept) list.push_back(i);
    list.insert(list.end(), todo.begin(), todo.begin() + static_cast<std::ptrdiff_t>(at));
    return list;
  };
  if (jobs == 1) {
    for (size_t t = 0; t < todo.size(); ++t) {
      const size_t i = todo[t];
      progress.start_run(result.runs[i].label(result.labels));
      execute(result.runs[i], measures, result.measures, options, overwrite, &ticks, result.runs,
              candidates(t));
      finish(i, true);
    }
  } else {
    // Each run in a process of its own, at most `jobs` at a time. The parent only waits,
    // refreshes the progress line and collects each run's run.json.
    std::vector<Child> children;
    size_t next = 0;
    while (next < todo.size() || !children.empty()) {
      while (children.size() < static_cast<size_t>(jobs) && next < todo.size()) {
        const std::vector<size_t> sources = candidates(next);
        const size_t i = todo[next++];
        RunRecord& run = result.runs[i];
        progress.start_run(run.label(result.labels));
        // What the parent has buffered would otherwise be written twice, once by the child.
        std::cout.flush();
        std::cerr.flush();
        if (options.progress) options.progress->flush();
        if (options.report) options.report->flush();
        const pid_t pid = fork();
        if (pid == 0) {
          execute(run, measures, result.measures, options, overwrite, nullptr, result.runs,
                  sources);
          std::cout.flush();
          std::cerr.flush();
          // Not exit(): the parent's atexit handlers and static objects are not the child's.
          std::_Exit(0);
        }
        if (pid < 0) {
          run.status = RunStatus::kError;
          run.message = std::string("could not start a process for the run: ") + strerror(errno);
          write_run_file(run, result.measures);  // a later run may be waiting for it
          finish(i, false);
          continue;
        }
        children.push_back({pid, i, std::chrono::steady_clock::now()});
      }
      bool ended = false;
      for (auto child = children.begin(); child != children.end();) {
        int status = 0;
        const pid_t done = waitpid(child->pid, &status, WNOHANG);
        if (done == 0 || (done < 0 && errno == EINTR)) {
          ++child;
          continue;
        }
        RunRecord& run = result.runs[child->run];
        if (done < 0 || !read_run_file(run, result.measures)) {
          run.status = RunStatus::kError;
          run.message = done < 0 ? std::string("lost the run's process: ") + strerror(errno)
                                 : process_end(status) + " before it recorded a result";
          run.wall_time = seconds_since(child->start);
          write_run_file(run, result.measures);  // a later run may be waiting for it
        }
        finish(child->run, true);
        child = children.erase(child);
        ended = true;
      }
      if (!ended && !children.empty()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        progress.tick();
      }
    }
  }
  progress.finish();

  const std::vector<RepeatSummaryRow> repeats = repeat_summary(result);
  std::error_code no_repeats;
  if (!repeats.empty()) {
    result.repeats = result.folder / "repeats.csv";
    write_repeat_table(result.repeats, repeats);
  } else {
    fs::remove(result.folder / "repeats.csv", no_repeats);
  }
  const std::vector<MeshConvergenceRow> convergence = mesh_convergence(result);
  if (!convergence.empty()) {
    result.convergence = result.folder / "convergence.csv";
    write_convergence_table(result.convergence, convergence);
  } else {
    // An earlier sweep in this folder (--force) may have left one that is not of this sweep.
    std::error_code ignored;
    fs::remove(result.folder / "convergence.csv", ignored);
  }
  write_summary(result, definition, repeats, convergence);
  result.plotted = write_plot(result, definition, numeric_parameter);
  if (options.report) {
    std::string keys;
    for (const std::string& k : result.parameters) keys += (keys.empty() ? "" : ", ") + k;
    const auto kept = std::count_if(result.runs.begin(), result.runs.end(),
                                    [](const RunRecord& r) { return r.kept; });
    *options.report << "\nsweep of " << keys << " over " << count << " runs (scene "
                    << definition.scene.string() << "):\n"
                    << format_table(result);
    if (kept > 0)
      *options.report << kept << " of " << count
                      << " runs kept from the earlier run of the sweep (--resume)\n";
    const auto reused = std::count_if(result.runs.begin(), result.runs.end(),
                                      [](const RunRecord& r) { return r.reused_from > 0; });
    if (reused > 0)
      *options.report << reused << " of " << count
                      << " runs started from the end of stages they share with another run "
                         "(--no-reuse runs every run whole)\n";
    *options.report << format_repeats(repeats, repeat_key_of(result))
                    << format_shared_meshes(result) << format_convergence(convergence);
    *options.report << "table: " << result.table.string() << "\n"
                    << "json:  " << result.summary.string() << "\n";
    if (result.plotted) *options.report << "plot:  " << result.plot.string() << "\n";
    if (!result.repeats.empty()) *options.report << "repeats: " << result.repeats.string() << "\n";
    if (!result.convergence.empty())
      *options.report << "mesh convergence: " << result.convergence.string() << "\n";
    *options.report << "runs:  " << result.folder.string()
                    << "/run_*/ (scene.toml, run.json, and the case in case/)\n";
  }
  return result;
}

}  // namespace lituya::sweep
