// lituya: pre | solve | post | run | verify | sweep
// Every user error ends with a message naming the file and line (exit code 1); a run that
// goes unstable ends with a diagnostic naming the step, point and field (exit code 2). A sweep
// records failed runs and goes on; it ends with exit code 5 when any run failed.
#include <unistd.h>

#include <boost/program_options.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "lituya/common/input_error.hpp"
#include "lituya/post/postprocess.hpp"
#include "lituya/pre/preprocess.hpp"
#include "lituya/solver/solve.hpp"
#include "lituya/sweep/definition.hpp"
#include "lituya/sweep/sweep.hpp"
#include "lituya/verify/runner.hpp"

namespace po = boost::program_options;
namespace fs = std::filesystem;

namespace {

const char* kUsage =
    R"(Lituya: MPM for granular landslides (dry and saturated flows, free water, surge waves)

usage:
  lituya pre    SCENE.toml [-o CASE] [--force]     mesh the scene, seed points, write the case
  lituya solve  CASE [--threads N] [--force]       run the case's stages, write CASE/output
  lituya post   CASE [--force]                     runout, profiles, wall height -> CASE/post
  lituya run    SCENE.toml [-o CASE] [--threads N] [--force]   pre + solve + post
  lituya verify [--full] [-o REPORT] [--threads N] [--case NAME] [--force]
                                                   run the verification cases, write a report
  lituya sweep  SCENE.toml --parameter KEY --values V1,V2,... [--measure M,...] [-o DIR]
                [--threads N] [--force] [--dry-run]
                                                   run the scene once per value of KEY, then
                                                   tabulate and plot the measures against it
  lituya sweep  SWEEP.toml [--measure M,...] [-o DIR] [--threads N] [--force] [--dry-run]
                                                   the same, defined in a sweep file

CASE defaults to the folder 'case' next to SCENE.toml. Nothing is overwritten unless --force
is given. File formats: manuals/file-formats.md; user manual: manuals/user-manual.md.

sweep: KEY is a dotted path to one value of the scene, e.g. material.beads.friction_angle,
stage.release.courant, mesh.cell_size ([[...]] entries by name or group). A value may be a
range START:STOP:STEP; write --values=-5,0,5 when the first value is negative. Measures:
gauge_first_crest[:GAUGE], gauge_max[:GAUGE], leading_wave_max, front_travel_final,
front_travel_max, wall_height_final, wall_height_max (default: gauge_first_crest at every
gauge, else front_travel_final). DIR defaults to sweep_<KEY> next to the scene (for a sweep
file: its name without .toml). --dry-run checks every scene copy and measure and lists the
runs without running them. Exit code 5: at least one run of the sweep failed (the table
marks it; the others are complete).
)";

struct Options {
  std::string command;
  std::string input;
  std::string output;
  int threads = 1;
  bool force = false;
  bool full = false;
  std::vector<std::string> cases;
  std::string parameter;              // sweep
  std::string values;                 // sweep
  std::vector<std::string> measures;  // sweep
  bool dry_run = false;               // sweep
};

Options parse(int argc, char** argv) {
  Options o;
  po::options_description named("options");
  named.add_options()("help,h", "show usage")("output,o", po::value(&o.output), "output folder")(
      "threads,t", po::value(&o.threads)->default_value(1), "OpenMP threads")(
      "force,f", po::bool_switch(&o.force), "overwrite existing output")(
      "full", po::bool_switch(&o.full), "verify: run the full variants")(
      "case", po::value(&o.cases)->composing(), "verify: run only this case (repeatable)")(
      "parameter,p", po::value(&o.parameter), "sweep: the scene key to vary")(
      "values", po::value(&o.values), "sweep: its values, V1,V2,... or START:STOP:STEP")(
      "measure,m", po::value(&o.measures)->composing(), "sweep: what to plot (repeatable)")(
      "dry-run", po::bool_switch(&o.dry_run), "sweep: check and show the runs, run nothing")(
      "command", po::value(&o.command), "")("input", po::value(&o.input), "");
  po::positional_options_description positional;
  positional.add("command", 1).add("input", 1);
  po::variables_map vm;
  po::store(po::command_line_parser(argc, argv).options(named).positional(positional).run(), vm);
  po::notify(vm);
  if (vm.count("help") || o.command.empty()) {
    std::cout << kUsage;
    std::exit(o.command.empty() && !vm.count("help") ? 1 : 0);
  }
  if (o.threads < 1) throw po::error("--threads must be at least 1");
  return o;
}

fs::path default_case(const std::string& scene) {
  return fs::path(scene).parent_path() / "case";
}

