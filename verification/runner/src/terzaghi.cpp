// Terzaghi 1D consolidation: excess pore pressure isochrones and degree of consolidation
// against the series solution (verification/terzaghi/README.md).
#include <algorithm>
#include <cmath>
#include <limits>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The load rises linearly from 0 to q over the time factor T_r (the scene's ramp_time), then
// stays. A load step dq at T' leaves u = dq (u0/q) sum_m (2/Mm) sin(Mm Z) exp(-Mm^2 (T - T'))
// (Terzaghi's series); superposing the steps of the ramp (Duhamel) integrates each term in
// closed form:
//   u / u0 = sum_m (2/Mm^3) sin(Mm Z) [exp(-Mm^2 (T - min(T, T_r))) - exp(-Mm^2 T)] / T_r.
// The weight of term m at time factor T, per unit sin(Mm Z) (Mm = (2m+1) pi/2):
double ramp_term(double mm, double time_factor, double ramp_factor) {
  if (time_factor <= 0) return 0.0;
  if (ramp_factor <= 0) return 2 / mm * std::exp(-mm * mm * time_factor);  // a sudden load
  const double end = std::min(time_factor, ramp_factor);
  return 2 / (mm * mm * mm) *
         (std::exp(-mm * mm * (time_factor - end)) - std::exp(-mm * mm * time_factor)) /
         ramp_factor;
}

// Excess pore pressure / u0 at depth ratio Z = z/H and time factor T (u0: the undrained
// response to the full load q).
double pressure_ratio(double depth_ratio, double time_factor, double ramp_factor) {
  double sum = 0;
  for (int m = 0; m < 200; ++m) {
    const double mm = (2 * m + 1) * kPi / 2;
    sum += std::sin(mm * depth_ratio) * ramp_term(mm, time_factor, ramp_factor);
  }
  return sum;
}

// Depth-averaged excess pore pressure / u0 (the mean of sin(Mm Z) over the column is 1/Mm).
double mean_pressure_ratio(double time_factor, double ramp_factor) {
  double sum = 0;
  for (int m = 0; m < 200; ++m) {
    const double mm = (2 * m + 1) * kPi / 2;
    sum += ramp_term(mm, time_factor, ramp_factor) / mm;
  }
  return sum;
}

}  // namespace

