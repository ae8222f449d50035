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
  const double sand_top = 0.5, width = 0.1, t1 = 0.3;
  const Column column;
  const auto case_folder = run_scene(context);
  const auto frames = read_series(case_folder, "seepage", "liquid");

  // Pond depth: water volume above the sand surface over the width.
  auto pond_depth = [&](const Frame& f) {
    int c = 0;
    const auto volume = read_point_array(f.file, "volume", c);
    const auto x = read_positions(f.file);
    double sum = 0;
    for (std::size_t q = 0; q < volume.size(); ++q)
      if (x[3 * q + 1] > sand_top) sum += volume[q];
    return sum / width;
  };
  const double d0 = pond_depth(frames.front());
  std::vector<std::vector<double>> rows;
  double d_t1 = NAN, d_end = pond_depth(frames.back());
  for (const Frame& f : frames) {
    const double d = pond_depth(f);
    rows.push_back({f.time, d, column.depth(d0, f.time)});
    if (std::abs(f.time - t1) < 1e-6) d_t1 = d;
  }
  const double t_end = frames.back().time;
  const double measured_flux = (d_t1 - d_end) / (t_end - t1);
  const double reference_flux = (column.depth(d0, t1) - column.depth(d0, t_end)) / (t_end - t1);
  add_check(result, "mean Darcy flux over 0.3 s to the end / Ergun value", "-",
            measured_flux / reference_flux, 1.0, 0.10);
  const double reference_end = column.depth(d0, t_end);
  add_check(result, "pond depth at the end", "m", d_end, reference_end, 0.1 * (d0 - reference_end));

  const auto csv = context.work / "pond_depth.csv";
  write_csv(csv, "time,pond_depth,ergun", rows);
  post::plot_xy(context.work / "pond_depth.png",
                "Seepage through a sand column: depth of the pond above it", "time (s)",
                "pond depth (m)",
                {{csv, 1, 2, "Lituya", true}, {csv, 1, 3, "Darcy-Forchheimer (Ergun)"}});
  result.plots.push_back(
      std::filesystem::relative(context.work / "pond_depth.png", context.report));
}

}  // namespace lituya::verify