void require_input(const Options& o, const char* what) {
  if (o.input.empty()) throw po::error(std::string("'lituya ") + o.command + "' needs " + what);
}

void run_post(const fs::path& case_folder, bool force) {
  if (!fs::exists(case_folder / "post.toml")) {
    std::cout << "post: skipped (the scene has no [post] table)\n";
    return;
  }
  lituya::post::postprocess(case_folder, case_folder / "post", force);
  std::cout << "post: CSV tables and PNG plots in " << (case_folder / "post").string() << "\n";
}

void run_solve(const fs::path& case_folder, const Options& o) {
  lituya::solver::SolveOptions options;
  options.threads = o.threads;
  options.overwrite = o.force;
  options.progress = &std::cerr;
  lituya::solver::solve_case(case_folder, options);
  std::cout << "solve: VTU series in " << (case_folder / "output").string()
            << " (open the .pvd files in ParaView)\n";
}

// Exit code of a sweep in which at least one run failed (the others are complete).
constexpr int kSweepRunFailed = 5;

int run_sweep(const Options& o) {
  lituya::sweep::SweepDefinition definition;
  if (lituya::sweep::is_sweep_file(o.input)) {
    if (!o.parameter.empty() || !o.values.empty())
      throw po::error("give --parameter and --values in the sweep file " + o.input +
                      " or on the command line with a scene, not both");
    definition = lituya::sweep::read_sweep_file(o.input);
  } else {
    if (o.parameter.empty() || o.values.empty())
      throw po::error("'lituya sweep SCENE.toml' needs --parameter KEY and --values V1,V2,...");
    definition.scene = o.input;
    definition.parameter = o.parameter;
    definition.values = lituya::sweep::parse_value_list(o.values);
  }
  if (!o.measures.empty()) {
    definition.measures.clear();
    for (const std::string& m : o.measures)
      for (const std::string& item : lituya::sweep::split_list(m))
        definition.measures.push_back(item);
  }
  if (!o.output.empty()) definition.output = o.output;
  lituya::sweep::SweepOptions options;
  options.threads = o.threads;
  options.overwrite = o.force;
  options.progress = &std::cerr;
  options.progress_is_terminal = isatty(fileno(stderr));
  options.report = &std::cout;
  options.dry_run = o.dry_run;
  const lituya::sweep::SweepResult result = lituya::sweep::run_sweep(definition, options);
  return result.all_ok() ? 0 : kSweepRunFailed;
}

void run_pre(const fs::path& scene, const fs::path& case_folder, bool force) {
  auto s = lituya::pre::preprocess(scene, case_folder, force);
  std::cout << "pre: " << s.dimension << "D case with " << s.nodes << " nodes, " << s.cells
            << " cells, " << s.points << " material points in " << case_folder.string() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    if (o.command == "pre") {
      require_input(o, "a scene file");
      run_pre(o.input, o.output.empty() ? default_case(o.input) : fs::path(o.output), o.force);
    } else if (o.command == "solve") {
      require_input(o, "a case folder");
      run_solve(o.input, o);
    } else if (o.command == "post") {
      require_input(o, "a case folder");
      run_post(o.input, o.force);
    } else if (o.command == "run") {
      require_input(o, "a scene file");
      const fs::path case_folder = o.output.empty() ? default_case(o.input) : fs::path(o.output);
      run_pre(o.input, case_folder, o.force);
      run_solve(case_folder, o);
      run_post(case_folder, o.force);
    } else if (o.command == "verify") {
      lituya::verify::RunnerOptions options;
      options.full = o.full;
      options.threads = o.threads;
      options.overwrite = o.force;
      options.only = o.cases;
      options.report_folder =
          o.output.empty() ? fs::path("verification-report") : fs::path(o.output);
      const bool all_passed = lituya::verify::run_verification(options);
      return all_passed ? 0 : 4;
    } else if (o.command == "sweep") {
      require_input(o, "a scene file (with --parameter and --values) or a sweep file");
      return run_sweep(o);
    } else {
      std::cerr << "lituya: unknown command '" << o.command << "'\n\n" << kUsage;
      return 1;
    }
    return 0;
  } catch (const lituya::InputError& e) {
    std::cerr << "\nlituya: input error: " << e.what() << "\n";
    return 1;
  } catch (const lituya::RunError& e) {
    std::cerr << "\nlituya: run stopped: " << e.what() << "\n";
    return 2;
  } catch (const po::error& e) {
    std::cerr << "lituya: " << e.what() << "\n\n" << kUsage;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "\nlituya: error: " << e.what() << "\n";
    return 3;
  }
}
