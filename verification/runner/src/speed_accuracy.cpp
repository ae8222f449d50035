// The speed/accuracy trade of the dam break (verification/speed_accuracy/README.md): the dam
// break of verification/dam_break run with one knob at a time changed from its quick setting,
// each run's RMS depth error against Ritter's solution (the dam_break case's own measure)
// against the wall time of its solve on one thread, and the cheapest runs within 5 % and 10 %.
#include "lituya/verify/speed_accuracy.hpp"
#include "case_support.hpp"
#include "dam_break_measure.hpp"
#include "trade_study.hpp"

namespace lituya::verify {

void run_speed_accuracy(const CaseContext& context, CaseResult& result) {
  const DamBreakSetup setup;
  TradeStudy study;
  study.name = "speed_accuracy";
  study.problem = "Dam break: error against Ritter";
  study.scene = context.source.parent_path() / "dam_break" / "scene_quick.toml";
  study.keys = trade_knob_keys();
  study.names = trade_knob_names();
  // The base setting: the dam_break quick scene's (h = 0.02 m, 4 points per cell, Courant 0.5,
  // K_w = 2.15e7 Pa); the quick variant starts from 0.04 m cells to stay within seconds.
  study.base = {"0.02", "4", "0.5", "2.15e7"};
  if (context.full) {
    study.knobs = {{study.keys[0],
                    study.names[0],
                    "cell size h (m)",
                    {"0.04", "0.03", "0.02", "0.014", "0.01", "0.005"}},
                   {study.keys[1], study.names[1], "points per cell", {"1", "3", "4", "9", "16"}},
                   {study.keys[2],
                    study.names[2],
                    "Courant number",
                    {"0.1", "0.2", "0.3", "0.5", "0.7", "0.9"}},
                   {study.keys[3],
                    study.names[3],
                    "water bulk modulus (Pa)",
                    {"2.15e4", "2.15e5", "2.15e6", "2.15e7", "2.15e8", "2.15e9"}}};
  } else {
    study.base[0] = "0.04";
    study.knobs = {{study.keys[2], study.names[2], "Courant number", {"0.25", "0.5"}}};
  }
  study.repeats = context.full ? 3 : 1;
  study.combined = context.full;
  study.measure_columns = {"rms_error", "depth_at_dam", "tenth_position"};
  study.errors = {{"error_over_h", "RMS depth error / H", "speed_accuracy",
                   "Dam break: RMS depth error against Ritter (t = 0.4 s) vs wall time"}};
  study.measure = [&setup](const std::filesystem::path& case_folder, StudyRun& run) {
    const DamBreakMeasure m = measure_dam_break(case_folder);
    run.measured = {m.rms_error, m.depth_at_dam, m.tenth_position};
    run.errors = {m.rms_error / setup.h0};
  };
  const std::vector<StudyRun> runs = run_trade_study(study, context, result);

  // Checks of the cost and accuracy claims of user manual section 3 (README.md).
  const auto [cx, cs] = knob_cost(runs, "courant", 0, 1, true);
  add_check(result, "steps ~ Courant^p: p", "-", log_log_slope(cx, cs), -1.0, 0.05);
  add_check(result, "the Courant number changes the cost, not the answer: spread of error / H", "-",
            error_spread(runs, "courant", 0), 0.0, 0.01);
  if (context.full) {
    const auto [cw, ct] = knob_cost(runs, "courant", 0, 1, false);
    add_check(result, "wall time ~ Courant^p: p", "-", log_log_slope(cw, ct), -1.0, 0.25);
    const auto [kx, ks] = knob_cost(runs, "bulk_modulus", 2.15e7, 2.15e9, true);
    add_check(result, "steps ~ K_w^p, K_w = 2.15e7-2.15e9 Pa: p", "-", log_log_slope(kx, ks), 0.5,
              0.05);
    const auto [nx, nt] = knob_cost(runs, "points_per_cell", 4, 16, false);
    add_check(result, "wall time ~ (points per cell)^p, 4-16: p", "-", log_log_slope(nx, nt), 1.0,
              0.3);
    const auto [hx, ht] = knob_cost(runs, "cell_size", 0.005, 0.01, false);
    add_check(result, "wall time ~ h^p, h = 0.005-0.01 m: p", "-", log_log_slope(hx, ht), -3.0,
              0.5);
  }
}

}  // namespace lituya::verify
