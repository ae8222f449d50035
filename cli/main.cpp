// lituya: pre | solve | post | run | verify | sweep
// Every user error ends with a message naming the file and line (exit code 1); a run that
// goes unstable ends with a diagnostic naming the step, point and field (exit code 2). A sweep
// records failed runs and goes on; it ends with exit code 5 when any run failed. SIGINT or
// SIGTERM during a solve stops it cleanly with exit code 130 or 143 (128 + the signal).
// `post` refuses a run that did not complete with exit code 6.
// A wrong command line is a usage error: a message and a hint naming the command's --help, on
// stderr, exit code 1. Each command accepts only its own options.
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <boost/program_options.hpp>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <streambuf>
#include <string>
#include <vector>

#include "lituya/common/input_error.hpp"
#include "lituya/common/provenance.hpp"
#include "lituya/common/stop_request.hpp"
#include "lituya/post/postprocess.hpp"
#include "lituya/pre/preprocess.hpp"
#include "lituya/solver/solve.hpp"
#include "lituya/sweep/definition.hpp"
#include "lituya/sweep/repeats.hpp"
#include "lituya/sweep/report.hpp"
#include "lituya/sweep/sweep.hpp"
#include "lituya/verify/runner.hpp"

namespace po = boost::program_options;
namespace fs = std::filesystem;

namespace {

const char* kUsage =
    R"(Lituya: MPM for granular landslides (dry and saturated flows, free water, surge waves)

usage:
  lituya pre    SCENE.toml [-o CASE] [--force] [--allow-large-mesh]
                                                   mesh the scene, seed points, write the case
  lituya solve  CASE [--threads N] [--force | --resume | --from-stage NAME]
                                                   run the case's stages, write CASE/output
  lituya post   CASE [--force] [--allow-incomplete]
                                                   runout, profiles, wall height -> CASE/post
  lituya run    SCENE.toml [-o CASE] [--threads N] [--force] [--allow-large-mesh]
                                                   pre + solve + post
  lituya verify [--full] [-o REPORT] [--threads N] [--case NAME] [--force]
                                                   run the verification cases, write a report
  lituya sweep  SCENE.toml --parameter KEY --values V1,V2,... [--measure M,...] [-o DIR]
                [--combine grid|zip] [--jobs N] [--threads N] [--force | --resume] [--dry-run]
                [--no-reuse]
                                                   run the scene once per value of KEY (or per
                                                   combination of several KEYs), then tabulate
                                                   and plot the measures against it
  lituya sweep  SWEEP.toml [--measure M,...] [-o DIR] [--jobs N] [--threads N]
                [--force | --resume] [--dry-run] [--no-reuse]
                                                   the same, defined in a sweep file
  lituya sweep  DIR [--merge DIR2 ...] [--sizes H1,H2,H3] [-o DIR3] [--force]
                                                   report finished sweeps again, their mesh
                                                   convergence from the sizes chosen
  lituya COMMAND --help                            the command's usage and options
  lituya --version                                 the version and the git commit built from

Every command also takes -q/--quiet (print errors only) and --verbose (also the version,
the threads, the time of each step and gmsh's own messages). --threads N defaults to
OMP_NUM_THREADS when it is set, else to the number of cores.

CASE defaults to the folder 'case' next to SCENE.toml. Nothing is overwritten unless --force
is given. File formats: manuals/file-formats.md; user manual: manuals/user-manual.md.
)";

const char* kSweepDetails =
    R"(KEY is a dotted path to one value of the scene, e.g. material.beads.friction_angle,
stage.release.courant, mesh.cell_size ([[...]] entries by name or group). A value may be a
range START:STOP:STEP; write --values=-5,0,5 when the first value is negative. Several keys:
repeat --parameter KEY --values ... per key; --combine grid (default) runs every
combination, --combine zip the i-th values of every key together. Measures:
gauge_first_crest[:GAUGE], gauge_first_wave_area[:GAUGE], gauge_max[:GAUGE],
leading_wave_max, front_travel_final, front_travel_max, mass_front_travel_final,
wall_height_final, wall_height_max, kinetic_energy_solid_max, kinetic_energy_liquid_max,
speed_solid_max, speed_liquid_max
(default: gauge_first_crest at every gauge, else front_travel_final). DIR defaults to
sweep_<KEY> next to the scene (several keys joined by '+'; for a sweep file: its name
without .toml). --dry-run checks every scene copy and measure and lists the runs without
running them. --jobs N runs N runs side by side, each in a process of its own with one
thread unless --threads says otherwise (the same results as one after another). --resume
continues a stopped sweep in DIR: a run whose scene copy is unchanged and whose solve
completed on the same case files is kept, not run again. A run whose first stages read the
same inputs as those of a run that finished (a key that only a later stage reads) starts
from that run's end-of-stage checkpoint instead of running them again, with the same results
to the last bit; --no-reuse runs every run whole. --repeats N makes each run N times with
the last stage's Courant number changed by 2e-4 of itself per repeat (a change far below
any truncation error) and reports each measure's mean and spread (repeats.csv): a setting's
effect, or a refinement step, is resolved only where it exceeds that spread; a sweep over
mesh.cell_size then extrapolates the means. --repeat-by mesh makes the repeats on other
meshes instead: repeat k sets [mesh] seed to one more than the last (gmsh then triangulates
the same geometry at the same cell size differently), so the spread includes what a
particular mesh does to a reading, which is often much more. Exit code 5: at least one run
of the sweep failed (the table marks it; the others are complete).

