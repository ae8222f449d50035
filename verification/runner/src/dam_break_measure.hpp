#pragma once
// The dam break's measures against Ritter's solution (verification/dam_break/README.md), shared
// by the dam_break case and the speed/accuracy study built on it (verification/speed_accuracy).
#include <filesystem>
#include <vector>

namespace lituya::verify {

// The dam break of verification/dam_break: column height, dam site, channel length, the
// width of the depth bins, gravity.
struct DamBreakSetup {
  double g = 9.81, h0 = 0.2, x_dam = 1.0, length = 3.0, bin = 0.02;
};

// Ritter (1892): depth at x - x_dam = xi t for a column of height h0.
double ritter_depth(double xi, double h0, double g);

struct DamBreakMeasure {
  double time = 0;            // s, of the frame measured
  double depth_at_dam = 0;    // m, interpolated between the bins around the dam site
  double rms_error = 0;       // m, over the bins with |x - x_dam| <= c0 t
  double tenth_position = 0;  // (x - x_dam) / (c0 t) where h = 0.1 h0 (most downstream crossing)
  std::vector<std::vector<double>> profile;  // per bin: x, depth, Ritter's depth
};

// The measures from the liquid points at time t: positions (3 per point) and volumes. The depth
// of a bin is the top of its highest point (centre + half its spacing); an empty bin is 0 deep.
DamBreakMeasure measure_dam_break(const std::vector<double>& positions,
                                  const std::vector<double>& volumes, double t,
                                  const DamBreakSetup& setup = {});

// The same from the last frame of the case's "release" liquid series.
DamBreakMeasure measure_dam_break(const std::filesystem::path& case_folder,
                                  const DamBreakSetup& setup = {});

}  // namespace lituya::verify
