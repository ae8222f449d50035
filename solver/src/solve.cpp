#include "lituya/solver/solve.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <memory>
#include <ostream>
#include <sstream>
#include <utility>

#include <toml++/toml.h>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/content_hash.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/common/output_folder.hpp"
#include "lituya/common/provenance.hpp"
#include "lituya/common/stop_request.hpp"
#include "lituya/solver/case_loader.hpp"
#include "lituya/solver/checkpoint.hpp"
#include "lituya/solver/output_writer.hpp"
#include "lituya/solver/probe_recorder.hpp"

namespace lituya::solver {

namespace fs = std::filesystem;

namespace {

// "case/" -> "case": lexically_relative against a path with a trailing separator fails.
fs::path without_trailing_separator(const fs::path& folder) {
  fs::path p = folder.lexically_normal();
  return p.filename().empty() && p.has_parent_path() ? p.parent_path() : p;
}

std::string describe(const StageReport& r, std::size_t n_points) {
  std::ostringstream s;
  s << std::setprecision(4) << "stage '" << r.stage << "': " << r.steps << " steps, "
    << r.simulated_time << " s simulated in " << r.wall_time << " s wall, "
    << r.point_steps_per_second / 1e6 << " M point-steps/s (" << n_points
    << " points), peak memory " << static_cast<double>(r.peak_memory) / (1024.0 * 1024.0)
    << " MiB; stopped: " << r.stop_reason;
  return s.str();
}

// Who made the run and from what: recorded in log.txt and summary.toml.
struct Provenance {
  std::string started = utc_now_iso8601();
  std::string case_hash;
  // A run that went on from a checkpoint: when, and from which.
  std::string resumed, resumed_from;
};

// summary.toml, rewritten whole at each change of the run's state. It is written to a
// temporary file and renamed over the old one, so a kill or a full disk during the write leaves
// the previous summary, never half of one.
class Summary {
 public:
  Summary(fs::path file, Provenance provenance, int threads)
      : file_(std::move(file)), provenance_(std::move(provenance)), threads_(threads) {}

  void set_points(std::size_t n) { points_ = n; }
  // state: "running", "completed", "stopped" or "failed"; reason: why it stopped or failed.
  void write(const std::string& state, const std::vector<StageReport>& reports,
             const std::string& reason = "") const {
    toml::array stages;
    for (const StageReport& r : reports)
      stages.push_back(toml::table{{"name", r.stage},
                                   {"steps", r.steps},
                                   {"simulated_time", r.simulated_time},
                                   {"wall_time", r.wall_time},
                                   {"point_steps_per_second", r.point_steps_per_second},
                                   {"peak_memory_bytes", static_cast<int64_t>(r.peak_memory)},
                                   {"stop_reason", r.stop_reason}});
    toml::table t{{"lituya_version", lituya_version()},
                  {"commit", lituya_commit()},
                  {"case_hash", provenance_.case_hash},
                  {"started", provenance_.started},
                  {"state", state},
                  {"completed", state == "completed"},
                  {"points", static_cast<int64_t>(points_)},
                  {"threads", threads_},
                  {"stage", stages}};
    if (!provenance_.resumed.empty()) {
      t.insert("resumed", provenance_.resumed);
      t.insert("resumed_from", provenance_.resumed_from);
    }
    if (state != "running") t.insert("finished", utc_now_iso8601());
    if (!reason.empty()) t.insert("reason", reason);
    // `error` as in format version 1, for readers that look for it.
    if (state == "failed") t.insert("error", reason);
    write_file_atomically(file_, [&](std::ostream& out) {
      out << "format = \"lituya-summary\"\nversion = 2\n" << t << "\n";
    });
  }

