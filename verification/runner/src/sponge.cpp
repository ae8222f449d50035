// A long wave leaving a tank through a sponge zone, and the same tank without one
// (verification/sponge/README.md): the reflection coefficient at a gauge between the wave's
// source and the tank end.
#include <algorithm>
#include <cmath>
#include <limits>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"
#include "lituya/pre/preprocess.hpp"
#include "lituya/solver/solve.hpp"

namespace lituya::verify {

namespace {
// The tank of tank.geo and the gauge (README.md).
constexpr double kGravity = 9.81, kDepth = 0.15;
constexpr double kGauge = 1.2;  // m, gauge position, past the initial wavelet (x < 0.9 m)
// m, half-widths of the gauge's averaging hat: the narrow one for the incident crest height,
// the wide one, as long as the short-wave noise on the surface (README.md), for the reflection.
constexpr double kCrestKernel = 0.1, kKernel = 0.3;
// s, the window of the running mean taken off the difference of two records: long beside the
// wave (about 2 s at the gauge), short beside the slow change of the level that the wave's net
// volume makes in a closed tank (README.md).
constexpr double kMeanWindow = 3.0;

struct Record {
  // s; m above the still water depth at t = 0, read with the narrow and the wide hat.
  std::vector<double> time, crest_elevation, elevation;
};

// Water depth at the gauge from the water volume around it: sum_q V_q K(x_q - x_g), with K the
// hat of half-width `kernel` and unit integral. In 2D a point's volume is an area per metre, so
// the sum is a depth; a point moving across the hat changes it continuously (a box bin would
// jump by a whole point's volume).
double gauge_depth(const std::vector<double>& volume, const std::vector<double>& x, double kernel) {
  double depth = 0;
  for (std::size_t q = 0; q < volume.size(); ++q) {
    const double r = std::abs(x[3 * q] - kGauge) / kernel;
    if (r < 1) depth += volume[q] * (1 - r) / kernel;
  }
  return depth;
}

Record run_tank(const CaseContext& context, const std::string& scene, const std::string& name) {
  const auto case_folder = run_scene(context, context.source / scene, context.work / name / "case");
  Record record;
  double still_crest = 0, still = 0;  // t = 0: the still water, before the wave arrives
  for (const Frame& frame : read_series(case_folder, "release", "liquid")) {
    int components = 0;
    const std::vector<double> volume = read_point_array(frame.file, "volume", components);
    const std::vector<double> x = read_positions(frame.file);
    const double crest_depth = gauge_depth(volume, x, kCrestKernel);
    const double depth = gauge_depth(volume, x, kKernel);
    if (record.time.empty()) {
      still_crest = crest_depth;
      still = depth;
    }
    record.time.push_back(frame.time);
    record.crest_elevation.push_back(crest_depth - still_crest);
    record.elevation.push_back(depth - still);
  }
  return record;
}

// What a tank end sends back: d = run - reference (wide hat), less d's running mean over
// kMeanWindow (the slow change of the level, not a wave); the largest |d - mean| where the
// window lies inside the run, over the incident crest height read with the same hat.
double reflection(const Record& run, const Record& reference, double incident) {
  const std::size_t n = std::min(run.time.size(), reference.time.size());
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> d(n);
  for (std::size_t k = 0; k < n; ++k) d[k] = run.elevation[k] - reference.elevation[k];
  const double interval = (run.time[n - 1] - run.time[0]) / static_cast<double>(n - 1);
  const auto half = static_cast<std::size_t>(std::lround(0.5 * kMeanWindow / interval));
  double reflected = 0;
  for (std::size_t k = half; k + half < n; ++k) {
    double mean = 0;
    for (std::size_t j = k - half; j <= k + half; ++j) mean += d[j];
    mean /= static_cast<double>(2 * half + 1);
    reflected = std::max(reflected, std::abs(d[k] - mean));
  }
  return reflected / incident;
}
}  // namespace

void run_sponge(const CaseContext& context, CaseResult& result) {
  const std::string variant = context.full ? "full" : "quick";
  const Record sponge = run_tank(context, "scene_" + variant + ".toml", "sponge");
  const Record wall = run_tank(context, "scene_" + variant + "_wall.toml", "wall");
  const Record reference = run_tank(context, "scene_" + variant + "_long.toml", "long");

  // The incident wave reaches 0.9 m each side of its centre (x = 0 at the release): its tail
  // has passed the gauge by (x_g + 0.9) / c, c = sqrt(g h); its crest is the long tank's
  // highest elevation before then. A reflection is any difference from the long tank's record
  // (the same mesh up to x = 3.1 m), whose end the wave does not reach before the run ends.
  const double c = std::sqrt(kGravity * kDepth);
  const double t_passed = (kGauge + 0.9) / c;
  double crest = 0, incident = 0;
  for (std::size_t k = 0; k < reference.time.size(); ++k)
    if (reference.time[k] < t_passed) {
      crest = std::max(crest, reference.crest_elevation[k]);
      incident = std::max(incident, reference.elevation[k]);
    }
  const double r_sponge = reflection(sponge, reference, incident);
  const double r_wall = reflection(wall, reference, incident);
  // Tolerances and why: README.md.
  add_check(result, "incident crest height at the gauge, linear theory a / 2", "m", crest, 0.02,
            0.01);
  add_check(result, "reflection without the sponge (end wall), reflected / incident height", "-",
            r_wall, 1.0, 0.5);
  add_check(result, "reflection with the sponge, reflected / incident height", "-", r_sponge, 0.0,
            0.10);

  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0;
       k < std::min({sponge.time.size(), wall.time.size(), reference.time.size()}); ++k)
    rows.push_back({sponge.time[k], sponge.elevation[k], wall.elevation[k], reference.elevation[k],
                    sponge.elevation[k] - reference.elevation[k],
                    wall.elevation[k] - reference.elevation[k]});
  const auto csv = context.work / "gauge.csv";
  write_csv(csv,
            "time,elevation_sponge,elevation_wall,elevation_long_tank,sponge_minus_long,"
            "wall_minus_long",
            rows);
  const auto png = context.work / "gauge.png";
  post::plot_xy(png, "Water surface at x = 1.2 m: a wave out through a sponge, and off a wall",
                "time (s)", "surface elevation (m)",
                {{csv, 1, 2, "with the sponge (x = 1.6 to 3.1 m)"},
                 {csv, 1, 3, "without (end wall at x = 3.1 m)"},
                 {csv, 1, 4, "10 m tank (the wave does not reach its end)"}});
  result.plots.push_back(std::filesystem::relative(png, context.report));
  const auto difference_png = context.work / "difference.png";
  post::plot_xy(difference_png, "What the tank end sends back to x = 1.2 m: run - 10 m tank",
                "time (s)", "elevation difference (m)",
                {{csv, 1, 5, "with the sponge"}, {csv, 1, 6, "without (end wall)"}});
  result.plots.push_back(std::filesystem::relative(difference_png, context.report));
}

}  // namespace lituya::verify