Given the folder DIR of a finished sweep instead, nothing is run: its runs, their repeats'
spread and its mesh convergence are reported again from DIR/sweep.json. --merge DIR2 adds
the runs of another sweep of the same keys (a finer size run on its own, say; repeatable);
the measures all of them have are reported. --sizes H1,H2,H3 makes the Richardson estimate
from those three cell sizes instead of the three finest. -o DIR3 also writes the merged
runs, repeats and mesh convergence there in a sweep's own tables, and for a sweep of the
cell size alone each measure against the cell size (convergence_<measure>.png).)";

const std::vector<std::string> kCommands = {"pre", "solve", "post", "run", "verify", "sweep"};

bool is_command(const std::string& name) {
  return std::find(kCommands.begin(), kCommands.end(), name) != kCommands.end();
}

// A wrong command line. `command` names the --help to point to ("" for the top level).
struct UsageError : std::runtime_error {
  UsageError(const std::string& command, const std::string& message)
      : std::runtime_error(message), command(command) {}
  std::string command;
};

std::string help_hint(const std::string& command) {
  return command.empty() ? "see 'lituya --help'" : "see 'lituya " + command + " --help'";
}

// The default of --threads. The solver sets its thread count explicitly on every loop, so
// OMP_NUM_THREADS would otherwise be ignored; honouring it lets a job scheduler's setting
// apply. omp_get_num_procs counts the cores this process may run on (taskset, cpusets), which
// std::thread::hardware_concurrency does not.
struct ThreadsDefault {
  int threads = 1;
  std::string source;  // for --verbose and --help
};

ThreadsDefault default_threads() {
  if (const char* env = std::getenv("OMP_NUM_THREADS")) {
    // OpenMP allows one number per nesting level ("4,2"); the solver's loops are one level.
    std::string text(env);
    text = text.substr(0, text.find(','));
    text.erase(0, text.find_first_not_of(" \t"));
    text.erase(text.find_last_not_of(" \t") + 1);
    int n = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (error == std::errc() && end == text.data() + text.size() && n > 0)
      return {n, "OMP_NUM_THREADS=" + std::string(env)};
  }
  const int cores = std::max(1, omp_get_num_procs());
  return {cores, std::to_string(cores) + (cores == 1 ? " core" : " cores")};
}

struct Options {
  std::string command;
  std::string input;
  std::string output;
  int threads = 1;
  std::string threads_source;
  bool force = false;
  bool full = false;
  bool quiet = false;
  bool verbose = false;
  std::vector<std::string> cases;
  std::vector<std::string> parameters;  // sweep, paired in order with `values`
  std::vector<std::string> values;      // sweep
  std::string combine = "grid";         // sweep
  int jobs = 1;                         // sweep
  std::vector<std::string> measures;    // sweep
  bool dry_run = false;                 // sweep
  bool no_reuse = false;                // sweep
  int repeats = 0;                      // sweep: 0 = as the sweep file says (default 1)
  std::string repeat_by;                // sweep: "courant" or "mesh"; empty: as the file says
  std::vector<std::string> merge;       // sweep report: more sweep folders
  std::string sizes;                    // sweep report: H1,H2,H3 of the Richardson estimate
  bool allow_incomplete = false;        // post
  bool allow_large_mesh = false;        // pre, run
  bool resume = false;                  // solve, sweep
  std::string from_stage;               // solve
};

// One command: its synopsis, what it does, and the only options it accepts.
struct Command {
  std::string name;
  std::string synopsis;
  std::string summary;
  std::string input;  // what the positional argument is; empty: the command takes none
  po::options_description options;
};

constexpr unsigned kLineLength = 100;

