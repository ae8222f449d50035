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
#include "lituya/sweep/measures.hpp"

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

// The mean of the history columns `columns` of a run's stage over the stage times [from, to]:
// each row holds the mean force since the row before, so the rows are weighted by their
// intervals (probe_recorder.cpp).
std::vector<double> mean_history(const std::filesystem::path& case_folder, const std::string& stage,
                                 const std::vector<std::string>& columns, double from, double to) {
  const auto file = (case_folder / "output" / (stage + "_history.csv")).string();
  const sweep::CsvTable table = sweep::read_csv(file, true);  // the `stage` column is text
  const std::vector<double> time = table.column("stage_time", file);
  std::vector<double> means;
  for (const std::string& name : columns) {
    const std::vector<double> values = table.column(name, file);
    double sum = 0, weight = 0, previous = 0;
    for (std::size_t r = 0; r < time.size(); ++r) {
      const double span = std::min(time[r], to) - std::max(previous, from);
      previous = time[r];
      if (!(span > 0)) continue;
      sum += span * values[r];
      weight += span;
    }
    means.push_back(weight > 0 ? sum / weight : NAN);
  }
  return means;
}

// The bed's own forces on the block of fine sand (the `friction` contact wall's columns of the
// slide history; wall_loads.cpp), against the closed form of the README: Coulomb friction on
// the effective normal force, and that force the buoyant weight's component normal to the
// slope. Its tolerance, 2.66 %, is the friction error that would move the friction ratio by
// its own 2 %: 0.02 x 0.5711 / (0.2 / tan(25 deg)).
void add_bed_force_checks(const CaseContext& context, CaseResult& result, double duration) {
  const double g = 9.81, rho_sat = 0.6 * 2650.0 + 0.4 * 1000.0, rho_w = 1000.0;
  const double block_area = 0.8 * 0.06;  // m2 per metre of width
  const double buoyant_normal = (rho_sat - rho_w) * g * block_area * std::cos(kTheta);
  const double tolerance =
      0.02 * (1.0 - kMuSlide / std::tan(kTheta)) / (kMuSlide / std::tan(kTheta));
  const std::vector<std::string> columns = {"wall_friction_tangential",
                                            "wall_friction_effective_normal"};
  const auto run = context.work / "slides";
  const auto whole = mean_history(run, "slide", columns, 0, duration);
  add_check(result, "bed friction / (mu x effective normal force), over the slide", "-",
            whole[0] / (kMuSlide * whole[1]), 1.0, 0.01);
  const auto first = mean_history(run, "slide", columns, 0, 0.1 * duration);
  add_check(result, "effective normal force on the bed, first tenth of the slide", "N/m", first[1],
            buoyant_normal, tolerance * buoyant_normal);
  // While it slides the block goes deeper and its pore water must flow in to follow the rising
  // pressure around it: the continuum lags at the bed by 25.1 Pa after 0.3 s and 43.0 Pa after
  // 0.5 s (consolidation_lag.py), which adds that times the block's length to the effective
  // normal force.
  const double lag = context.full ? 43.0 : 25.1;
  const auto last = mean_history(run, "slide", columns, 0.9 * duration, duration);
  add_check(result, "effective normal force on the bed, last tenth of the slide", "N/m", last[1],
            buoyant_normal + lag * 0.8, tolerance * (buoyant_normal + lag * 0.8));
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
  add_bed_force_checks(context, result, context.full ? 0.5 : 0.3);
  write_travel(context, result,
               "Saturated block of fine sand under water on a 25 degree incline: travel", slides,
               free, nullptr, NAN, NAN);
}

}  // namespace lituya::verify
