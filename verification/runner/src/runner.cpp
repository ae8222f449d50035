#include "lituya/verify/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "case_support.hpp"
#include "lituya/common/atomic_file.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/common/json_file.hpp"
#include "lituya/common/output_folder.hpp"
#include "lituya/common/provenance.hpp"
#include "lituya/solver/solve.hpp"

namespace lituya::verify {

// verification/extremes and its impact sub-case (extremes.cpp); declared here, the one place
// that needs them.
void run_extremes(const CaseContext& context, CaseResult& result);
void run_extremes_impact(const CaseContext& context, CaseResult& result);
// verification/speed_accuracy (speed_accuracy.cpp).
void run_speed_accuracy(const CaseContext& context, CaseResult& result);
// verification/speed_accuracy_case_b (speed_accuracy_case_b.cpp).
void run_speed_accuracy_case_b(const CaseContext& context, CaseResult& result);

namespace {

struct CaseEntry {
  std::string name;
  std::string title;
  CaseFunction run;
};

const std::vector<CaseEntry>& all_cases() {
  static const std::vector<CaseEntry> cases = {
      {"bar_vibration", "1D elastic bar vibration", run_bar_vibration},
      {"sliding_block", "Block sliding on a rigid incline", run_sliding_block},
      {"saturated_block", "Saturated block on a submerged incline: friction on effective stress",
       run_saturated_block},
      {"saturated_block_fine",
       "Saturated block of fine sand (grains and water locked): friction on effective stress",
       run_saturated_block_fine},
      {"gravity_column", "Gravity loading of a soil column", run_gravity_column},
      {"column_collapse", "Granular column collapse (dry, a = 2) at the default Courant number",
       run_column_collapse},
      {"case_a", "Case A: granular collapse on an erodible 22 degree slope", run_case_a},
      {"case_b", "Case B: dry granular slide into water down a 45 degree slope", run_case_b},
      {"case_c", "Case C: dry and saturated slides on rigid and erodible slopes", run_case_c},
      {"hydrostatic_tank", "Hydrostatic tank: still water stays still", run_hydrostatic_tank},
      {"dam_break", "Dam break on a dry bed against Ritter's solution", run_dam_break},
      {"dam_break_late", "Dam break on a dry bed against Ritter's solution at t sqrt(g/H) = 7",
       run_dam_break_late},
      {"speed_accuracy", "Speed against accuracy: the dam break's error vs wall time per knob",
       run_speed_accuracy},
      {"speed_accuracy_case_b",
       "Speed against accuracy: Case B's first waves vs wall time per knob, against a fine run",
       run_speed_accuracy_case_b},
      {"terzaghi", "Terzaghi 1D consolidation", run_terzaghi},
      {"seepage", "Seepage through a sand column (Darcy-Forchheimer)", run_seepage},
      {"infiltration", "Infiltration of a pond into dry sand (Green-Ampt with Ergun drag)",
       run_infiltration},
      {"lock_exchange",
       "Lock exchange: a saturated, strengthless fine soil runs along the bed under water",
       run_lock_exchange},
      {"sponge", "A long wave leaving a tank through a sponge zone", run_sponge},
      {"standing_wave", "Standing wave in a tank: period and damping of a resolved wave",
       run_standing_wave},
      {"extremes", "Stability at the extremes of the inputs", run_extremes},
      // A folder of its own, so that its known failure does not excuse the group's checks.
      {"extremes/impact", "Stability at the extremes: a slide's impact at 16 points per cell",
       run_extremes_impact},
  };
  return cases;
}

std::string number(double v) {
  std::ostringstream s;
  s << std::setprecision(4) << v;
  return s.str();
}

std::string status(const CaseResult& r) {
  if (r.passed()) return r.known_failure() ? "PASS (listed as a known failure: update it)" : "PASS";
  return r.known_failure() ? "FAIL (known failure)" : "FAIL";
}

// Every case folder (one holding stages.toml) that the case wrote under its work folder, with
// the hash of its case files, in path order.
std::vector<std::pair<std::string, std::string>> hash_case_folders(
    const std::filesystem::path& work) {
  std::vector<std::pair<std::string, std::string>> out;
  if (!std::filesystem::is_directory(work)) return out;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(work))
    if (entry.is_regular_file() && entry.path().filename() == "stages.toml") {
      const std::filesystem::path folder = entry.path().parent_path();
      out.emplace_back(std::filesystem::relative(folder, work).generic_string(),
                       solver::case_files_hash(folder));
    }
  std::sort(out.begin(), out.end());
  return out;
}

// Which program made the report and when: a report is compared with others long after.
struct ReportProvenance {
  std::string date = utc_now_iso8601();
};

void write_report(const std::filesystem::path& folder, const std::vector<CaseResult>& results,
                  bool full, const ReportProvenance& provenance) {
  write_file_atomically(folder / "report.md", [&](std::ostream& md) {
    md << "# Lituya verification report (" << (full ? "full" : "quick") << " variants)\n\n"
       << "Lituya " << lituya_version() << ", commit `" << lituya_commit() << "`, run "
       << provenance.date << ".\n\n"
       << "Each case states its reference, tolerance and why in `verification/<case>/README.md`."
       << "\nA check passes when |measured - reference| <= tolerance.\n\n";
    md << "| case | result | wall time (s) |\n|---|---|---|\n";
    for (const CaseResult& r : results)
      md << "| " << r.title << " | " << status(r) << " | " << number(r.wall_time) << " |\n";
    for (const CaseResult& r : results) {
      md << "\n## " << r.title << "\n\nFolder `verification/" << r.name << "`, " << r.variant
         << " variant: **" << status(r) << "**\n\n";
      if (r.known_failure() && !r.passed())
        md << "Known failure, explained in `verification/" << r.name << "/" << r.known_failure_note
           << "`.\n\n";
      if (!r.error.empty()) md << "Could not run: `" << r.error << "`\n\n";
      for (const auto& [case_folder, hash] : r.case_hashes)
        md << "Case files of `" << r.name << "/" << case_folder << "`: `" << hash << "`\n\n";
      if (!r.checks.empty()) {
        md << "| quantity | measured | reference | tolerance | unit | result |\n"
              "|---|---|---|---|---|---|\n";
        for (const Check& c : r.checks)
          md << "| " << c.quantity << " | " << number(c.measured) << " | " << number(c.reference)
             << " | " << number(c.tolerance) << " | " << c.unit << " | "
             << (c.passed ? "pass" : "FAIL") << " |\n";
      }
      for (const auto& plot : r.plots)
        md << "\n![" << plot.string() << "](" << plot.string() << ")\n";
    }
  });
  // Built as a JSON value (strings escaped whatever they hold) and written with every double
  // as it was measured: a script comparing reports must not see a 4-digit rounding.
  Json cases = Json::array();
  for (const CaseResult& r : results) {
    Json hashes = Json::object();
    for (const auto& [case_folder, hash] : r.case_hashes) hashes[case_folder] = hash;
    Json checks = Json::array();
    for (const Check& c : r.checks)
      checks.push_back({{"quantity", c.quantity},
                        {"unit", c.unit},
                        {"measured", json_number(c.measured)},
                        {"reference", json_number(c.reference)},
                        {"tolerance", json_number(c.tolerance)},
                        {"passed", c.passed}});
    cases.push_back({{"name", r.name},
                     {"title", r.title},
                     {"passed", r.passed()},
                     {"known_failure", r.known_failure()},
                     {"wall_time", json_number(r.wall_time)},
                     {"error", r.error},
                     {"case_hashes", hashes},
                     {"checks", checks}});
  }
  write_json_file(folder / "summary.json", {{"variant", full ? "full" : "quick"},
                                            {"lituya_version", lituya_version()},
                                            {"commit", lituya_commit()},
                                            {"date", provenance.date},
                                            {"cases", cases}});
}

}  // namespace

