// Seepage through a sand column under a falling head, against the Darcy-Forchheimer (Ergun)
// drag of eqs. (23), (24) (verification/seepage/README.md).
#include <cmath>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

namespace {

struct Column {
  double length = 0.3, porosity = 0.4, grain = 1.0e-3, viscosity = 1.0e-3, density = 1000.0;
  double g = 9.81;
  // Darcy flux q = n v for a pond depth d: n rho g i = a v + b v^2, i = (L + d) / L.
  double flux(double depth) const {
    const double n = porosity;
    const double kappa = n * n * n * grain * grain / (150 * (1 - n) * (1 - n));
    const double a = n * n * viscosity / kappa;
    const double b = 1.75 * std::pow(n, 1.5) * density / std::sqrt(150 * kappa);
    const double drive = n * density * g * (length + depth) / length;
    const double v = (-a + std::sqrt(a * a + 4 * b * drive)) / (2 * b);
    return n * v;
  }
  // Pond depth after time t from d0 (RK4).
  double depth(double d0, double t) const {
    const double h = 1e-4;
    double d = d0;
    for (double s = 0; s < t - 1e-12; s += h) {
      const double step = std::min(h, t - s);
      const double k1 = -flux(d), k2 = -flux(d + 0.5 * step * k1);
      const double k3 = -flux(d + 0.5 * step * k2), k4 = -flux(d + step * k3);
      d = std::max(0.0, d + step * (k1 + 2 * k2 + 2 * k3 + k4) / 6);
    }
    return d;
  }
};

}  // namespace

void run_seepage(const CaseContext& context, CaseResult& result) {
  const double sand_top = 0.5, plate = 0.2, width = 0.1, t1 = 0.3;  // seepage.geo
  const Column column;
  const auto case_folder = run_scene(context);
  const auto frames = read_series(case_folder, "seepage", "liquid");

  // The water of each frame as depths (volume over the width): the pond above the sand, the
  // pores of the sand, and the chamber below the plate. The pond's fall is the flux the case
  // checks; the chamber's rise is the flux through the column. They agree while the sand's
  // pores stay full; where they differ, the sand has gained or lost water (README, stop 32).
  struct Depths {
    double pond = 0, sand = 0, chamber = 0;
  };
  auto depths = [&](const Frame& f) {
    int c = 0;
    const auto volume = read_point_array(f.file, "volume", c);
    const auto x = read_positions(f.file);
    Depths d;
    for (std::size_t q = 0; q < volume.size(); ++q) {
      const double y = x[3 * q + 1];
      (y > sand_top ? d.pond : y >= plate ? d.sand : d.chamber) += volume[q] / width;
    }
    return d;
  };
  std::vector<Depths> at;
  for (const Frame& f : frames) at.push_back(depths(f));
  const Depths &first = at.front(), &last = at.back();
  // Drawn, not checked: the chamber also receives what the sand's bottom loses as it drains
  // (its pores under-fill at the outflow, where the water has no tension), so its rise is no
  // cleaner a measure of the flux than the pond's fall (README, stop 32).
  const double d0 = first.pond;
  std::vector<std::vector<double>> rows;
  Depths at_t1{NAN, NAN, NAN};
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const Depths& d = at[k];
    const double ergun = column.depth(d0, frames[k].time);
    rows.push_back({frames[k].time, d.pond, ergun, d.chamber, d0 - ergun, d.sand - first.sand});
    if (std::abs(frames[k].time - t1) < 1e-6) at_t1 = d;
  }
  const double t_end = frames.back().time;
  const double reference_flux = (column.depth(d0, t1) - column.depth(d0, t_end)) / (t_end - t1);
  add_check(result, "mean Darcy flux over 0.3 s to the end / Ergun value", "-",
            (at_t1.pond - last.pond) / (t_end - t1) / reference_flux, 1.0, 0.10);
  const double reference_end = column.depth(d0, t_end);
  add_check(result, "pond depth at the end", "m", last.pond, reference_end,
            0.1 * (d0 - reference_end));

  const auto csv = context.work / "pond_depth.csv";
  write_csv(csv, "time,pond_depth,ergun,chamber_depth,ergun_outflow,sand_water_change", rows);
  post::plot_xy(context.work / "pond_depth.png",
                "Seepage through a sand column: the pond above it, the chamber below", "time (s)",
                "water depth (m)",
                {{csv, 1, 2, "pond, Lituya", true},
                 {csv, 1, 3, "pond, Darcy-Forchheimer (Ergun)"},
                 {csv, 1, 4, "chamber, Lituya", true},
                 {csv, 1, 5, "chamber, Ergun (the pond's fall)"},
                 {csv, 1, 6, "water gained by the sand", true}});
  result.plots.push_back(
      std::filesystem::relative(context.work / "pond_depth.png", context.report));
}

}  // namespace lituya::verify
