// Gravity loading of an elastic column: sigma_yy = -rho g d, sigma_xx = nu/(1-nu) sigma_yy
// (verification/gravity_column/README.md).
#include <cmath>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

void run_gravity_column(const CaseContext& context, CaseResult& result) {
  const double density = (1 - 0.4) * 2650.0, g = 9.81, nu = 0.3, height = 1.0;
  const double k0 = nu / (1 - nu);

  const auto case_folder = run_scene(context);
  const auto frames = read_series(case_folder, "gravity");
  const auto& last = frames.back().file;
  int sc = 0, uc = 0;
  const auto stress = read_point_array(last, "stress", sc);
  const auto u = read_point_array(last, "displacement", uc);
  const auto x = read_positions(last);
  const std::size_t n = x.size() / 3;
  double squared_error = 0, sxy = 0, syy = 0;
  int count = 0;
  std::vector<std::vector<double>> rows;
  for (std::size_t p = 0; p < n; ++p) {
    const double depth = height - (x[3 * p + 1] - u[uc * p + 1]);
    const double sigma_v = stress[sc * p + 1], sigma_h = stress[sc * p];
    rows.push_back({depth, sigma_v, sigma_h, -density * g * depth, -k0 * density * g * depth});
    if (depth < 0.1 || depth > 0.9) continue;
    squared_error += std::pow((sigma_v + density * g * depth) / (density * g * height), 2);
    sxy += sigma_h * sigma_v;
    syy += sigma_v * sigma_v;
    ++count;
  }
  add_check(result, "RMS error of sigma_yy / (rho g H)", "-",
            count ? std::sqrt(squared_error / count) : NAN, 0.0, 0.02);
  add_check(result, "K0 = sigma_xx / sigma_yy", "-", syy > 0 ? sxy / syy : NAN, k0, 0.03 * k0);

  const auto csv = context.work / "stress_profile.csv";
  write_csv(csv, "depth,sigma_yy,sigma_xx,exact_sigma_yy,exact_sigma_xx", rows);
  post::plot_xy(context.work / "stress_profile.png",
                "Elastic column under gravity: stresses against depth", "depth (m)",
                "stress (Pa, tension positive)",
                {{csv, 1, 2, "sigma_yy (points)", true},
                 {csv, 1, 3, "sigma_xx (points)", true},
                 {csv, 1, 4, "-rho g d"},
                 {csv, 1, 5, "-K0 rho g d"}});
  result.plots.push_back(
      std::filesystem::relative(context.work / "stress_profile.png", context.report));
}

}  // namespace lituya::verify