// The per-command option tables, bound to `o`. Each option is declared here once per command
// that accepts it, so a command's --help and what it accepts cannot disagree.
std::vector<Command> command_table(Options& o, const ThreadsDefault& threads) {
  const std::string threads_text =
      "OpenMP threads (default: OMP_NUM_THREADS when set, else the "
      "number of cores; here " +
      std::to_string(threads.threads) + ", from " + threads.source + ")";
  auto common = [&](po::options_description& d) {
    d.add_options()("help,h", "show this help")("quiet,q", po::bool_switch(&o.quiet),
                                                "print errors only")(
        "verbose", po::bool_switch(&o.verbose),
        "also print the version, the threads, the time of each step and gmsh's messages");
  };
  auto output = [&](po::options_description& d, const char* what) {
    d.add_options()("output,o", po::value(&o.output)->value_name("DIR"), what);
  };
  auto threads_option = [&](po::options_description& d) {
    d.add_options()("threads,t", po::value(&o.threads)->value_name("N"), threads_text.c_str());
  };
  auto force = [&](po::options_description& d, const char* what) {
    d.add_options()("force,f", po::bool_switch(&o.force), what);
  };
  // Without it, `pre` estimates the mesh before meshing and refuses one that needs more memory
  // than the machine has (a cell size typed far too small would otherwise exhaust it).
  auto allow_large_mesh = [&](po::options_description& d) {
    d.add_options()("allow-large-mesh", po::bool_switch(&o.allow_large_mesh),
                    "mesh even when the estimated memory exceeds what the machine has");
  };
  auto make = [](const char* name, const char* synopsis, const std::string& summary,
                 const char* input) {
    return Command{name, synopsis, summary, input,
                   po::options_description("options", kLineLength, kLineLength / 2)};
  };

  std::vector<Command> table;
  {
    Command c = make("pre", "lituya pre SCENE.toml [-o CASE] [--force] [--allow-large-mesh]",
                     "Mesh the scene with gmsh, seed the material points and write the case "
                     "folder.",
                     "a scene file");
    output(c.options, "the case folder (default: case/ next to the scene file)");
    force(c.options, "write into a case folder that already holds files");
    allow_large_mesh(c.options);
    common(c.options);
    table.push_back(std::move(c));
  }
  {
    Command c =
        make("solve", "lituya solve CASE [--threads N] [--force | --resume | --from-stage NAME]",
             "Run the case's stages and write the VTU series to CASE/output. Checkpoints go "
             "to\nCASE/output/checkpoints: at the end of each stage, every [solver] "
             "checkpoint_interval_minutes\nand when stopped by Ctrl-C or SIGTERM.",
             "a case folder");
    threads_option(c.options);
    force(c.options, "write into CASE/output when it already holds files");
    c.options.add_options()("resume", po::bool_switch(&o.resume),
                            "go on from the newest checkpoint in CASE/output")(
        "from-stage", po::value(&o.from_stage)->value_name("NAME"),
        "re-run stage NAME and the later ones from the end-of-stage checkpoint of the stage "
        "before it");
    common(c.options);
    table.push_back(std::move(c));
  }
  {
    Command c = make("post", "lituya post CASE [--force] [--allow-incomplete]",
                     "Measure runout, profiles, wall height, wave gauges and the leading wave; "
                     "write CSV tables and PNG plots to CASE/post.\nA run that did not complete "
                     "(CASE/output/summary.toml missing or completed = false) is\nrefused with "
                     "exit code 6 unless --allow-incomplete is given.",
                     "a case folder");
    force(c.options, "write into CASE/post when it already holds files");
    c.options.add_options()("allow-incomplete", po::bool_switch(&o.allow_incomplete),
                            "measure a run that was stopped, failed or killed");
    common(c.options);
    table.push_back(std::move(c));
  }
  {
    Command c = make("run",
                     "lituya run SCENE.toml [-o CASE] [--threads N] [--force] "
                     "[--allow-large-mesh]",
                     "pre + solve + post in one.", "a scene file");
    output(c.options, "the case folder (default: case/ next to the scene file)");
    threads_option(c.options);
    force(c.options, "write into folders that already hold files");
    allow_large_mesh(c.options);
    common(c.options);
    table.push_back(std::move(c));
  }
  {
    Command c = make("verify",
                     "lituya verify [--full] [-o REPORT] [--threads N] [--case NAME] "
                     "[--force]",
                     "Run the verification cases and write a report. Exit code 4: at least one "
                     "check failed.",
                     "");
    c.options.add_options()("full", po::bool_switch(&o.full),
                            "run the full variants instead of the quick (CI) ones")(
        "case", po::value(&o.cases)->composing()->value_name("NAME"),
        "run only this case (repeatable)");
    output(c.options, "the report folder (default: verification-report/)");
    threads_option(c.options);
    force(c.options, "write into a report folder that already holds files");
    common(c.options);
    table.push_back(std::move(c));
  }
  {
    Command c = make(
        "sweep",
        "lituya sweep SCENE.toml --parameter KEY --values V1,V2,... [--measure M,...] "
        "[-o DIR]\n              [--combine grid|zip] [--jobs N] [--threads N] "
        "[--force | --resume] [--dry-run]\n              [--no-reuse] [--repeats N [--repeat-by "
        "courant|mesh]]\n"
        "       lituya sweep SWEEP.toml [--measure M,...] [-o DIR] [--jobs N] "
        "[--threads N] [--force | --resume]\n              [--dry-run] [--no-reuse] "
        "[--repeats N [--repeat-by courant|mesh]]\n"
        "       lituya sweep DIR [--merge DIR2 ...] [--sizes H1,H2,H3] [-o DIR3] "
        "[--force]",
        std::string("Run the scene once per value of KEY, or per combination of the "
                    "values of several\nKEYs (pre + solve + post), then tabulate and "
                    "plot the measures against it.\n\n") +
            kSweepDetails,
        "a scene file (with --parameter and --values), a sweep file, or the folder "
        "of a finished sweep");
    c.options.add_options()("parameter,p", po::value(&o.parameters)->composing()->value_name("KEY"),
                            "the scene key to vary (repeatable, one --values each)")(
        "values", po::value(&o.values)->composing()->value_name("V1,V2,..."),
        "its values, V1,V2,... or START:STOP:STEP")(
        "combine", po::value(&o.combine)->value_name("grid|zip"),
        "several keys: every combination (grid, the default) or the i-th values together (zip)")(
        "jobs,j", po::value(&o.jobs)->value_name("N"),
        "runs side by side, each in a process of its own (default 1)")(
        "resume", po::bool_switch(&o.resume),
        "continue the sweep in its folder, keeping the runs that finished")(
        "measure,m", po::value(&o.measures)->composing()->value_name("M,..."),
        "what to tabulate and plot (repeatable)")("dry-run", po::bool_switch(&o.dry_run),
                                                  "check and list the runs, run nothing")(
        "no-reuse", po::bool_switch(&o.no_reuse),
        "run every run whole, even the first stages it shares with another run")(
        "repeats", po::value(&o.repeats)->value_name("N"),
        "make each run N times (2-20), each repeat on another mesh or with the last stage's "
        "Courant number changed by 2e-4 of itself (--repeat-by), and report each measure's "
        "mean and spread")(
        "repeat-by", po::value(&o.repeat_by)->value_name("WHAT"),
        "what a repeat changes: mesh (another gmsh seed per repeat; the default when "
        "mesh.cell_size is swept) or courant (the default otherwise)")(
        "merge", po::value(&o.merge)->composing()->value_name("DIR2"),
        "with a sweep folder: add the runs of another finished sweep (repeatable)")(
        "sizes", po::value(&o.sizes)->value_name("H1,H2,H3"),
        "with a sweep folder: the three cell sizes of the Richardson estimate (default: the "
        "three finest)");
    output(c.options,
           "the sweep folder (default: sweep_<KEY>/ next to the scene file); with a sweep "
           "folder: a folder for the merged tables and the convergence plots");
    threads_option(c.options);
    force(c.options, "write into a sweep folder that already holds files and run every run again");
    common(c.options);
    table.push_back(std::move(c));
  }
  return table;
}

