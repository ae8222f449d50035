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
#include "lituya/common/output_folder.hpp"
#include "lituya/common/provenance.hpp"
#include "lituya/solver/solve.hpp"

namespace lituya::verify {

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
      {"gravity_column", "Gravity loading of a soil column", run_gravity_column},
      {"case_a", "Case A: granular collapse on an erodible 22 degree slope", run_case_a},
      {"case_b", "Case B: dry granular slide into water down a 45 degree slope", run_case_b},
      {"case_c", "Case C: dry and saturated slides on rigid and erodible slopes", run_case_c},
      {"hydrostatic_tank", "Hydrostatic tank: still water stays still", run_hydrostatic_tank},
      {"dam_break", "Dam break on a dry bed against Ritter's solution", run_dam_break},
      {"terzaghi", "Terzaghi 1D consolidation", run_terzaghi},
      {"seepage", "Seepage through a sand column (Darcy-Forchheimer)", run_seepage},
  };
  return cases;
}

std::string number(double v) {
  std::ostringstream s;
  s << std::setprecision(4) << v;
  return s.str();
}

std::string status(const CaseResult& r) {
  if (r.passed()) return r.known_failure ? "PASS (listed as a known failure: update it)" : "PASS";
  return r.known_failure ? "FAIL (known failure)" : "FAIL";
}

std::string json_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
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
      if (r.known_failure && !r.passed())
        md << "Known failure, explained in `verification/" << r.name << "/known-failure.md`.\n\n";
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
  write_file_atomically(folder / "summary.json", [&](std::ostream& json) {
    json << "{\n  \"variant\": \"" << (full ? "full" : "quick") << "\",\n  \"lituya_version\": \""
         << json_escape(lituya_version()) << "\",\n  \"commit\": \"" << json_escape(lituya_commit())
         << "\",\n  \"date\": \"" << provenance.date << "\",\n  \"cases\": [\n";
    for (std::size_t i = 0; i < results.size(); ++i) {
      const CaseResult& r = results[i];
      json << "    {\"name\": \"" << r.name << "\", \"passed\": " << (r.passed() ? "true" : "false")
           << ", \"known_failure\": " << (r.known_failure ? "true" : "false")
           << ", \"wall_time\": " << r.wall_time << ", \"error\": \"" << json_escape(r.error)
           << "\", \"case_hashes\": {";
      for (std::size_t k = 0; k < r.case_hashes.size(); ++k)
        json << (k ? ", " : "") << "\"" << json_escape(r.case_hashes[k].first) << "\": \""
             << r.case_hashes[k].second << "\"";
      json << "}, \"checks\": [";
      for (std::size_t k = 0; k < r.checks.size(); ++k) {
        const Check& c = r.checks[k];
        json << (k ? ", " : "") << "{\"quantity\": \"" << c.quantity << "\", \"unit\": \"" << c.unit
             << "\", \"measured\": " << (std::isfinite(c.measured) ? number(c.measured) : "null")
             << ", \"reference\": " << c.reference << ", \"tolerance\": " << c.tolerance
             << ", \"passed\": " << (c.passed ? "true" : "false") << "}";
      }
      json << "]}" << (i + 1 < results.size() ? "," : "") << "\n";
    }
    json << "  ]\n}\n";
  });
}

}  // namespace

bool run_verification(const RunnerOptions& options) {
  const std::filesystem::path source = options.verification_folder.empty()
                                           ? std::filesystem::path(LITUYA_VERIFICATION_DIR)
                                           : options.verification_folder;
  for (const std::string& name : options.only) {
    bool known = false;
    for (const CaseEntry& c : all_cases()) known = known || c.name == name;
    if (!known) throw InputError(name, 0, "no verification case of this name");
  }
  prepare_output_folder(options.report_folder, options.overwrite);
  const ReportProvenance provenance;
  std::vector<CaseResult> results;
  for (const CaseEntry& entry : all_cases()) {
    if (!options.only.empty() &&
        std::find(options.only.begin(), options.only.end(), entry.name) == options.only.end())
      continue;
    CaseResult result;
    result.name = entry.name;
    result.title = entry.title;
    result.variant = options.full ? "full" : "quick";
    CaseContext context{source / entry.name, options.report_folder / entry.name,
                        options.report_folder, options.full, options.threads};
    std::filesystem::create_directories(context.work);
    result.known_failure = std::filesystem::exists(context.source / "known-failure.md");
    std::cout << "verify: " << entry.title << " (" << result.variant << ") ..." << std::flush;
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
    std::cout << " " << status(result) << " (" << number(result.wall_time) << " s)\n";
    for (const Check& c : result.checks)
      std::cout << "    " << (c.passed ? "pass " : "FAIL ") << c.quantity << ": measured "
                << number(c.measured) << ", reference " << number(c.reference) << " +- "
                << number(c.tolerance) << " " << c.unit << "\n";
    if (!result.error.empty()) std::cout << "    error: " << result.error << "\n";
    results.push_back(std::move(result));
  }
  write_report(options.report_folder, results, options.full, provenance);
  int passed = 0, known = 0;
  for (const CaseResult& r : results) {
    passed += r.passed();
    known += !r.passed() && r.known_failure;
  }
  const int failed = static_cast<int>(results.size()) - passed - known;
  std::cout << "verification report: " << (options.report_folder / "report.md").string() << "\n"
            << known << " known failure(s), documented in the report\n"
            << "verification: " << passed << " passed, " << failed << " failed\n";
  return failed == 0;
}

}  // namespace lituya::verify
