// Dam break on a dry frictionless bed against Ritter's solution, at t sqrt(g/H) = 2.8
// (verification/dam_break/README.md) and at 7 (verification/dam_break_late/README.md).
#include <cmath>

#include "case_support.hpp"
#include "dam_break_measure.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

namespace {

// pre + solve of the case's scene, then the three checks against Ritter at the last output,
// the RMS depth error within `rms_tolerance`, and the depth profile drawn against Ritter's.
void check_against_ritter(const CaseContext& context, CaseResult& result,
                          const DamBreakSetup& setup, double rms_tolerance) {
  const double h0 = setup.h0;
  const auto case_folder = run_scene(context);
  const DamBreakMeasure m = measure_dam_break(case_folder, setup);
  const double t = m.time;

  add_check(result, "depth at the dam site (Ritter 4 H / 9)", "m", m.depth_at_dam, 4 * h0 / 9,
            0.1 * h0);
  add_check(result, "RMS depth error over |x - x_dam| <= c0 t", "m", m.rms_error, 0.0,
            rms_tolerance);
  // Ritter: h = 0.1 h0 where (2 - xi/c0)^2 / 9 = 0.1, xi / c0 = 2 - sqrt(0.9).
  add_check(result, "position of h = 0.1 H, (x - x_dam) / (c0 t)", "-", m.tenth_position,
            2 - std::sqrt(0.9), 0.15);

  const auto csv = context.work / "depth_profile.csv";
  write_csv(csv, "x,depth,ritter", m.profile);
  post::plot_xy(context.work / "depth_profile.png",
                "Dam break at t = " + std::to_string(t).substr(0, 4) + " s: depth against x",
                "x (m)", "depth (m)",
                {{csv, 1, 2, "Lituya (water points)", true}, {csv, 1, 3, "Ritter (1892)"}}, true);
  result.plots.push_back(
      std::filesystem::relative(context.work / "depth_profile.png", context.report));
}

}  // namespace

void run_dam_break(const CaseContext& context, CaseResult& result) {
  const DamBreakSetup setup;
  check_against_ritter(context, result, setup, 0.05 * setup.h0);
}

void run_dam_break_late(const CaseContext& context, CaseResult& result) {
  // verification/dam_break_late/README.md: the channel is longer and the column starts 1.6 m
  // long, so that at t = 1.0 s (t sqrt(g/H) = 7) no wave has met a wall; 0.005 m is issue 8's
  // target for the RMS depth error.
  DamBreakSetup setup;
  setup.x_dam = 1.6;
  setup.length = 4.6;
  check_against_ritter(context, result, setup, 0.005);
}

}  // namespace lituya::verify
