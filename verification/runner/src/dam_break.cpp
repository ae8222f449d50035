// Dam break on a dry frictionless bed against Ritter's shallow-water solution
// (verification/dam_break/README.md).
#include <algorithm>
#include <cmath>
#include <limits>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

namespace {
// Ritter (1892): depth at x - x_dam = xi t for a column of height h0.
double ritter_depth(double xi, double h0, double g) {
  const double c0 = std::sqrt(g * h0);
  if (xi <= -c0) return h0;
  if (xi >= 2 * c0) return 0.0;
  return (2 * c0 - xi) * (2 * c0 - xi) / (9 * g);
}
}  // namespace

void run_dam_break(const CaseContext& context, CaseResult& result) {
  const double g = 9.81, h0 = 0.2, x_dam = 1.0, bin = 0.02, length = 3.0;
  const double c0 = std::sqrt(g * h0);
  const auto case_folder = run_scene(context);
  const auto frames = read_series(case_folder, "release", "liquid");
  const Frame& last = frames.back();
  const double t = last.time;

  // Depth per bin: the top of the highest point (centre + half its spacing).
  int vc = 0;
  const auto volume = read_point_array(last.file, "volume", vc);
  const auto x = read_positions(last.file);
  const int bins = static_cast<int>(std::lround(length / bin));
  std::vector<double> depth(bins, 0.0);
  for (std::size_t p = 0; p < volume.size(); ++p) {
    const int b = std::clamp(static_cast<int>(x[3 * p] / bin), 0, bins - 1);
    depth[b] = std::max(depth[b], x[3 * p + 1] + 0.5 * std::sqrt(volume[p]));
  }
  std::vector<std::vector<double>> rows;
  double squared = 0;
  int count = 0;
  double at_dam = std::numeric_limits<double>::quiet_NaN();
  double tenth_position = std::numeric_limits<double>::quiet_NaN();
  for (int b = 0; b < bins; ++b) {
    const double xc = (b + 0.5) * bin;
    const double xi = (xc - x_dam) / t;
    const double exact = ritter_depth(xi, h0, g);
    rows.push_back({xc, depth[b], exact});
    if (std::abs(xi) <= c0) {
      squared += (depth[b] - exact) * (depth[b] - exact);
      ++count;
    }
    if (b > 0 && (b - 0.5) * bin <= x_dam && xc > x_dam) {
      // Linear interpolation between the two bin centres around the dam site.
      const double w = (x_dam - (b - 0.5) * bin) / bin;
      at_dam = (1 - w) * depth[b - 1] + w * depth[b];
    }
  }
  // Most downstream crossing of h = 0.1 h0 (interpolated between bin centres).
  for (int b = bins - 1; b > 0; --b)
    if (depth[b - 1] >= 0.1 * h0 && depth[b] < 0.1 * h0) {
      const double w = (depth[b - 1] - 0.1 * h0) / (depth[b - 1] - depth[b]);
      tenth_position = (b - 0.5 + w) * bin;
      break;
    }
  add_check(result, "depth at the dam site (Ritter 4 H / 9)", "m", at_dam, 4 * h0 / 9, 0.1 * h0);
  add_check(result, "RMS depth error over |x - x_dam| <= c0 t", "m",
            count ? std::sqrt(squared / count) : NAN, 0.0, 0.05 * h0);
  // Ritter: h = 0.1 h0 where (2 - xi/c0)^2 / 9 = 0.1, xi / c0 = 2 - sqrt(0.9).
  add_check(result, "position of h = 0.1 H, (x - x_dam) / (c0 t)", "-",
            (tenth_position - x_dam) / (c0 * t), 2 - std::sqrt(0.9), 0.15);

  const auto csv = context.work / "depth_profile.csv";
  write_csv(csv, "x,depth,ritter", rows);
  post::plot_xy(context.work / "depth_profile.png",
                "Dam break at t = " + std::to_string(t).substr(0, 4) + " s: depth against x",
                "x (m)", "depth (m)",
                {{csv, 1, 2, "Lituya (water points)", true}, {csv, 1, 3, "Ritter (1892)"}}, true);
  result.plots.push_back(
      std::filesystem::relative(context.work / "depth_profile.png", context.report));
}

}  // namespace lituya::verify
