// A saturated block on a submerged 25 degree incline: Coulomb friction on the effective normal
// stress only, a = (1 - rho_w / rho_s) g (sin - mu cos) for tan > mu, and no slide for
// tan < mu (verification/saturated_block/README.md). The same block of fine sand, whose drag
// locks grains and pore water together, checks the friction ratio a(mu) / a(0) = 1 - mu / tan
// (verification/saturated_block_fine/README.md).
#include <algorithm>
#include <cmath>

#include "case_support.hpp"
#include "incline_travel.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

namespace {

constexpr double kPi = 3.14159265358979323846;
const double kTheta = 25 * kPi / 180;
constexpr double kMuSlide = 0.2;
// Along the slope, downhill.
const double kDx = std::cos(kTheta), kDy = -std::sin(kTheta);

InclineTravel run_block(const CaseContext& context, const std::string& name,
                        const std::string& stage) {
  const std::string variant = context.full ? "full" : "quick";
  return along_slope_travel(
      run_scene(context, context.source / ("scene_" + variant + "_" + name + ".toml"),
                context.work / name),
      stage, kDx, kDy);
}

// Friction alone: the same block without friction has the same mass, buoyancy and displaced
// water, so a(mu) / a(0) = 1 - mu / tan(theta) whatever they are.
void add_friction_ratio_check(CaseResult& result, const InclineTravel& slides,
                              const InclineTravel& free) {
  const double measured = fitted_acceleration(slides) / fitted_acceleration(free);
  const double ratio = 1.0 - kMuSlide / std::tan(kTheta);
  add_check(result, "a(mu = 0.2) / a(mu = 0)", "-", measured, ratio, 0.02 * ratio);
}

// travel.csv and travel.png: each run's travel, and the closed forms where there are some
// (NAN: none).
void write_travel(const CaseContext& context, CaseResult& result, const std::string& title,
                  const InclineTravel& slides, const InclineTravel& free,
                  const InclineTravel* stays, double acceleration, double free_acceleration) {
  std::vector<std::vector<double>> rows;
  for (std::size_t i = 0; i < slides.time.size(); ++i) {
    const double t = slides.time[i];
    rows.push_back({t, slides.travel[i], 0.5 * acceleration * t * t,
                    i < free.travel.size() ? free.travel[i] : NAN, 0.5 * free_acceleration * t * t,
                    stays && i < stays->travel.size() ? stays->travel[i] : NAN});
  }
  const auto csv = context.work / "travel.csv";
  write_csv(csv, "time,travel,exact_travel,travel_free,exact_travel_free,travel_hold", rows);
  std::vector<post::PlotSeries> series = {{csv, 1, 2, "Lituya, mu = 0.2", true},
                                          {csv, 1, 4, "Lituya, mu = 0", true}};
  if (std::isfinite(acceleration)) {
    series.push_back({csv, 1, 3, "(1 - rho_w/rho_s) g (sin - mu cos) t^2 / 2"});
    series.push_back({csv, 1, 5, "(1 - rho_w/rho_s) g sin t^2 / 2"});
  }
  if (stays) series.push_back({csv, 1, 6, "Lituya, mu = 0.6", true});
  post::plot_xy(context.work / "travel.png", title, "time (s)", "travel (m)", series);
  result.plots.push_back(std::filesystem::relative(context.work / "travel.png", context.report));
}

}  // namespace

void run_saturated_block(const CaseContext& context, CaseResult& result) {
  const double g = 9.81, rho_s = 2650.0, rho_w = 1000.0;
  const double reduced_g = (1.0 - rho_w / rho_s) * g;  // gravity less buoyancy, on the grains
  const double acceleration = reduced_g * (std::sin(kTheta) - kMuSlide * std::cos(kTheta));

  const InclineTravel slides = run_block(context, "slides", "slide");
  const InclineTravel free = run_block(context, "free", "slide");
  const InclineTravel stays = run_block(context, "stays", "hold");

  // (1) The closed form; the water the grains displace (added mass) is not in it (README).
  add_check(result, "acceleration along the incline, mu = 0.2", "m/s2", fitted_acceleration(slides),
            acceleration, 0.06 * acceleration);
  // (2) Friction alone.
  add_friction_ratio_check(result, slides, free);
  // (3) mu = 0.6 > tan(theta): the block stays put.
  double largest = stays.travel.empty() ? NAN : 0.0;
  for (double s : stays.travel) largest = std::isfinite(s) ? std::max(largest, std::abs(s)) : NAN;
  add_check(result, "largest travel along the incline, mu = 0.6", "mm", 1000.0 * largest, 0.0, 1.0);

  write_travel(context, result,
               "Saturated block under water on a 25 degree incline: travel along the slope", slides,
               free, &stays, acceleration, reduced_g * std::sin(kTheta));
}

void run_saturated_block_fine(const CaseContext& context, CaseResult& result) {
  const InclineTravel slides = run_block(context, "slides", "slide");
  const InclineTravel free = run_block(context, "free", "slide");
  // The locked block displaces its whole volume: its added mass has no closed form here, so
  // only the friction ratio is checked (README.md).
  add_friction_ratio_check(result, slides, free);
  write_travel(context, result,
               "Saturated block of fine sand under water on a 25 degree incline: travel", slides,
               free, nullptr, NAN, NAN);
}

}  // namespace lituya::verify
