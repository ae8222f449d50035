#include "lituya/solver/solve.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

#include <toml++/toml.h>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/content_hash.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/common/output_folder.hpp"
#include "lituya/common/provenance.hpp"
#include "lituya/common/stop_request.hpp"
#include "lituya/solver/case_loader.hpp"
#include "lituya/solver/output_writer.hpp"

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

template <int dim>
std::vector<StageReport> run(const CaseDescription& description, const SolveOptions& options,
                             const fs::path& output_folder, std::ostream& log, Summary& summary) {
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
  try {
    LoadedCase<dim> loaded = load_case<dim>(description);
    const std::size_t n_points = loaded.points.size() + loaded.liquid.size();
    const std::size_t n_liquid = loaded.liquid.size();
    Simulation<dim> simulation(description, std::move(loaded.mesh), std::move(loaded.points),
                               std::move(loaded.constraints), std::move(loaded.liquid));
    simulation.set_threads(options.threads);
    simulation.set_progress_stream(options.progress);
    summary.set_points(n_points);
    summary.write("running", reports);
    OutputWriter<dim> writer(output_folder, description.output);
    // The output callback is where the state is whole and just written: a stop asked for by
    // SIGINT/SIGTERM ends the run here, with that state as the last one in the series.
    auto on_output = [&](const Stage& stage, double t, int index) {
      writer.write(simulation, stage, t, index);
      if (const int signal = stop_signal()) {
        std::ostringstream where;
        where << "in stage '" << stage.name << "' at t = " << std::setprecision(6) << t << " s";
        stop_where = where.str();
        throw RunStopped(signal, stop_message(signal));
      }
    };
    note("Lituya solve: " + std::to_string(dim) + "D, " + std::to_string(n_points) + " points (" +
         std::to_string(n_liquid) + " liquid), " + std::to_string(simulation.mesh().cell_count()) +
         " cells, " + std::to_string(options.threads) + " thread(s)");
    note(simulation.transfer_damping().description);
    for (const Stage& stage : description.stages) {
      if (const int signal = stop_signal()) throw RunStopped(signal, stop_message(signal));
      reports.push_back(simulation.run_stage(as_run(stage), on_output));
      note(describe(reports.back(), n_points));
      summary.write("running", reports);
      stop_where = "after stage '" + stage.name + "'";
    }
  } catch (const RunStopped& e) {
    note(std::string("STOPPED: ") + e.what() + "; the state at that time is the last output");
    note("The output written up to then is kept in " + output_folder.string());
    summary.write("stopped", reports, e.what());
    throw;
  } catch (const RunError& e) {
    note(std::string("ERROR: ") + e.what());
    note("The output written before the failure is kept in " + output_folder.string());
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

std::string files_hash(const CaseDescription& description, const fs::path& case_folder) {
  const fs::path folder = without_trailing_separator(case_folder);
  std::vector<fs::path> files = {"stages.toml"};
  for (const std::string& file : {description.geometry_file, description.points_file,
                                  description.materials_file, description.liquid_points_file}) {
    if (file.empty()) continue;
    const fs::path relative = fs::path(file).lexically_normal().lexically_relative(folder);
    files.push_back(relative.empty() ? fs::path(file) : relative);
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return hash_files(folder, files);
}

}  // namespace

std::string case_files_hash(const fs::path& case_folder) {
  return files_hash(read_case(case_folder.string()), case_folder);
}

std::vector<StageReport> solve_case(const fs::path& case_folder, const SolveOptions& options) {
  const CaseDescription description = read_case(case_folder.string());
  const fs::path output_folder =
      options.output_folder.empty() ? case_folder / "output" : options.output_folder;
  prepare_output_folder(output_folder, options.overwrite);  // refuses without --force
  Provenance provenance;
  provenance.case_hash = files_hash(description, case_folder);
  set_aside_earlier_run(output_folder, options.keep_previous_output);
  fs::create_directories(output_folder);
  std::ofstream log(output_folder / "log.txt");
  log << version_line() << ", started " << provenance.started << ", case " << case_folder.string()
      << " (case files " << provenance.case_hash << ")\n"
      << std::flush;
  Summary summary(output_folder / kSummaryFile, provenance, options.threads);
  if (description.dimension == 2) return run<2>(description, options, output_folder, log, summary);
  return run<3>(description, options, output_folder, log, summary);
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