// The command word, found by parsing with every option of every command so that option values
// are told apart from it wherever the options stand (`lituya -o post pre scene.toml` is `pre`).
// When even that parse fails, the first word that names a command, for the hint only.
std::string find_command(int argc, char** argv, const std::vector<Command>& table) {
  po::options_description all;
  for (const Command& c : table)
    for (const auto& option : c.options.options())
      if (!all.find_nothrow(option->long_name(), false)) all.add(option);
  all.add_options()("version", "")("command", po::value<std::string>(), "")(
      "rest", po::value<std::vector<std::string>>(), "");
  po::positional_options_description positional;
  positional.add("command", 1).add("rest", -1);
  try {
    const po::parsed_options parsed = po::command_line_parser(argc, argv)
                                          .options(all)
                                          .positional(positional)
                                          .allow_unregistered()
                                          .run();
    for (const po::option& option : parsed.options)
      if (option.string_key == "command" && !option.value.empty()) return option.value.front();
    return "";
  } catch (const po::error&) {
    for (int i = 1; i < argc; ++i)
      if (is_command(argv[i])) return argv[i];
    return "";
  }
}

void print_help(std::ostream& out, const Command& c) {
  out << "usage: " << c.synopsis << "\n\n" << c.summary << "\n\n" << c.options;
}