 private:
  fs::path file_;
  Provenance provenance_;
  int threads_;
  std::size_t points_ = 0;
};

// The stage as run_stage should see it: an output interval longer than the stage would let
// the stage end past its duration without writing its final state (only t = 0 was written),
// because run_stage aims its steps at the next output time. Clamped to the duration, the last
// step lands on the duration and its state is written there.
Stage as_run(const Stage& stage) {
  Stage s = stage;
  if (s.output_interval > s.duration) s.output_interval = s.duration;
  return s;
}

// Where a run begins: at the case's initial state, or at a checkpoint.
struct Start {
  std::optional<fs::path> checkpoint;
  CheckpointHeader header;                 // of the checkpoint
  std::vector<std::string> inputs_hashes;  // stage_inputs_hashes of the case
};

std::string describe(const CheckpointHeader& h, const std::vector<Stage>& stages) {
  std::ostringstream s;
  s << h.reason << ", step " << h.step_count << ", ";
  if (h.within_stage)
    s << "stage '" << stages.at(static_cast<std::size_t>(h.stage)).name
      << "' at t = " << std::setprecision(6) << h.within_stage->time << " s";
  else if (static_cast<std::size_t>(h.stage) < stages.size())
    s << "before stage '" << stages[static_cast<std::size_t>(h.stage)].name << "'";
  else
    s << "after the last stage";
  s << ", written " << h.written;
  return s.str();
}

template <int dim>
std::vector<StageReport> run(const CaseDescription& description, const SolveOptions& options,
                             const fs::path& output_folder, std::ostream& log, Summary& summary,
                             const Provenance& provenance, const Start& start) {
  std::vector<StageReport> reports;
  auto note = [&](const std::string& line) {
    log << line << "\n" << std::flush;
    if (options.progress) *options.progress << line << "\n" << std::flush;
  };
  // Every way out of the run but success leaves a summary that says why: a killed run leaves
  // "running" from below, a stopped or failed one says so here.
  std::string stop_where = "before the first stage";
  auto stop_message = [&](int signal) {
    return "stopped by " + signal_name(signal) + " " + stop_where;
  };
  // Probes and stage histories; outside the try so that a failed run still writes the rows
  // sampled up to its failure.
  std::unique_ptr<ProbeRecorder<dim>> records;
  auto write_records = [&] {
    try {
      if (records) records->write();
    } catch (const std::exception&) {  // the first error is the one to report
    }
  };
  try {
    LoadedCase<dim> loaded = load_case<dim>(description);
    const std::size_t n_points = loaded.points.size() + loaded.liquid.size();
    const std::size_t n_liquid = loaded.liquid.size();
    Simulation<dim> simulation(description, std::move(loaded.mesh), std::move(loaded.points),
                               std::move(loaded.constraints), std::move(loaded.liquid));
    simulation.set_threads(options.threads);
    simulation.set_progress_stream(options.progress);
    OutputWriter<dim> writer(output_folder, description.output);
    std::size_t first_stage = 0;
    if (start.checkpoint) {
      RunRecord record = read_checkpoint(*start.checkpoint, simulation);
      reports = std::move(record.reports);
      writer.restore_series(record.series);
      first_stage = static_cast<std::size_t>(start.header.stage);
      stop_where = first_stage < description.stages.size()
                       ? "before stage '" + description.stages[first_stage].name + "'"
                       : "after the last stage";
    }
    records = std::make_unique<ProbeRecorder<dim>>(simulation, description.probes, output_folder);
    if (start.checkpoint)
      records->restart(description.stages, first_stage,
                       start.header.within_stage
                           ? std::optional<double>(start.header.within_stage->time)
                           : std::nullopt);
    summary.set_points(n_points);
    summary.write("running", reports);

    // Checkpoints (checkpoint.hpp). A within-stage one replaces the previous within-stage one;
    // the end of a stage makes it stale, and it is removed then.
    std::size_t current = first_stage;
    const double interval_seconds = 60.0 * description.solver.checkpoint_interval_minutes;
    auto wall_clock = [] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
          .count();
    };
    double last_checkpoint = wall_clock();
    auto checkpoint = [&](const fs::path& file, const std::string& reason, std::size_t stage,
                          std::optional<StageProgress> within) {
      records->write();  // the tables hold every row up to the state the checkpoint keeps
      CheckpointHeader header;
      header.case_hash = provenance.case_hash;
      // What this state depends on: the stages run so far, the running one included.
      header.inputs_hash = start.inputs_hashes.at(within ? stage + 1 : stage);
      header.started = provenance.started;
      header.reason = reason;
      header.stage = static_cast<int>(stage);
      header.within_stage = within;
      write_checkpoint(file, simulation, header, RunRecord{reports, writer.series()});
      last_checkpoint = wall_clock();
    };
    // The output callback writes the state; what ends the run comes after the step
    // (after_step), where the state is whole and a checkpoint can hold it.
    std::pair<const Stage*, double> last_output{nullptr, 0.0};
    auto on_output = [&](const Stage& stage, double t, int index) {
      writer.write(simulation, stage, t, index);
      records->at_output(simulation, t);
      last_output = {&stage, t};
    };
    auto after_step = [&](const Stage& stage, const StageProgress& at) {
      records->after_step(simulation, at.time);
      const int signal = stop_signal();
      const bool due = interval_seconds > 0 && wall_clock() - last_checkpoint >= interval_seconds;
      if (!signal && !due) return;
      std::ostringstream reason;
      if (signal)
        reason << "stopped by " << signal_name(signal);
      else
        reason << "every " << description.solver.checkpoint_interval_minutes << " minutes";
      checkpoint(within_stage_checkpoint(output_folder), reason.str(), current, at);
      if (signal) {
        // SIGINT/SIGTERM: the run ends with this step's state as its last output, written
        // after the checkpoint; a run resumed from it writes its next scheduled output over
        // this one, under the same number, as a run never stopped does.
        if (last_output != std::pair<const Stage*, double>{&stage, at.time})
          writer.write(simulation, stage, at.time, at.next_output_index);
        std::ostringstream where;
        where << "in stage '" << stage.name << "' at t = " << std::setprecision(6) << at.time
              << " s";
        stop_where = where.str();
        throw RunStopped(signal, stop_message(signal));
      }
    };
    note("Lituya solve: " + std::to_string(dim) + "D, " + std::to_string(n_points) + " points (" +
         std::to_string(n_liquid) + " liquid), " + std::to_string(simulation.mesh().cell_count()) +
         " cells, " + std::to_string(options.threads) + " thread(s)");
    note(simulation.transfer_damping().description);
    if (simulation.has_liquid()) note(simulation.pressure_projection_description());
    if (start.checkpoint) {
      note("Going on from checkpoint " + start.checkpoint->string() + " (" +
           describe(start.header, description.stages) + ")");
      if (start.header.threads != options.threads)
        note("Note: the checkpoint was written by a run with " +
             std::to_string(start.header.threads) + " thread(s), this one has " +
             std::to_string(options.threads) +
             ": the results differ in the last bits from those of a run never interrupted");
      if (first_stage >= description.stages.size())
        note("The run had completed all its stages: nothing left to run");
    }
    for (current = first_stage; current < description.stages.size(); ++current) {
      const Stage& stage = description.stages[current];
      if (const int signal = stop_signal()) throw RunStopped(signal, stop_message(signal));
      const bool within = start.checkpoint && current == first_stage && start.header.within_stage;
      records->begin_stage(
          as_run(stage), run_time_at_stage_start(reports),
          within ? std::optional<double>(start.header.within_stage->time) : std::nullopt);
      const long landed_before = simulation.landed_point_count();
      reports.push_back(simulation.run_stage(as_run(stage), on_output, after_step,
                                             within ? &*start.header.within_stage : nullptr));
      note(describe(reports.back(), n_points));
      if (const long landed = simulation.landed_point_count() - landed_before; landed > 0)
        note("stage '" + stage.name + "': " + std::to_string(landed) +
             " landings of liquid points from free flight, merged into the water they met "
             "([solver] liquid_landing)");
      checkpoint(end_of_stage_checkpoint(output_folder, stage.name),
                 "end of stage '" + stage.name + "'", current + 1, std::nullopt);
      fs::remove(within_stage_checkpoint(output_folder));
      summary.write("running", reports);
      stop_where = "after stage '" + stage.name + "'";
    }
  } catch (const RunStopped& e) {
    note(std::string("STOPPED: ") + e.what() + "; the state at that time is the last output");
    note("The output written up to then is kept in " + output_folder.string() +
         "; `lituya solve CASE --resume` goes on from its last checkpoint");
    write_records();
    summary.write("stopped", reports, e.what());
    throw;
  } catch (const RunError& e) {
    note(std::string("ERROR: ") + e.what());
    note("The output written before the failure is kept in " + output_folder.string());
    write_records();
    summary.write("failed", reports, e.what());
    throw;
  } catch (const std::exception& e) {
    // A bad input file found while loading, a write that failed: the summary must not go on
    // saying "running". Writing it may fail too (a full disk); the first error is the one to
    // report.
    log << "ERROR: " << e.what() << "\n" << std::flush;
    try {
      summary.write("failed", reports, e.what());
    } catch (const std::exception&) {
    }
    throw;
  }
  summary.write("completed", reports);
  return reports;
}

// --force: the earlier run's output (VTU and PVD series, log, summary) must not sit beside
// the new run's, where a partial new run would look complete or a shorter one would leave
// stale frames. It is moved whole to <output>.previous, replacing an older one: one rename,
// and the earlier results survive until the next --force. Without keep_previous it is deleted.
void set_aside_earlier_run(const fs::path& output_folder, bool keep_previous) {
  const fs::path folder = without_trailing_separator(output_folder);
  if (!fs::is_directory(folder) || fs::is_empty(folder)) return;
  if (!keep_previous) {
    fs::remove_all(folder);
    return;
  }
  const fs::path previous = fs::path(folder).concat(".previous");
  fs::remove_all(previous);
  fs::rename(folder, previous);
}

// --resume: the newest checkpoint of the run in `output_folder`.
fs::path resume_checkpoint(const fs::path& output_folder) {
  const fs::path folder = output_folder / kCheckpointFolder;
  if (const std::optional<fs::path> newest = newest_checkpoint(output_folder)) return *newest;
  throw InputError(folder.string(), 0,
                   "no checkpoint to resume from (none was written: the run was never started "
                   "here, or it stopped before the end of its first stage and before its first "
                   "timed checkpoint); run the case without --resume");
}

// --from-stage NAME: the end-of-stage checkpoint of the stage before NAME.
fs::path from_stage_checkpoint(const CaseDescription& description, const fs::path& output_folder,
                               const std::string& name) {
  const fs::path stages_file = fs::path(description.folder) / "stages.toml";
  std::string names;
  for (std::size_t k = 0; k < description.stages.size(); ++k) {
    const Stage& stage = description.stages[k];
    names += (names.empty() ? "'" : ", '") + stage.name + "'";
    if (stage.name != name) continue;
    if (k == 0)
      throw InputError(stages_file.string(), 0,
                       "stage '" + name +
                           "' is the first stage: no earlier stage ends where it begins; run "
                           "the case from its start (lituya solve CASE --force)");
    const fs::path file = end_of_stage_checkpoint(output_folder, description.stages[k - 1].name);
    if (!fs::exists(file))
      throw InputError(file.string(), 0,
                       "not found: --from-stage " + name + " starts from the end of stage '" +
                           description.stages[k - 1].name +
                           "', whose checkpoint this is; run the case until that stage has "
                           "ended first");
    return file;
  }
  throw InputError(
      stages_file.string(), 0,
      "--from-stage " + name + ": the case has no stage of that name (stages: " + names + ")");
}

// --from-stage: the output of the stages from `first` on belongs to the earlier run and would
// sit beside the new one's (a shorter new stage would leave stale frames); it is removed, with
// their checkpoints and the within-stage checkpoint.
void remove_output_from(const fs::path& output_folder, const CaseDescription& description,
                        std::size_t first) {
  fs::remove(within_stage_checkpoint(output_folder));
  for (std::size_t k = first; k < description.stages.size(); ++k) {
    const std::string& name = description.stages[k].name;
    fs::remove(end_of_stage_checkpoint(output_folder, name));
    for (const char* series : {"_points", "_liquid", "_grid"}) {
      const std::string prefix = name + series;
      fs::remove(output_folder / (prefix + ".pvd"));
      // <prefix>_NNNN.vtu
      auto is_frame = [&](const std::string& file) {
        const std::size_t head = prefix.size() + 1, tail = 4;
        if (file.size() <= head + tail || file.compare(0, head, prefix + "_") != 0 ||
            file.compare(file.size() - tail, tail, ".vtu") != 0)
          return false;
        return std::all_of(file.begin() + static_cast<std::ptrdiff_t>(head),
                           file.end() - static_cast<std::ptrdiff_t>(tail),
                           [](char c) { return c >= '0' && c <= '9'; });
      };
      std::vector<fs::path> frames;
      for (const auto& entry : fs::directory_iterator(output_folder))
        if (is_frame(entry.path().filename().string())) frames.push_back(entry.path());
      for (const fs::path& f : frames) fs::remove(f);
    }
  }
}

std::string files_hash(const CaseDescription& description, const fs::path& case_folder) {
  const fs::path folder = without_trailing_separator(case_folder);
  std::vector<fs::path> files = case_data_files(description, folder);
  files.push_back("stages.toml");
  std::sort(files.begin(), files.end());
  return hash_files(folder, files);
}

}  // namespace