void run_terzaghi(const CaseContext& context, CaseResult& result) {
  const double height = 1.0, load = 1.0e4, n = 0.4, grain = 2.0e-4, mu = 1.0e-3;
  const double youngs = 1.0e7, nu = 0.3, bulk_water = 2.15e7;
  const double oedometric = youngs * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double kappa = n * n * n * grain * grain / (150 * (1 - n) * (1 - n));
  const double storage = 1 / oedometric + n / bulk_water;
  const double cv = kappa / (mu * storage);
  const double u0 = load / (oedometric * storage);
  const double s0 = load * height / (oedometric + bulk_water / n);
  const double s_inf = load * height / oedometric;
  const double cell = context.full ? 0.025 : 0.05;
  const double ramp_time = 0.1;  // s, the traction's ramp_time in both scenes
  const double ramp_factor = cv * ramp_time / (height * height);
  // Settlement from 1D strain: s = (H / M) (q(t) - mean u) (grains incompressible), which is
  // s0 at the first instant of a sudden load and s_inf once drained.
  auto settlement_series = [&](double time_factor) {
    const double applied = load * std::min(1.0, time_factor / ramp_factor);
    return height / oedometric * (applied - u0 * mean_pressure_ratio(time_factor, ramp_factor));
  };
  // The degree of consolidation, (s - s0) / (s_inf - s0), with s0 and s_inf those of the full
  // load; before the ramp ends it also holds the growth of the load.
  auto degree = [&](double settlement) { return (settlement - s0) / (s_inf - s0); };

  const auto case_folder = run_scene(context);
  const auto liquid = read_series(case_folder, "consolidation", "liquid");
  const auto solid = read_series(case_folder, "consolidation", "points");

  // The output nearest a time factor T.
  auto nearest = [&](const std::vector<Frame>& frames, double time_factor) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < frames.size(); ++i)
      if (std::abs(frames[i].time * cv / (height * height) - time_factor) <
          std::abs(frames[best].time * cv / (height * height) - time_factor))
        best = i;
    return best;
  };

  std::vector<std::vector<double>> isochrone_rows;
  auto isochrone_error = [&](double time_factor, bool lower_half_only) {
    const Frame& f = liquid[nearest(liquid, time_factor)];
    const double t_factor = f.time * cv / (height * height);
    int c = 0;
    const auto p = read_point_array(f.file, "pressure", c);
    const auto x = read_positions(f.file);
    double squared = 0;
    int count = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
      const double y = x[3 * q + 1];
      if (y > height) continue;  // expelled water on top of the column
      const double depth_ratio = (height - y) / height;
      const double exact = u0 * pressure_ratio(depth_ratio, t_factor, ramp_factor);
      isochrone_rows.push_back({t_factor, depth_ratio, p[q] / load, exact / load});
      if (lower_half_only && depth_ratio < 0.5) continue;
      squared += std::pow((p[q] - exact) / load, 2);
      ++count;
    }
    return count ? std::sqrt(squared / count) : NAN;
  };
  add_check(result, "RMS (u - u_series) / q in the lower half at T = 0.01", "-",
            isochrone_error(0.01, true), 0.0, 0.04);
  for (double time_factor : {0.1, 0.2, 0.5})
    add_check(result, "RMS (u - u_series) / q at T = " + std::to_string(time_factor).substr(0, 3),
              "-", isochrone_error(time_factor, false), 0.0, 0.03);

  // Settlement: mean vertical displacement of the solid points that started in the top quarter
  // cell.
  std::vector<std::vector<double>> settlement_rows;
  auto settlement = [&](const Frame& f) {
    int c = 0;
    const auto u = read_point_array(f.file, "displacement", c);
    const auto x = read_positions(f.file);
    double sum = 0;
    int count = 0;
    for (std::size_t p = 0; p < x.size() / 3; ++p)
      if (x[3 * p + 1] - u[c * p + 1] > height - 0.25 * cell) {
        sum += -u[c * p + 1];
        ++count;
      }
    return count ? sum / count : NAN;
  };
  for (const Frame& f : solid) {
    const double t_factor = f.time * cv / (height * height);
    settlement_rows.push_back(
        {t_factor, degree(settlement(f)), degree(settlement_series(t_factor))});
  }
  for (double time_factor : {0.1, 0.2, 0.5}) {
    const Frame& f = solid[nearest(solid, time_factor)];
    const double t_factor = f.time * cv / (height * height);
    add_check(result,
              "degree of consolidation U at T = " + std::to_string(time_factor).substr(0, 3), "-",
              degree(settlement(f)), degree(settlement_series(t_factor)), 0.05);
  }

  std::sort(isochrone_rows.begin(), isochrone_rows.end());  // by T, then depth: clean lines
  const auto iso_csv = context.work / "isochrones.csv";
  write_csv(iso_csv, "T,depth_ratio,u_over_q,series_u_over_q", isochrone_rows);
  std::vector<post::PlotSeries> series;
  for (double time_factor : {0.01, 0.1, 0.2, 0.5}) {
    const double t_factor = liquid[nearest(liquid, time_factor)].time * cv / (height * height);
    const std::string label = "T = " + std::to_string(t_factor).substr(0, 4);
    series.push_back({iso_csv, 2, 3, label + " (points)", true, 1, t_factor});
    series.push_back({iso_csv, 2, 4, label + " (series)", false, 1, t_factor});
  }
  post::plot_xy(context.work / "isochrones.png",
                "Terzaghi consolidation: excess pore pressure isochrones", "z / H (from the top)",
                "u / q", series, true);
  const auto u_csv = context.work / "degree_of_consolidation.csv";
  write_csv(u_csv, "T,U_lituya,U_series", settlement_rows);
  post::plot_xy(context.work / "degree_of_consolidation.png",
                "Terzaghi consolidation: degree of consolidation", "T = c_v t / H^2", "U",
                {{u_csv, 1, 2, "Lituya (settlement)", true}, {u_csv, 1, 3, "series"}}, true);
  for (const char* png : {"isochrones.png", "degree_of_consolidation.png"})
    result.plots.push_back(std::filesystem::relative(context.work / png, context.report));
}

}  // namespace lituya::verify
