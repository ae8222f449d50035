// The speed/accuracy trade of Case B (verification/speed_accuracy_case_b/README.md): the slide
// into water of examples/case_b_2d on a Coulomb slope, run with one knob at a time changed
// from the paper's setting, each run's first crests and first-wave areas at the gauges X1 and
// X2 against those of a reference run on a finer mesh than any of the study's, against the
// wall time of its solve on one thread.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "case_support.hpp"
#include "lituya/common/atomic_file.hpp"
#include "lituya/post/postprocess.hpp"
#include "lituya/verify/speed_accuracy.hpp"
#include "trade_study.hpp"

namespace lituya::verify {

namespace {

namespace fs = std::filesystem;

// The first wave at X1 and X2 of a solved case: crest heights (m) and areas (m s), NaN where
// the wave is still standing at the end of the run.
struct FirstWaves {
  double crest[2] = {NAN, NAN};
  double area[2] = {NAN, NAN};
};

FirstWaves measure_first_waves(const fs::path& case_folder) {
  const post::PostResult r =
      post::postprocess(case_folder, case_folder.parent_path() / "post", /*overwrite=*/true);
  if (r.gauge_eta.size() != 2)
    throw std::runtime_error("speed_accuracy_case_b: the scene's [post] must name 2 gauges");
  FirstWaves w;
  for (int g = 0; g < 2; ++g) {
    const post::WaveCrest c = complete_first_wave(r.liquid_time, r.gauge_eta[g]);
    w.crest[g] = c.height;
    w.area[g] = c.area;
  }
  return w;
}

// The larger of the relative differences at the two gauges.
double worst_relative(const double (&value)[2], const double (&reference)[2]) {
  double worst = 0;
  for (int g = 0; g < 2; ++g) {
    const double e = std::abs(value[g] - reference[g]) / reference[g];
    if (!std::isfinite(e)) return std::numeric_limits<double>::quiet_NaN();
    worst = std::max(worst, e);
  }
  return worst;
}

// The largest relative difference of the crests among the runs of `knob`, at either gauge:
// how much that knob moves the answer (0 when it moves only the cost).
double crest_spread(const std::vector<StudyRun>& runs, const std::string& knob) {
  double worst = 0;
  for (int g = 0; g < 2; ++g) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const StudyRun& r : runs)
      if (r.knob == knob) {
        if (!std::isfinite(r.measured[g])) return std::numeric_limits<double>::quiet_NaN();
        lo = std::min(lo, r.measured[g]);
        hi = std::max(hi, r.measured[g]);
      }
    worst = std::max(worst, (hi - lo) / lo);
  }
  return worst;
}

std::string number(double v, int digits = 4) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

// A line of the convergence table: the values at three cell sizes (ratio r), the observed order
// and the Richardson limit, or why there is none.
std::string richardson_line(const std::string& what, double f1, double f2, double f3, double r) {
  std::ostringstream s;
  s << "| " << what << " | " << number(f1) << " | " << number(f2) << " | " << number(f3) << " | ";
  const RichardsonEstimate e = richardson(f1, f2, f3, r);
  if (!std::isfinite(e.order)) {
    s << "- | - | the differences change sign (or vanish): not in the asymptotic range |\n";
    return s.str();
  }
  s << number(e.order, 3) << " | " << number(e.limit) << " | "
    << (e.order > 0.5 && e.order < 3 ? "order plausible for this scheme (1-2)"
                                     : "order not plausible: no estimate")
    << " |\n";
  return s.str();
}

}  // namespace

