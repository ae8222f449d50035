// The first sloshing mode of a tank released from rest (verification/standing_wave/README.md):
// its period against linear theory, and the height it loses per period, which in a tank with
// frictionless walls is what the numerics take from a resolved wave.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"
#include "standing_wave_measure.hpp"

namespace lituya::verify {

namespace {
// The tank of tank.geo: length and still depth; gravity.
constexpr double kLength = 0.5, kDepth = 0.15, kGravity = 9.81;

struct Record {
  std::vector<double> time, amplitude, centroid;  // s; m (the mode); m (volume centroid)
};

Record run_tank(const CaseContext& context, const std::string& scene, const std::string& name) {
  const auto case_folder = run_scene(context, context.source / scene, context.work / name);
  Record record;
  for (const Frame& frame : read_series(case_folder, "release", "liquid")) {
    int components = 0;
    const std::vector<double> volume = read_point_array(frame.file, "volume", components);
    const std::vector<double> positions = read_positions(frame.file);
    record.time.push_back(frame.time);
    record.amplitude.push_back(modal_amplitude(positions, volume, kLength));
    record.centroid.push_back(volume_centroid_height(positions, volume));
  }
  return record;
}

// The three checks of README.md on the run.
StandingWaveFit check_tank(CaseResult& result, const Record& r, double linear_period) {
  StandingWaveFit fit = fit_standing_wave(r.time, r.amplitude);
  double sinking = 0;  // the largest fall of the centroid below its height at the release
  for (double y : r.centroid) sinking = std::max(sinking, r.centroid.front() - y);
  // Tolerances and why: README.md.
  add_check(result, "period / linear theory's 2 pi / sqrt(g k tanh(k h))", "-",
            fit.period / linear_period, 1.0, 0.02);
  add_check(result, "height lost per period (fit to the extremes of the mode)", "-",
            fit.decay_per_period, 0.0, 0.05);
  add_check(result, "largest fall of the water's volume centroid", "m", sinking, 0.0, 0.001);
  return fit;
}
}  // namespace

void run_standing_wave(const CaseContext& context, CaseResult& result) {
  const std::string variant = context.full ? "full" : "quick";
  const Record base = run_tank(context, "scene_" + variant + ".toml", "case");

  // Linear theory (Lamb 1932, art. 257): omega^2 = g k tanh(k h), k = pi / L.
  const double k = std::numbers::pi / kLength;
  const double omega = std::sqrt(kGravity * k * std::tanh(k * kDepth));
  const double linear_period = 2 * std::numbers::pi / omega;
  const StandingWaveFit fit = check_tank(result, base, linear_period);

  std::vector<std::vector<double>> rows;
  for (std::size_t f = 0; f < base.time.size(); ++f)
    rows.push_back({base.time[f], base.amplitude[f],
                    base.amplitude[0] * std::cos(omega * base.time[f]),
                    base.centroid[f] - base.centroid[0]});
  const auto csv = context.work / "modal_amplitude.csv";
  write_csv(csv, "time,modal_amplitude,linear_theory,centroid_change", rows);
  std::vector<std::vector<double>> extremes;
  for (std::size_t e = 0; e < fit.extreme_time.size(); ++e)
    extremes.push_back({fit.extreme_time[e], fit.extreme_amplitude[e]});
  write_csv(context.work / "extremes.csv", "time,amplitude", extremes);
  const auto png = context.work / "modal_amplitude.png";
  post::plot_xy(png, "Standing wave: amplitude of the surface mode cos(pi x / L)", "time (s)",
                "amplitude (m)",
                {{csv, 1, 2, "Lituya (cosine moment of the water's volume)"},
                 {csv, 1, 3, "linear theory, undamped"}});
  result.plots.push_back(std::filesystem::relative(png, context.report));
  const auto centroid_png = context.work / "centroid.png";
  post::plot_xy(centroid_png, "Standing wave: fall of the water's volume centroid", "time (s)",
                "centroid height - its height at the release (m)", {{csv, 1, 4, "Lituya"}});
  result.plots.push_back(std::filesystem::relative(centroid_png, context.report));
}

}  // namespace lituya::verify