std::vector<fs::path> case_data_files(const CaseDescription& description,
                                      const fs::path& case_folder) {
  const fs::path folder = without_trailing_separator(case_folder);
  std::vector<fs::path> files;
  for (const std::string& file : {description.geometry_file, description.points_file,
                                  description.materials_file, description.liquid_points_file}) {
    if (file.empty()) continue;
    const fs::path relative = fs::path(file).lexically_normal().lexically_relative(folder);
    files.push_back(relative.empty() ? fs::path(file) : relative);
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

std::string case_files_hash(const fs::path& case_folder) {
  return files_hash(read_case(case_folder.string()), case_folder);
}

std::vector<StageReport> solve_case(const fs::path& case_folder, const SolveOptions& options) {
  const CaseDescription description = read_case(case_folder.string());
  const fs::path output_folder =
      options.output_folder.empty() ? case_folder / "output" : options.output_folder;
  Provenance provenance;
  provenance.case_hash = files_hash(description, case_folder);
  Start start;
  start.inputs_hashes = stage_inputs_hashes(case_folder);
  if (options.resume || !options.from_stage.empty()) {
    // Everything is checked before anything in the output folder is touched.
    start.checkpoint = options.resume
                           ? resume_checkpoint(output_folder)
                           : from_stage_checkpoint(description, output_folder, options.from_stage);
    start.header = read_checkpoint_header(*start.checkpoint);
    const std::size_t stage = static_cast<std::size_t>(start.header.stage);
    if (start.header.dimension != description.dimension || stage > description.stages.size() ||
        (start.header.within_stage && stage >= description.stages.size()))
      throw InputError(start.checkpoint->string(), 0,
                       "the checkpoint does not fit this case (a " +
                           std::to_string(start.header.dimension) + "D state at stage " +
                           std::to_string(stage) + "; the case is " +
                           std::to_string(description.dimension) + "D with " +
                           std::to_string(description.stages.size()) + " stages)");
    if (options.resume)
      check_checkpoint(*start.checkpoint, start.header, provenance.case_hash, true);
    else
      check_checkpoint(*start.checkpoint, start.header, start.inputs_hashes.at(stage), false);
    provenance.started = start.header.started;
    provenance.resumed = utc_now_iso8601();
    provenance.resumed_from = start.checkpoint->lexically_relative(output_folder).generic_string() +
                              " (" + describe(start.header, description.stages) + ")";
    if (!options.from_stage.empty()) remove_output_from(output_folder, description, stage);
  } else {
    prepare_output_folder(output_folder, options.overwrite);  // refuses without --force
    set_aside_earlier_run(output_folder, options.keep_previous_output);
  }
  fs::create_directories(output_folder);
  // A resumed run goes on with the log of the run it continues.
  std::ofstream log(output_folder / "log.txt", start.checkpoint ? std::ios::app : std::ios::trunc);
  if (start.checkpoint)
    log << version_line() << ", resumed " << provenance.resumed << " from "
        << provenance.resumed_from << ", case " << case_folder.string() << " (case files "
        << provenance.case_hash << ")\n"
        << std::flush;
  else
    log << version_line() << ", started " << provenance.started << ", case " << case_folder.string()
        << " (case files " << provenance.case_hash << ")\n"
        << std::flush;
  Summary summary(output_folder / kSummaryFile, provenance, options.threads);
  if (description.dimension == 2)
    return run<2>(description, options, output_folder, log, summary, provenance, start);
  return run<3>(description, options, output_folder, log, summary, provenance, start);
}

std::optional<std::string> incomplete_run_problem(const fs::path& case_folder) {
  if (!fs::is_directory(case_folder))
    throw InputError(case_folder.string(), 0, "not found or not a folder; give a case folder");
  if (!fs::exists(case_folder / "stages.toml"))
    throw InputError(case_folder.string(), 0,
                     "not a case folder (it has no stages.toml); give the folder `lituya pre` "
                     "wrote");
  const fs::path file = case_folder / "output" / kSummaryFile;
  if (!fs::exists(file))
    return file.string() +
           " not found: the case has not been solved, or its solve was killed before it "
           "started";
  toml::table t;
  try {
    t = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    return file.string() + " cannot be read (" + std::string(e.description()) +
           "); the run may have been killed";
  }
  if (t["completed"].value_or(false)) return std::nullopt;
  const std::string state = t["state"].value_or(std::string("failed"));
  std::string reason = t["reason"].value_or(t["error"].value_or(std::string()));
  if (state == "running")
    reason = "it was killed or is still running (the summary was not updated since)";
  return file.string() + ": the run did not complete (state \"" + state + "\"" +
         (reason.empty() ? "" : ": " + reason) + ")";
}

}  // namespace lituya::solver