// Parses the command line into `o`. Returns -1 to go on with o.command, or the exit code when
// the command line only asked for help or the version.
int parse(int argc, char** argv, Options& o) {
  const ThreadsDefault threads = default_threads();
  o.threads = threads.threads;
  o.threads_source = threads.source;
  const std::vector<Command> table = command_table(o, threads);
  o.command = find_command(argc, argv, table);

  if (o.command.empty()) {
    po::options_description top;
    top.add_options()("help,h", "")("version", "")("quiet,q", "")("verbose", "");
    po::variables_map vm;
    try {
      po::store(po::command_line_parser(argc, argv).options(top).run(), vm);
    } catch (const po::error& e) {
      throw UsageError("", e.what());
    }
    if (vm.count("help")) {
      std::cout << kUsage;
      return 0;
    }
    if (vm.count("version")) {
      std::cout << lituya::version_line() << "\n";
      return 0;
    }
    if (argc > 1) throw UsageError("", "no command given");
    std::cerr << kUsage;
    return 1;
  }
  const auto command = std::find_if(table.begin(), table.end(),
                                    [&](const Command& c) { return c.name == o.command; });
  if (command == table.end()) throw UsageError("", "unknown command '" + o.command + "'");

  po::options_description accepted = command->options;
  accepted.add_options()("command", po::value<std::string>(), "")("input", po::value(&o.input), "");
  po::positional_options_description positional;
  positional.add("command", 1).add("input", 1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(argc, argv).options(accepted).positional(positional).run(),
              vm);
    po::notify(vm);
  } catch (const po::unknown_option& e) {
    // An option of another command gets a message that says so, not just "unrecognised".
    // Long names are looked up without their "--", short ones with their "-" ("-t4" is the
    // short option "-t" with its value attached).
    const std::string name = e.get_option_name();
    const std::string key = name.rfind("--", 0) == 0 ? name.substr(2) : name.substr(0, 2);
    std::string owners;
    for (const Command& c : table)
      if (c.options.find_nothrow(key, /*approx=*/false, /*long_ignore_case=*/false,
                                 /*short_ignore_case=*/false))
        owners += (owners.empty() ? "" : ", ") + c.name;
    if (owners.empty()) throw UsageError(o.command, e.what());
    throw UsageError(o.command, "'lituya " + o.command + "' does not take " +
                                    (name.rfind("--", 0) == 0 ? name : key) +
                                    " (it is an option of: " + owners + ")");
  } catch (const po::too_many_positional_options_error&) {
    throw UsageError(o.command,
                     command->input.empty()
                         ? "'lituya " + o.command + "' takes no argument"
                         : "'lituya " + o.command + "' takes one argument, " + command->input);
  } catch (const po::error& e) {
    throw UsageError(o.command, e.what());
  }
  if (vm.count("help")) {
    print_help(std::cout, *command);
    return 0;
  }
  if (o.quiet && o.verbose) throw UsageError(o.command, "--quiet and --verbose exclude each other");
  if (o.threads < 1) throw UsageError(o.command, "--threads must be at least 1");
  if (o.jobs < 1) throw UsageError(o.command, "--jobs must be at least 1");
  if (o.combine != "grid" && o.combine != "zip")
    throw UsageError(o.command, "--combine takes grid or zip, not '" + o.combine + "'");
  if (o.resume + o.force + vm.count("from-stage") > 1)
    throw UsageError(o.command, o.command == "solve"
                                    ? "--force, --resume and --from-stage exclude each other"
                                    : "--force and --resume exclude each other");
  if (vm.count("from-stage") && o.from_stage.empty())
    throw UsageError(o.command, "--from-stage needs the name of a stage");
  if (vm.count("threads")) o.threads_source = "--threads";
  // Runs side by side are single-thread runs unless --threads says otherwise: N runs of one
  // thread fill N cores without the runs competing for them.
  if (o.jobs > 1 && !vm.count("threads")) {
    o.threads = 1;
    o.threads_source = "--jobs " + std::to_string(o.jobs) + ": one per run";
  }
  if (command->input.empty() && !o.input.empty())
    throw UsageError(o.command,
                     "'lituya " + o.command + "' takes no argument (got '" + o.input + "')");
  if (!command->input.empty() && o.input.empty())
    throw UsageError(o.command, "'lituya " + o.command + "' needs " + command->input);
  return -1;
}