void run_speed_accuracy_case_b(const CaseContext& context, CaseResult& result) {
  TradeStudy study;
  study.name = "speed_accuracy_case_b";
  study.problem = "Case B: first crests and first-wave areas at X1 and X2 against a fine run";
  study.scene = context.source / "scene.toml";
  study.keys = trade_knob_keys();
  study.names = trade_knob_names();
  // The base: the paper's setting (h = 0.02 m, 4 points per cell, Courant 0.5, K_w = 2.15e7 Pa).
  // The quick variant (CI) only checks at 0.03 m that the Courant number moves the cost, not
  // the wave.
  study.base = {"0.02", "4", "0.5", "2.15e7"};
  std::vector<std::string> reference_setting = study.base;
  if (context.full) {
    study.knobs = {
        {study.keys[0], study.names[0], "cell size h (m)", {"0.03", "0.02", "0.015", "0.01"}},
        {study.keys[1], study.names[1], "points per cell", {"1", "4", "9", "16"}},
        {study.keys[2], study.names[2], "Courant number", {"0.2", "0.3", "0.5", "0.7", "0.9"}},
        {study.keys[3],
         study.names[3],
         "water bulk modulus (Pa)",
         {"2.15e5", "2.15e6", "2.15e7", "2.15e8", "2.15e9"}}};
    // The reference: 0.0075 m, the finest mesh the study can afford (6e9 point-steps, 15 min on
    // two threads; 0.005 m would take 2e10 and about 50 min). It also makes 0.03 / 0.015 /
    // 0.0075 m a sequence of ratio 2 for the Richardson estimate.
    reference_setting[0] = "0.0075";
  } else {
    study.base[0] = reference_setting[0] = "0.03";
    study.knobs = {{study.keys[2], study.names[2], "Courant number", {"0.25", "0.5"}}};
  }
  study.repeats = context.full ? 3 : 1;
  study.combined = context.full;
  study.measure_columns = {"crest_x1", "crest_x2", "area_x1", "area_x2"};
  study.errors = {
      {"crest_error", "first-crest error (worse of X1, X2)", "speed_accuracy_case_b_crest",
       "Case B: first-crest error at X1 and X2 against the reference run vs wall time"},
      {"area_error", "first-wave area error (worse of X1, X2)", "speed_accuracy_case_b_area",
       "Case B: first-wave area error at X1 and X2 against the reference run vs wall time"}};

  // The reference: the base setting on a finer mesh than the study's finest (quick: the base
  // itself), on all the threads the verification was given (its cost is not plotted).
  std::cout << study.name << ": reference run " << setting_name(study, reference_setting)
            << std::flush;
  TradeStudy reference_study = study;
  reference_study.repeats = 1;
  reference_study.measure = [](const fs::path& case_folder, StudyRun& run) {
    const FirstWaves w = measure_first_waves(case_folder);
    run.measured = {w.crest[0], w.crest[1], w.area[0], w.area[1]};
  };
  const StudyRun reference = run_study_setting(reference_study, reference_setting,
                                               context.work / "reference", context.threads);
  if (!reference.failure.empty())
    throw std::runtime_error("speed_accuracy_case_b: the reference run failed: " +
                             reference.failure);
  const FirstWaves ref = {{reference.measured[0], reference.measured[1]},
                          {reference.measured[2], reference.measured[3]}};
  std::cout << ": crests " << number(1e3 * ref.crest[0]) << " / " << number(1e3 * ref.crest[1])
            << " mm, areas " << number(1e3 * ref.area[0]) << " / " << number(1e3 * ref.area[1])
            << " mm s, " << number(reference.wall_time, 3) << " s on " << context.threads
            << " thread(s)" << std::endl;
  if (!std::all_of(reference.measured.begin(), reference.measured.end(),
                   [](double v) { return std::isfinite(v) && v > 0; }))
    throw std::runtime_error(
        "speed_accuracy_case_b: the reference run's first wave did not pass both gauges");

  study.measure = [ref](const fs::path& case_folder, StudyRun& run) {
    const FirstWaves w = measure_first_waves(case_folder);
    run.measured = {w.crest[0], w.crest[1], w.area[0], w.area[1]};
    run.errors = {worst_relative(w.crest, ref.crest), worst_relative(w.area, ref.area)};
  };
  std::ostringstream notes;
  notes << "Reference run: " << setting_name(study, reference_setting) << " (" << reference.points
        << " liquid points, " << reference.steps << " steps, " << number(reference.wall_time, 3)
        << " s on " << context.threads << " thread(s)): first crests X1 "
        << number(1e3 * ref.crest[0]) << " mm, X2 " << number(1e3 * ref.crest[1])
        << " mm; first-wave areas X1 " << number(1e3 * ref.area[0]) << " mm s, X2 "
        << number(1e3 * ref.area[1]) << " mm s; water volume change "
        << number(100 * reference.volume_change, 3) << " %.\n";
  study.notes = notes.str();
  const std::vector<StudyRun> runs = run_trade_study(study, context, result);

  // The crest and area against h with the reference: the convergence of the wave (user manual
  // section 3), and a Richardson estimate from 0.03 / 0.015 / 0.0075 m where one can be made.
  if (context.full) {
    auto at = [&](const std::string& h) -> const StudyRun* {
      for (const StudyRun& r : runs)
        if (r.knob == "cell_size" && r.setting[0] == h) return &r;
      return nullptr;
    };
    const StudyRun* coarse = at("0.03");
    const StudyRun* medium = at("0.015");
    std::ostringstream md;
    md << "# Case B on the Coulomb slope: the wave against the cell size\n\n"
       << "| measure | h = 0.03 m | 0.015 m | 0.0075 m (reference) | observed order | "
          "Richardson limit | reading |\n|---|---|---|---|---|---|---|\n";
    const char* names[] = {"X1 first crest (m)", "X2 first crest (m)", "X1 first-wave area (m s)",
                           "X2 first-wave area (m s)"};
    for (int m = 0; m < 4; ++m)
      md << richardson_line(names[m], coarse ? coarse->measured[m] : NAN,
                            medium ? medium->measured[m] : NAN, reference.measured[m], 2.0);
    write_file_atomically(context.work / "convergence.md",
                          [&](std::ostream& out) { out << md.str(); });
    std::cout << md.str() << std::flush;
  }

  // Checks (README.md, fixed before the first run).
  const auto [cx, cs] = knob_cost(runs, "courant", 0, 1, true);
  add_check(result, "release steps ~ Courant^p: p", "-", log_log_slope(cx, cs), -1.0, 0.05);
  add_check(result,
            "the Courant number changes the cost, not the wave: spread of the first crests "
            "(relative)",
            "-", crest_spread(runs, "courant"), 0.0, context.full ? 0.05 : 0.025);
  if (context.full) {
    const auto [kx, ks] = knob_cost(runs, "bulk_modulus", 2.15e8, 2.15e9, true);
    add_check(result, "release steps ~ K_w^p, K_w = 2.15e8-2.15e9 Pa (the water sets the step): p",
              "-", log_log_slope(kx, ks), 0.5, 0.05);
    const auto [sx, ss] = knob_cost(runs, "bulk_modulus", 2.15e5, 2.15e6, true);
    add_check(result, "release steps ~ K_w^p, K_w = 2.15e5-2.15e6 Pa (the soil sets the step): p",
              "-", log_log_slope(sx, ss), 0.0, 0.1);
  }
}

}  // namespace lituya::verify
