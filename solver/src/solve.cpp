#include "lituya/solver/solve.hpp"

#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

#include <toml++/toml.h>

#include "lituya/common/input_error.hpp"
#include "lituya/common/output_folder.hpp"
#include "lituya/solver/case_loader.hpp"
#include "lituya/solver/output_writer.hpp"

namespace lituya::solver {

namespace {

std::string describe(const StageReport& r, std::size_t n_points) {
  std::ostringstream s;
  s << std::setprecision(4) << "stage '" << r.stage << "': " << r.steps << " steps, "
    << r.simulated_time << " s simulated in " << r.wall_time << " s wall, "
    << r.point_steps_per_second / 1e6 << " M point-steps/s (" << n_points
    << " points), peak memory " << static_cast<double>(r.peak_memory) / (1024.0 * 1024.0)
    << " MiB; stopped: " << r.stop_reason;
  return s.str();
}

void write_summary(const std::filesystem::path& file, const std::vector<StageReport>& reports,
                   std::size_t n_points, int threads, const std::string& error) {
  toml::array stages;
  for (const StageReport& r : reports)
    stages.push_back(toml::table{{"name", r.stage},
                                 {"steps", r.steps},
                                 {"simulated_time", r.simulated_time},
                                 {"wall_time", r.wall_time},
                                 {"point_steps_per_second", r.point_steps_per_second},
                                 {"peak_memory_bytes", static_cast<int64_t>(r.peak_memory)},
                                 {"stop_reason", r.stop_reason}});
  toml::table t{{"points", static_cast<int64_t>(n_points)},
                {"threads", threads},
                {"completed", error.empty()},
                {"stage", stages}};
  if (!error.empty()) t.insert("error", error);
  std::ofstream out(file);
  out << "format = \"lituya-summary\"\nversion = 1\n" << t << "\n";
}

template <int dim>
std::vector<StageReport> run(const CaseDescription& description, const SolveOptions& options,
                             const std::filesystem::path& output_folder, std::ostream& log) {
  LoadedCase<dim> loaded = load_case<dim>(description);
  const std::size_t n_points = loaded.points.size() + loaded.liquid.size();
  const std::size_t n_liquid = loaded.liquid.size();
  Simulation<dim> simulation(description, std::move(loaded.mesh), std::move(loaded.points),
                             std::move(loaded.constraints), std::move(loaded.liquid));
  simulation.set_threads(options.threads);
  simulation.set_progress_stream(options.progress);
  OutputWriter<dim> writer(output_folder, description.output);
  std::vector<StageReport> reports;
  auto on_output = [&](const Stage& stage, double t, int index) {
    writer.write(simulation, stage, t, index);
  };
  auto note = [&](const std::string& line) {
    log << line << "\n" << std::flush;
    if (options.progress) *options.progress << line << "\n" << std::flush;
  };
  note("Lituya solve: " + std::to_string(dim) + "D, " + std::to_string(n_points) + " points (" +
       std::to_string(n_liquid) + " liquid), " + std::to_string(simulation.mesh().cell_count()) +
       " cells, " + std::to_string(options.threads) + " thread(s)");
  note(simulation.transfer_damping().description);
  try {
    for (const Stage& stage : description.stages) {
      reports.push_back(simulation.run_stage(stage, on_output));
      note(describe(reports.back(), n_points));
    }
  } catch (const RunError& e) {
    note(std::string("ERROR: ") + e.what());
    note("The output written before the failure is kept in " + output_folder.string());
    write_summary(output_folder / "summary.toml", reports, n_points, options.threads, e.what());
    throw;
  }
  write_summary(output_folder / "summary.toml", reports, n_points, options.threads, "");
  return reports;
}

}  // namespace

std::vector<StageReport> solve_case(const std::filesystem::path& case_folder,
                                    const SolveOptions& options) {
  const CaseDescription description = read_case(case_folder.string());
  const std::filesystem::path output_folder =
      options.output_folder.empty() ? case_folder / "output" : options.output_folder;
  prepare_output_folder(output_folder, options.overwrite);
  std::ofstream log(output_folder / "log.txt");
  if (description.dimension == 2) return run<2>(description, options, output_folder, log);
  return run<3>(description, options, output_folder, log);
}

}  // namespace lituya::solver