// Where --quiet sends everything but errors.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// --quiet silences std::cout and std::cerr as a whole (the libraries print summaries and
// warnings there); errors still reach the terminal through errors(), which keeps stderr's
// own buffer. The streams are restored when main returns, before the buffer goes away.
class QuietScope {
 public:
  QuietScope() : errors_(std::cerr.rdbuf()) {}
  ~QuietScope() {
    if (!active_) return;
    std::cout.rdbuf(cout_);
    std::cerr.rdbuf(cerr_);
    std::clog.rdbuf(clog_);
  }
  QuietScope(const QuietScope&) = delete;
  QuietScope& operator=(const QuietScope&) = delete;

  void enable() {
    std::cout.flush();
    cout_ = std::cout.rdbuf(&null_);
    cerr_ = std::cerr.rdbuf(&null_);
    clog_ = std::clog.rdbuf(&null_);
    active_ = true;
  }
  std::ostream& errors() { return errors_; }

 private:
  NullBuffer null_;
  std::ostream errors_;
  bool active_ = false;
  std::streambuf* cout_ = nullptr;
  std::streambuf* cerr_ = nullptr;
  std::streambuf* clog_ = nullptr;
};

// --verbose: how long each step took.
class StepTimer {
 public:
  StepTimer(const Options& o, const char* step) : verbose_(o.verbose), step_(step) {}
  ~StepTimer() {
    if (!verbose_) return;
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start_;
    const auto precision = std::cerr.precision(3);
    std::cerr << "lituya: " << step_ << " took " << wall.count() << " s\n";
    std::cerr.precision(precision);
  }
  StepTimer(const StepTimer&) = delete;
  StepTimer& operator=(const StepTimer&) = delete;

 private:
  bool verbose_;
  const char* step_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The progress line of a solve or sweep: none with --quiet.
std::ostream* progress_stream(const Options& o) {
  return o.quiet ? nullptr : &std::cerr;
}

fs::path default_case(const std::string& scene) {
  return fs::path(scene).parent_path() / "case";
}

// Exit code of `lituya post` on a run that did not complete (nothing was measured).
constexpr int kIncompleteRun = 6;

// Measuring a run that stopped, failed or was killed would give numbers that look like
// results of the whole scene; `post` says so and stops unless the user asks to go on.
struct IncompleteRun : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void run_post(const fs::path& case_folder, const Options& o) {
  StepTimer timer(o, "post");
  // Throws InputError (exit 1) when the folder is not a case.
  if (const auto problem = lituya::solver::incomplete_run_problem(case_folder)) {
    if (!o.allow_incomplete)
      throw IncompleteRun(*problem +
                          ". Nothing was measured; pass --allow-incomplete to "
                          "measure the output there is");
    std::cerr << "lituya: warning: " << *problem << "; measuring the output there is\n";
  }
  if (!fs::exists(case_folder / "post.toml")) {
    // Nothing to measure, but the probes and stage histories the run wrote are still plotted.
    const auto plots = lituya::post::plot_run_histories(case_folder, case_folder / "post", o.force);
    if (plots.files.empty())
      std::cout << "post: skipped (the scene has no [post] table)\n";
    else
      std::cout << "post: no [post] table; probe and stage history plots in "
                << (case_folder / "post").string() << "\n";
    return;
  }
  lituya::post::postprocess(case_folder, case_folder / "post", o.force);
  std::cout << "post: CSV tables and PNG plots in " << (case_folder / "post").string() << "\n";
}

void run_solve(const fs::path& case_folder, const Options& o) {
  StepTimer timer(o, "solve");
  lituya::solver::SolveOptions options;
  options.threads = o.threads;
  options.overwrite = o.force;
  options.resume = o.resume;
  options.from_stage = o.from_stage;
  options.progress = progress_stream(o);
  // SIGINT/SIGTERM during the solve stop it cleanly (RunStopped); outside it they end the
  // process as usual, since nothing else would notice the request.
  lituya::StopSignalScope stop_on_signal;
  lituya::solver::solve_case(case_folder, options);
  std::cout << "solve: VTU series in " << (case_folder / "output").string()
            << " (open the .pvd files in ParaView)\n";
}

// Exit code of a sweep in which at least one run failed (the others are complete).
constexpr int kSweepRunFailed = 5;
// Exit code of `lituya verify` when at least one check failed.
constexpr int kVerifyFailed = 4;

// `lituya sweep DIR ...`: finished sweeps reported again (sweep/report.hpp).
int report_sweeps(const Options& o) {
  if (!o.parameters.empty() || !o.values.empty() || o.combine != "grid" || !o.measures.empty() ||
      o.repeats != 0 || !o.repeat_by.empty() || o.resume || o.dry_run || o.no_reuse || o.jobs != 1)
    throw UsageError("sweep", o.input +
                                  " is a sweep folder: it is reported, not run, and takes only "
                                  "--merge, --sizes, -o and --force");
  std::vector<double> sizes;
  if (!o.sizes.empty()) {
    for (const std::string& item : lituya::sweep::split_list(o.sizes)) {
      double h = 0;
      const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), h);
      if (error != std::errc() || end != item.data() + item.size() || !(h > 0) || !std::isfinite(h))
        throw UsageError("sweep",
                         "--sizes takes three positive cell sizes in metres, not '" + item + "'");
      sizes.push_back(h);
    }
    std::vector<double> sorted = sizes;
    std::sort(sorted.begin(), sorted.end());
    if (sorted.size() != 3 || sorted[0] == sorted[1] || sorted[1] == sorted[2])
      throw UsageError("sweep",
                       "--sizes takes three distinct cell sizes, H1,H2,H3 (got '" + o.sizes + "')");
  }
  std::vector<fs::path> folders{o.input};
  folders.insert(folders.end(), o.merge.begin(), o.merge.end());
  const lituya::sweep::MergedSweep merged = lituya::sweep::merge_sweeps(folders);
  std::vector<lituya::sweep::MeshConvergenceRow> convergence;
  std::cout << lituya::sweep::format_report(merged, sizes, &convergence);
  if (!o.output.empty()) {
    const lituya::sweep::ReportFiles files =
        lituya::sweep::write_report(o.output, merged, convergence, o.force);
    std::cout << "table: " << files.runs.string() << "\n";
    if (!files.repeats.empty()) std::cout << "repeats: " << files.repeats.string() << "\n";
    if (!files.convergence.empty())
      std::cout << "mesh convergence: " << files.convergence.string() << "\n";
    for (const fs::path& plot : files.plots) std::cout << "plot: " << plot.string() << "\n";
  }
  return 0;
}

