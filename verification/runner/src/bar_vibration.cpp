// 1D elastic bar under suddenly applied gravity: period 4L/c and peak tip displacement
// rho g L^2 / E (verification/bar_vibration/README.md).
#include <algorithm>
#include <cmath>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

void run_bar_vibration(const CaseContext& context, CaseResult& result) {
  const double length = 1.0, youngs_modulus = 1.0e7, density = 2000.0, g = 9.81;
  const double wave_speed = std::sqrt(youngs_modulus / density);
  const double period = 4 * length / wave_speed;
  const double peak = density * g * length * length / youngs_modulus;  // 2 u_s(L)

  const auto case_folder = run_scene(context);
  const auto frames = read_series(case_folder, "vibration");
  std::vector<double> time, tip;
  std::vector<int> top;
  for (const Frame& f : frames) {
    int components = 0;
    const auto u = read_point_array(f.file, "displacement", components);
    if (top.empty()) {
      const auto x = read_positions(f.file);
      for (std::size_t p = 0; 3 * p < x.size(); ++p)
        if (x[3 * p + 1] > length - 0.05) top.push_back(static_cast<int>(p));
    }
    double sum = 0;
    for (int p : top) sum += u[components * p + 1];
    time.push_back(f.time);
    tip.push_back(-sum / static_cast<double>(top.size()));  // downward displacement, > 0
  }
  // Period: mean spacing of upward crossings of the mean level, linearly interpolated.
  double mean = 0;
  for (double v : tip) mean += v;
  mean /= static_cast<double>(tip.size());
  std::vector<double> crossings;
  for (std::size_t i = 1; i < tip.size(); ++i)
    if (tip[i - 1] < mean && tip[i] >= mean)
      crossings.push_back(time[i - 1] +
                          (mean - tip[i - 1]) / (tip[i] - tip[i - 1]) * (time[i] - time[i - 1]));
  double measured_period = NAN, measured_peak = NAN;
  if (crossings.size() >= 2) {
    measured_period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
    double sum = 0;
    for (std::size_t k = 0; k + 1 < crossings.size(); ++k) {
      double cycle_max = 0;
      for (std::size_t i = 0; i < time.size(); ++i)
        if (time[i] >= crossings[k] && time[i] < crossings[k + 1])
          cycle_max = std::max(cycle_max, tip[i]);
      sum += cycle_max;
    }
    measured_peak = sum / (crossings.size() - 1);
  }
  add_check(result, "period", "s", measured_period, period, 0.02 * period);
  add_check(result, "peak tip displacement", "m", measured_peak, peak, 0.05 * peak);

  std::vector<std::vector<double>> rows;
  for (std::size_t i = 0; i < time.size(); ++i) rows.push_back({time[i], tip[i], 0.5 * peak, peak});
  write_csv(context.work / "tip_displacement.csv",
            "time,tip_displacement,static_tip_displacement,exact_peak", rows);
  const auto csv = context.work / "tip_displacement.csv";
  post::plot_xy(
      context.work / "tip_displacement.png",
      "Bar under sudden gravity: tip displacement (period 4L/c, peak rho g L^2/E)", "time (s)",
      "downward tip displacement (m)",
      {{csv, 1, 2, "Lituya"}, {csv, 1, 3, "static u_s(L)"}, {csv, 1, 4, "exact peak 2 u_s(L)"}});
  result.plots.push_back(
      std::filesystem::relative(context.work / "tip_displacement.png", context.report));
}

}  // namespace lituya::verify
