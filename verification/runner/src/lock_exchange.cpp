// Lock exchange: a saturated, strengthless fine soil released into water runs along the bed as
// a heavy fluid, against the energy-conserving front speed (verification/lock_exchange/README.md).
#include "case_support.hpp"
#include "lituya/post/plot.hpp"
#include "lock_exchange_measure.hpp"
#include "standing_wave_measure.hpp"

namespace lituya::verify {

namespace {

// The scenes' set-up (lock_exchange.geo, scene_*.toml).
constexpr double kGravity = 9.81, kDepth = 0.2, kGate = 0.2;
constexpr double kGrainDensity = 1200.0, kPorosity = 0.4, kWaterDensity = 1000.0;
// The current's front is read below a quarter of the depth; the speed over 0.3-0.7 m from the
// channel's end (a half to two and a half lock lengths past the gate), after the release's
// start-up and long before the bore reflected from the end wall catches the front (more than
// five lock lengths in lock-exchange experiments).
constexpr double kFrontBelow = kDepth / 4, kWindowLow = 0.3, kWindowHigh = 0.7;

// The height of the volume centroid of everything the points fill: grains (mass over grain
// density) and water (the liquid points' volumes). In a full channel with a level surface it is
// half the surface's height whatever the two fluids do, so its drift measures points that crowd
// or leave gaps.
double volume_centroid(const Frame& solid, const Frame& liquid) {
  int c = 0;
  std::vector<double> positions = read_positions(solid.file);
  std::vector<double> volumes = read_point_array(solid.file, "mass", c);
  for (double& v : volumes) v /= kGrainDensity;
  const std::vector<double> xl = read_positions(liquid.file),
                            vl = read_point_array(liquid.file, "volume", c);
  positions.insert(positions.end(), xl.begin(), xl.end());
  volumes.insert(volumes.end(), vl.begin(), vl.end());
  return volume_centroid_height(positions, volumes);
}

// Runs one scene into <work>/<label>, adds its two checks (labelled with the cell size), writes
// the front's record and plot; returns the front speed over the reference speed.
double run_one(const CaseContext& context, const std::string& scene_name, const std::string& label,
               double cell_size, CaseResult& result) {
  const double mixture = (1 - kPorosity) * kGrainDensity + kPorosity * kWaterDensity;
  const double reference = lock_exchange_speed(kGravity, kDepth, mixture, kWaterDensity);
  const auto folder = context.work / label;
  const auto case_folder = run_scene(context, context.source / scene_name, folder / "case");
  const auto solid = read_series(case_folder, "release", "points");
  const auto liquid = read_series(case_folder, "release", "liquid");

  std::vector<double> times, fronts;
  std::vector<std::vector<double>> rows;
  for (const Frame& f : solid) {
    times.push_back(f.time);
    fronts.push_back(current_front(read_positions(f.file), kFrontBelow, 2));
    rows.push_back({f.time, fronts.back(), kGate + reference * f.time});
  }
  const std::string at = cell_size_tag(cell_size);
  const double ratio = front_speed(times, fronts, kWindowLow, kWindowHigh) / reference;
  add_check(result, "front speed over x = 0.3-0.7 m / energy-conserving lock exchange" + at, "-",
            ratio, 1.0, 0.10);
  const double drift =
      volume_centroid(solid.back(), liquid.back()) - volume_centroid(solid.front(), liquid.front());
  add_check(result, "drift of the height of the points' volume centroid by the end" + at, "mm",
            1000 * drift, 0.0, 1.0);

  const auto csv = folder / "front.csv";
  write_csv(csv, "time,front,energy_conserving", rows);
  post::plot_xy(folder / "front.png",
                "Lock exchange" + at + ": the heavy current's front along the bed", "time (s)",
                "front position x (m)",
                {{csv, 1, 2, "Lituya", true}, {csv, 1, 3, "U = sqrt(g' H) / 2 from the gate"}});
  result.plots.push_back(std::filesystem::relative(folder / "front.png", context.report));
  return ratio;
}

}  // namespace

void run_lock_exchange(const CaseContext& context, CaseResult& result) {
  run_at_cell_sizes(context, result, {0.02, 0.01, 0.0075}, "the front speed", 0.05, run_one);
}

}  // namespace lituya::verify
