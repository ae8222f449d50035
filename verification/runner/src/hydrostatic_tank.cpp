// Still water in a tank: p = rho_w g (H - y), and no motion beyond the water's own
// compression (verification/hydrostatic_tank/README.md).
#include <algorithm>
#include <cmath>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

void run_hydrostatic_tank(const CaseContext& context, CaseResult& result) {
  const double rho = 1000.0, g = 9.81, depth = 0.5;
  const auto case_folder = run_scene(context);
  const auto frames = read_series(case_folder, "still", "liquid");

  // Largest speed over every output of the run.
  double max_speed = 0;
  std::vector<std::vector<double>> speed_rows;
  for (const Frame& f : frames) {
    int c = 0;
    const auto v = read_point_array(f.file, "velocity", c);
    double frame_max = 0;
    for (std::size_t p = 0; p < v.size() / c; ++p)
      frame_max = std::max(frame_max, std::hypot(v[c * p], v[c * p + 1]));
    max_speed = std::max(max_speed, frame_max);
    speed_rows.push_back({f.time, frame_max});
  }

  const auto& last = frames.back().file;
  int pc = 0;
  const auto pressure = read_point_array(last, "pressure", pc);
  const auto x = read_positions(last);
  const double scale = rho * g * depth;
  double squared = 0;
  std::vector<std::vector<double>> rows;
  for (std::size_t p = 0; p < pressure.size(); ++p) {
    const double d = depth - x[3 * p + 1];
    const double exact = rho * g * d;
    squared += std::pow((pressure[p] - exact) / scale, 2);
    rows.push_back({d, pressure[p], exact});
  }
  std::sort(rows.begin(), rows.end());
  add_check(result, "RMS pressure error / (rho_w g H) at the last output", "-",
            std::sqrt(squared / static_cast<double>(pressure.size())), 0.0, 0.02);
  add_check(result, "largest water speed / sqrt(g H) over the run", "-",
            max_speed / std::sqrt(g * depth), 0.0, 0.01);

  const auto csv = context.work / "pressure_profile.csv";
  write_csv(csv, "depth,pressure,hydrostatic", rows);
  post::plot_xy(context.work / "pressure_profile.png",
                "Still water: pressure of every water point against depth", "depth (m)",
                "pressure (Pa)", {{csv, 1, 2, "water points", true}, {csv, 1, 3, "rho_w g depth"}},
                true);
  const auto speed_csv = context.work / "max_speed.csv";
  write_csv(speed_csv, "time,max_speed", speed_rows);
  post::plot_xy(context.work / "max_speed.png", "Still water: largest point speed", "time (s)",
                "speed (m/s)", {{speed_csv, 1, 2, "largest speed"}}, true);
  for (const char* png : {"pressure_profile.png", "max_speed.png"})
    result.plots.push_back(std::filesystem::relative(context.work / png, context.report));
}

}  // namespace lituya::verify