int run_sweep(const Options& o, std::ostream& errors) {
  StepTimer timer(o, "sweep");
  if (fs::is_directory(o.input)) return report_sweeps(o);
  if (!o.merge.empty() || !o.sizes.empty())
    throw UsageError("sweep",
                     "--merge and --sizes report finished sweeps: give a sweep folder, "
                     "not " +
                         o.input);
  lituya::sweep::SweepDefinition definition;
  if (lituya::sweep::is_sweep_file(o.input)) {
    if (!o.parameters.empty() || !o.values.empty() || o.combine != "grid")
      throw UsageError("sweep", "give --parameter, --values and --combine in the sweep file " +
                                    o.input + " or on the command line with a scene, not both");
    definition = lituya::sweep::read_sweep_file(o.input);
  } else {
    if (o.parameters.empty() || o.values.empty())
      throw UsageError("sweep",
                       "'lituya sweep SCENE.toml' needs --parameter KEY and --values V1,V2,...");
    if (o.parameters.size() != o.values.size())
      throw UsageError("sweep", "each --parameter needs its own --values (got " +
                                    std::to_string(o.parameters.size()) + " --parameter and " +
                                    std::to_string(o.values.size()) + " --values)");
    definition.scene = o.input;
    for (size_t p = 0; p < o.parameters.size(); ++p)
      definition.parameters.push_back(
          {o.parameters[p], lituya::sweep::parse_value_list(o.values[p])});
    definition.combination =
        o.combine == "zip" ? lituya::sweep::Combination::kZip : lituya::sweep::Combination::kGrid;
  }
  if (!o.measures.empty()) {
    definition.measures.clear();
    for (const std::string& m : o.measures)
      for (const std::string& item : lituya::sweep::split_list(m))
        definition.measures.push_back(item);
  }
  if (!o.output.empty()) definition.output = o.output;
  if (o.repeats != 0) {
    const std::string range = lituya::sweep::repeats_range_error(o.repeats);
    if (!range.empty()) throw UsageError("sweep", "--repeats " + range);
    definition.repeats = o.repeats;
    definition.repeats_line = 0;
  }
  if (!o.repeat_by.empty()) {
    const std::optional<lituya::sweep::RepeatBy> by =
        lituya::sweep::repeat_by_from_name(o.repeat_by);
    if (!by)
      throw UsageError("sweep", "--repeat-by must be courant or mesh (got '" + o.repeat_by + "')");
    if (definition.repeats < 2)
      throw UsageError("sweep", "--repeat-by " + o.repeat_by +
                                    " says what the repeats change, but there are none: give "
                                    "--repeats N (2-20) as well");
    definition.repeat_by = *by;
  }
  lituya::sweep::SweepOptions options;
  options.threads = o.threads;
  options.jobs = o.jobs;
  options.overwrite = o.force;
  options.resume = o.resume;
  options.progress = progress_stream(o);
  options.progress_is_terminal = isatty(fileno(stderr));
  options.report = &std::cout;
  options.dry_run = o.dry_run;
  options.reuse = !o.no_reuse;
  const lituya::sweep::SweepResult result = lituya::sweep::run_sweep(definition, options);
  if (result.all_ok()) return 0;
  // Without --quiet the table names the failed runs; with it, this line is all there is.
  if (o.quiet) {
    const auto failed = std::count_if(result.runs.begin(), result.runs.end(), [](const auto& run) {
      return run.status != lituya::sweep::RunStatus::kOk;
    });
    errors << "lituya: sweep: " << failed << " of " << result.runs.size() << " runs failed (see "
           << result.table.string() << ")\n";
  }
  return kSweepRunFailed;
}