std::filesystem::path default_verification_folder() {
  // The executable's own path rather than argv[0] or the working folder: the command may be
  // run from any folder, through a symlink or from $PATH. A staged install (DESTDIR) or a
  // prefix moved after installing still finds its cases, since the path is relative.
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed =
        (exe.parent_path() / LITUYA_INSTALLED_VERIFICATION_DIR).lexically_normal();
    if (std::filesystem::is_directory(installed, error)) return installed;
  }
  return LITUYA_VERIFICATION_DIR;
}

bool run_verification(const RunnerOptions& options) {
  const std::filesystem::path source = options.verification_folder.empty()
                                           ? default_verification_folder()
                                           : options.verification_folder;
  for (const std::string& name : options.only) {
    bool known = false;
    for (const CaseEntry& c : all_cases()) known = known || c.name == name;
    if (!known) throw InputError(name, 0, "no verification case of this name");
  }
  prepare_output_folder(options.report_folder, options.overwrite);
  const ReportProvenance provenance;
  std::vector<CaseResult> results;
  std::vector<const CaseEntry*> selected;
  for (const CaseEntry& entry : all_cases())
    if (options.only.empty() ||
        std::find(options.only.begin(), options.only.end(), entry.name) != options.only.end())
      selected.push_back(&entry);
  // One line when a case starts and one when it ends, so that a run of several minutes shows
  // where it is (a case's own output, e.g. a warning, comes between them).
  std::ostream null_stream(nullptr);
  std::ostream& progress = options.progress ? *options.progress : null_stream;
  for (std::size_t k = 0; k < selected.size(); ++k) {
    const CaseEntry& entry = *selected[k];
    const std::string counter =
        "verify [" + std::to_string(k + 1) + "/" + std::to_string(selected.size()) + "] ";
    CaseResult result;
    result.name = entry.name;
    result.title = entry.title;
    result.variant = options.full ? "full" : "quick";
    CaseContext context{source / entry.name, options.report_folder / entry.name,
                        options.report_folder, options.full, options.threads};
    std::filesystem::create_directories(context.work);
    // known-failure-full.md: a failure of the full variant only (finer meshes than CI runs).
    if (std::filesystem::exists(context.source / "known-failure.md"))
      result.known_failure_note = "known-failure.md";
    else if (options.full && std::filesystem::exists(context.source / "known-failure-full.md"))
      result.known_failure_note = "known-failure-full.md";
    progress << counter << entry.name << ": started (" << result.variant
             << " variant: " << entry.title << ")" << std::endl;
    const auto start = std::chrono::steady_clock::now();
    try {
      entry.run(context, result);
    } catch (const std::exception& e) {
      result.error = e.what();
    }
    try {
      result.case_hashes = hash_case_folders(context.work);
    } catch (const std::exception& e) {
      result.case_hashes.emplace_back("?", std::string("not hashed: ") + e.what());
    }
    result.wall_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress << counter << entry.name << ": " << status(result) << " in "
             << number(result.wall_time) << " s\n";
    for (const Check& c : result.checks)
      progress << "    " << (c.passed ? "pass " : "FAIL ") << c.quantity << ": measured "
               << number(c.measured) << ", reference " << number(c.reference) << " +- "
               << number(c.tolerance) << " " << c.unit << "\n";
    if (!result.error.empty()) progress << "    error: " << result.error << "\n";
    progress.flush();
    results.push_back(std::move(result));
  }
  write_report(options.report_folder, results, options.full, provenance);
  int passed = 0, known = 0;
  for (const CaseResult& r : results) {
    passed += r.passed();
    known += !r.passed() && r.known_failure();
  }
  const int failed = static_cast<int>(results.size()) - passed - known;
  progress << "verification report: " << (options.report_folder / "report.md").string() << "\n"
           << known << " known failure(s), documented in the report\n"
           << "verification: " << passed << " passed, " << failed << " failed\n";
  return failed == 0;
}

}  // namespace lituya::verify
