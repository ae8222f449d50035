#include "dam_break_measure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "case_support.hpp"

namespace lituya::verify {

double ritter_depth(double xi, double h0, double g) {
  const double c0 = std::sqrt(g * h0);
  if (xi <= -c0) return h0;
  if (xi >= 2 * c0) return 0.0;
  return (2 * c0 - xi) * (2 * c0 - xi) / (9 * g);
}

DamBreakMeasure measure_dam_break(const std::vector<double>& positions,
                                  const std::vector<double>& volumes, double t,
                                  const DamBreakSetup& setup) {
  const double g = setup.g, h0 = setup.h0, x_dam = setup.x_dam, bin = setup.bin;
  const double c0 = std::sqrt(g * h0);
  DamBreakMeasure m;
  m.time = t;
  m.depth_at_dam = std::numeric_limits<double>::quiet_NaN();
  m.tenth_position = std::numeric_limits<double>::quiet_NaN();

  // Depth per bin: the top of the highest point (centre + half its spacing).
  const int bins = static_cast<int>(std::lround(setup.length / bin));
  std::vector<double> depth(bins, 0.0);
  for (std::size_t p = 0; p < volumes.size(); ++p) {
    const int b = std::clamp(static_cast<int>(positions[3 * p] / bin), 0, bins - 1);
    depth[b] = std::max(depth[b], positions[3 * p + 1] + 0.5 * std::sqrt(volumes[p]));
  }
  double squared = 0;
  int count = 0;
  for (int b = 0; b < bins; ++b) {
    const double xc = (b + 0.5) * bin;
    const double xi = (xc - x_dam) / t;
    const double exact = ritter_depth(xi, h0, g);
    m.profile.push_back({xc, depth[b], exact});
    if (std::abs(xi) <= c0) {
      squared += (depth[b] - exact) * (depth[b] - exact);
      ++count;
    }
    if (b > 0 && (b - 0.5) * bin <= x_dam && xc > x_dam) {
      // Linear interpolation between the two bin centres around the dam site.
      const double w = (x_dam - (b - 0.5) * bin) / bin;
      m.depth_at_dam = (1 - w) * depth[b - 1] + w * depth[b];
    }
  }
  m.rms_error = count ? std::sqrt(squared / count) : std::numeric_limits<double>::quiet_NaN();
  // Most downstream crossing of h = 0.1 h0 (interpolated between bin centres).
  for (int b = bins - 1; b > 0; --b)
    if (depth[b - 1] >= 0.1 * h0 && depth[b] < 0.1 * h0) {
      const double w = (depth[b - 1] - 0.1 * h0) / (depth[b - 1] - depth[b]);
      m.tenth_position = ((b - 0.5 + w) * bin - x_dam) / (c0 * t);
      break;
    }
  return m;
}

DamBreakMeasure measure_dam_break(const std::filesystem::path& case_folder,
                                  const DamBreakSetup& setup) {
  const auto frames = read_series(case_folder, "release", "liquid");
  const Frame& last = frames.back();
  int components = 0;
  const auto volume = read_point_array(last.file, "volume", components);
  return measure_dam_break(read_positions(last.file), volume, last.time, setup);
}

}  // namespace lituya::verify
