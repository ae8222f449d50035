// A saturated block on a submerged 25 degree incline: Coulomb friction on the effective normal
// stress only, a = (1 - rho_w / rho_s) g (sin - mu cos) for tan > mu, and no slide for
// tan < mu (verification/saturated_block/README.md).
#include <algorithm>
#include <cmath>

#include "case_support.hpp"
#include "incline_travel.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

void run_saturated_block(const CaseContext& context, CaseResult& result) {
  constexpr double kPi = 3.14159265358979323846;
  const double theta = 25 * kPi / 180, g = 9.81, rho_s = 2650.0, rho_w = 1000.0;
  const double mu_slide = 0.2;
  const double reduced_g = (1.0 - rho_w / rho_s) * g;  // gravity less buoyancy, on the grains
  const double acceleration = reduced_g * (std::sin(theta) - mu_slide * std::cos(theta));
  const double ratio = 1.0 - mu_slide / std::tan(theta);
  const double dx = std::cos(theta), dy = -std::sin(theta);

  const std::string variant = context.full ? "full" : "quick";
  auto run = [&](const std::string& name) {
    return run_scene(context, context.source / ("scene_" + variant + "_" + name + ".toml"),
                     context.work / name);
  };
  const InclineTravel slides = along_slope_travel(run("slides"), "slide", dx, dy);
  const InclineTravel free = along_slope_travel(run("free"), "slide", dx, dy);
  const InclineTravel stays = along_slope_travel(run("stays"), "hold", dx, dy);

  // (1) The closed form; the water the grains displace (added mass) is not in it (README).
  const double measured = fitted_acceleration(slides);
  add_check(result, "acceleration along the incline, mu = 0.2", "m/s2", measured, acceleration,
            0.06 * acceleration);
  // (2) Friction alone: the same block without friction has the same mass, buoyancy and
  // displaced water, so a(mu) / a(0) = 1 - mu / tan(theta) whatever they are.
  const double free_acceleration = fitted_acceleration(free);
  add_check(result, "a(mu = 0.2) / a(mu = 0)", "-", measured / free_acceleration, ratio,
            0.02 * ratio);
  // (3) mu = 0.6 > tan(theta): the block stays put.
  double largest = stays.travel.empty() ? NAN : 0.0;
  for (double s : stays.travel) largest = std::isfinite(s) ? std::max(largest, std::abs(s)) : NAN;
  add_check(result, "largest travel along the incline, mu = 0.6", "mm", 1000.0 * largest, 0.0, 1.0);

  std::vector<std::vector<double>> rows;
  for (std::size_t i = 0; i < slides.time.size(); ++i) {
    const double t = slides.time[i];
    rows.push_back({t, slides.travel[i], 0.5 * acceleration * t * t,
                    i < free.travel.size() ? free.travel[i] : NAN,
                    0.5 * reduced_g * std::sin(theta) * t * t,
                    i < stays.travel.size() ? stays.travel[i] : NAN});
  }
  const auto csv = context.work / "travel.csv";
  write_csv(csv, "time,travel,exact_travel,travel_free,exact_travel_free,travel_hold", rows);
  post::plot_xy(context.work / "travel.png",
                "Saturated block under water on a 25 degree incline: travel along the slope",
                "time (s)", "travel (m)",
                {{csv, 1, 2, "Lituya, mu = 0.2", true},
                 {csv, 1, 3, "(1 - rho_w/rho_s) g (sin - mu cos) t^2 / 2"},
                 {csv, 1, 4, "Lituya, mu = 0", true},
                 {csv, 1, 5, "(1 - rho_w/rho_s) g sin t^2 / 2"},
                 {csv, 1, 6, "Lituya, mu = 0.6", true}});
  result.plots.push_back(std::filesystem::relative(context.work / "travel.png", context.report));
}

}  // namespace lituya::verify