void run_pre(const fs::path& scene, const fs::path& case_folder, const Options& o) {
  StepTimer timer(o, "pre");
  auto s = lituya::pre::preprocess(scene, case_folder, o.force, o.allow_large_mesh,
                                   /*gmsh_messages=*/o.verbose);
  std::cout << "pre: " << s.dimension << "D case with " << s.nodes << " nodes, " << s.cells
            << " cells, " << s.points << " material points in " << case_folder.string() << "\n";
}

int run_verify(const Options& o, std::ostream& errors) {
  StepTimer timer(o, "verify");
  lituya::verify::RunnerOptions options;
  options.full = o.full;
  options.threads = o.threads;
  options.overwrite = o.force;
  options.only = o.cases;
  options.progress = o.quiet ? nullptr : &std::cout;
  options.report_folder = o.output.empty() ? fs::path("verification-report") : fs::path(o.output);
  if (lituya::verify::run_verification(options)) return 0;
  if (o.quiet)
    errors << "lituya: verify: at least one check failed (see "
           << (options.report_folder / "report.md").string() << ")\n";
  return kVerifyFailed;
}

bool uses_threads(const std::string& command) {
  return command != "pre" && command != "post";
}

int run_command(const Options& o, std::ostream& errors) {
  if (o.verbose) {
    std::cerr << lituya::version_line() << ": " << o.command;
    if (uses_threads(o.command))
      std::cerr << ", " << o.threads << (o.threads == 1 ? " thread" : " threads") << " ("
                << o.threads_source << ")";
    std::cerr << "\n";
  }
  if (o.command == "pre") {
    run_pre(o.input, o.output.empty() ? default_case(o.input) : fs::path(o.output), o);
  } else if (o.command == "solve") {
    run_solve(o.input, o);
  } else if (o.command == "post") {
    run_post(o.input, o);
  } else if (o.command == "run") {
    const fs::path case_folder = o.output.empty() ? default_case(o.input) : fs::path(o.output);
    run_pre(o.input, case_folder, o);
    run_solve(case_folder, o);
    run_post(case_folder, o);
  } else if (o.command == "verify") {
    return run_verify(o, errors);
  } else if (o.command == "sweep") {
    return run_sweep(o, errors);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  QuietScope quiet;
  Options o;
  try {
    if (const int code = parse(argc, argv, o); code >= 0) return code;
    if (o.quiet) quiet.enable();
    return run_command(o, quiet.errors());
  } catch (const UsageError& e) {
    quiet.errors() << "lituya: " << e.what() << "\n" << help_hint(e.command) << "\n";
    return 1;
  } catch (const lituya::InputError& e) {
    quiet.errors() << "\nlituya: input error: " << e.what() << "\n";
    return 1;
  } catch (const lituya::RunError& e) {
    quiet.errors() << "\nlituya: run stopped: " << e.what() << "\n";
    return 2;
  } catch (const lituya::RunStopped& e) {
    quiet.errors() << "\nlituya: " << e.what()
                   << "; the output up to then is kept and summary.toml says completed = "
                      "false; `lituya solve CASE --resume` goes on from there\n";
    return 128 + e.signal();  // as a shell reports a process ended by the signal
  } catch (const IncompleteRun& e) {
    quiet.errors() << "lituya: post: " << e.what() << "\n";
    return kIncompleteRun;
  } catch (const po::error& e) {
    // Not expected (parse turns these into UsageError), but still the command line's fault.
    quiet.errors() << "lituya: " << e.what() << "\n" << help_hint(o.command) << "\n";
    return 1;
  } catch (const std::exception& e) {
    quiet.errors() << "\nlituya: error: " << e.what() << "\n";
    return 3;
  }
}
