// Block sliding on a rigid 25 degree incline with mu = 0.2: a = g (sin - mu cos)
// (verification/sliding_block/README.md).
#include <cmath>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

void run_sliding_block(const CaseContext& context, CaseResult& result) {
  constexpr double kPi = 3.14159265358979323846;
  const double theta = 25 * kPi / 180, mu = 0.2, g = 9.81;
  const double acceleration = g * (std::sin(theta) - mu * std::cos(theta));
  const double dx = std::cos(theta), dy = -std::sin(theta);

  const auto case_folder = run_scene(context);
  std::vector<double> time, travel;
  for (const Frame& f : read_series(case_folder, "slide")) {
    int components = 0;
    const auto u = read_point_array(f.file, "displacement", components);
    double sum = 0;
    const std::size_t n = u.size() / components;
    for (std::size_t p = 0; p < n; ++p) sum += u[components * p] * dx + u[components * p + 1] * dy;
    time.push_back(f.time);
    travel.push_back(sum / static_cast<double>(n));
  }
  // Least squares of s = a t^2 / 2.
  double st2 = 0, t4 = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    st2 += travel[i] * time[i] * time[i];
    t4 += std::pow(time[i], 4);
  }
  const double measured = t4 > 0 ? 2 * st2 / t4 : NAN;
  add_check(result, "acceleration along the incline", "m/s2", measured, acceleration,
            0.02 * acceleration);

  std::vector<std::vector<double>> rows;
  for (std::size_t i = 0; i < time.size(); ++i)
    rows.push_back({time[i], travel[i], 0.5 * acceleration * time[i] * time[i]});
  const auto csv = context.work / "travel.csv";
  write_csv(csv, "time,travel,exact_travel", rows);
  post::plot_xy(context.work / "travel.png",
                "Block on a 25 degree incline, mu = 0.2: travel along the slope", "time (s)",
                "travel (m)",
                {{csv, 1, 2, "Lituya", true}, {csv, 1, 3, "g (sin - mu cos) t^2 / 2"}});
  result.plots.push_back(std::filesystem::relative(context.work / "travel.png", context.report));
}

}  // namespace lituya::verify
