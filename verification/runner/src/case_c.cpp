// Case C of the reference paper: the leading wave raised by a dry or saturated slide on a
// rigid or erodible slope, four runs compared (verification/case_c/README.md).
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"
#include "lituya/post/postprocess.hpp"
#include "lituya/pre/preprocess.hpp"
#include "lituya/solver/solve.hpp"

namespace lituya::verify {

namespace {

struct Run {
  const char* name;   // scene_<variant>_<name>.toml, and the work sub-folder
  const char* label;  // for plots
};
constexpr Run kRuns[] = {{"rigid_dry", "rigid slope, dry slide"},
                         {"rigid_saturated", "rigid slope, saturated slide"},
                         {"erodible_dry", "erodible slope, dry slide"},
                         {"erodible_saturated", "erodible slope, saturated slide"}};

constexpr double kStillWater = 0.15;  // m
constexpr double kMinCrest = 0.005;   // m, as leading_wave_min_height in the scenes

struct Measured {
  double h05 = NAN;        // mean leading-crest height over [0.45, 0.55] s
  double peak = NAN;       // highest leading crest in the first 0.8 s
  double peak_time = NAN;  // its time
};

// Liquid points (by index in liquid_points.vtu) that start as free water: those that do not
// sit on a solid point. The pore water of a saturated region is seeded at the positions of
// its solid points (file-formats manual).
std::vector<bool> free_water(const std::filesystem::path& case_folder) {
  const std::vector<double> solid = read_positions(case_folder / "points.vtu");
  const std::vector<double> liquid = read_positions(case_folder / "liquid_points.vtu");
  std::set<std::pair<double, double>> occupied;
  for (std::size_t p = 0; 3 * p < solid.size(); ++p)
    occupied.insert({solid[3 * p], solid[3 * p + 1]});
  std::vector<bool> free(liquid.size() / 3);
  for (std::size_t q = 0; q < free.size(); ++q)
    free[q] = occupied.count({liquid[3 * q], liquid[3 * q + 1]}) == 0;
  return free;
}

post::PointCloud select(const post::PointCloud& all, const std::vector<bool>& keep_id) {
  post::PointCloud out;
  out.dimension = all.dimension;
  for (std::size_t i = 0; i < all.position.size(); ++i) {
    const int id = all.id.at(i);
    if (id < 0 || id >= static_cast<int>(keep_id.size()) || !keep_id[id]) continue;
    out.position.push_back(all.position[i]);
    out.id.push_back(id);
    if (!all.material.empty()) out.material.push_back(all.material[i]);
    if (!all.volume.empty()) out.volume.push_back(all.volume[i]);
    if (!all.porosity.empty()) out.porosity.push_back(all.porosity[i]);
  }
  return out;
}

// pre + solve + post of one run; then the leading wave of the free water (the post's tracker,
// on the liquid points that started as free water), written to
// <work>/<run>/leading_wave_free_water.csv.
Measured run_one(const CaseContext& context, const Run& run) {
  const std::string variant = context.full ? "full" : "quick";
  const auto scene = context.source / ("scene_" + variant + "_" + run.name + ".toml");
  const auto folder = context.work / run.name;
  const auto case_folder = run_scene(context, scene, folder / "case");
  const post::PostResult r = post::postprocess(case_folder, folder / "post", /*overwrite=*/true);
  const post::PostSettings settings = post::read_post_settings(case_folder / "post.toml");

  const std::vector<bool> free = free_water(case_folder);
  const std::string liquid_stage =
      settings.liquid_stage.empty() ? settings.stage : settings.liquid_stage;
  // The whole record first: the leading wave is tracked from output to output.
  std::vector<double> times;
  std::vector<std::vector<post::SurfaceBin>> profiles;
  double depth = NAN;  // of the lake at rest, from the first output with free water
  for (const auto& entry :
       post::read_pvd(case_folder / "output" / (liquid_stage + "_liquid.pvd"))) {
    const post::PointCloud water = select(post::read_liquid_points(entry.file, 2), free);
    if (std::isnan(depth)) depth = post::still_water_depth(water, kStillWater);
    times.push_back(entry.time);
    profiles.push_back(post::surface_profile(water, settings.leading_wave_start,
                                             2 * r.gauge_half_width, kStillWater));
  }
  const std::vector<post::LeadingWave> waves =
      post::track_leading_wave(times, profiles, settings.leading_wave_start, kMinCrest, depth,
                               post::case_gravity(case_folder));

  std::vector<std::vector<double>> rows;
  Measured m;
  double sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < waves.size(); ++k) {
    const post::LeadingWave& wave = waves[k];
    rows.push_back({times[k], wave.crest_x, wave.crest_eta, wave.max_eta});
    if (!std::isfinite(wave.crest_eta)) continue;
    if (times[k] >= 0.45 - 1e-9 && times[k] <= 0.55 + 1e-9) {
      sum += wave.crest_eta;
      ++count;
    }
    if (times[k] <= 0.8 + 1e-9 && !(wave.crest_eta <= m.peak)) {
      m.peak = wave.crest_eta;
      m.peak_time = times[k];
    }
  }
  if (count > 0) m.h05 = sum / count;
  write_csv(folder / "leading_wave_free_water.csv", "time,crest_x,crest_height,max_eta", rows);
  return m;
}

double percent_higher(double high, double low) {
  return 100.0 * (high - low) / low;
}

}  // namespace

void run_case_c(const CaseContext& context, CaseResult& result) {
  Measured m[4];
  for (int i = 0; i < 4; ++i) m[i] = run_one(context, kRuns[i]);
  const Measured &rigid_dry = m[0], &rigid_saturated = m[1], &erodible_dry = m[2],
                 &erodible_saturated = m[3];

  add_check(result, "leading wave at 0.5 s: erodible over rigid, dry slide", "%",
            percent_higher(erodible_dry.h05, rigid_dry.h05), 27.5, 15.0);
  add_check(result, "leading wave at 0.5 s: erodible over rigid, saturated slide", "%",
            percent_higher(erodible_saturated.h05, rigid_saturated.h05), 50.0, 50.0);
  add_check(result, "leading wave at 0.5 s: saturated over dry, rigid slope", "%",
            percent_higher(rigid_saturated.h05, rigid_dry.h05), 50.0, 50.0);
  add_check(result, "leading wave at 0.5 s: saturated over dry, erodible slope", "%",
            percent_higher(erodible_saturated.h05, erodible_dry.h05), 50.0, 50.0);
  for (int i = 0; i < 4; ++i)
    add_check(result, std::string("time of the highest leading crest, ") + kRuns[i].label, "s",
              m[i].peak_time, 0.45, 0.15);

  std::vector<std::vector<double>> rows;
  for (int i = 0; i < 4; ++i) rows.push_back({double(i), m[i].h05, m[i].peak, m[i].peak_time});
  write_csv(context.work / "leading_wave_summary.csv",
            "run(0=rigid_dry;1=rigid_saturated;2=erodible_dry;3=erodible_saturated),"
            "height_at_0.5s,peak_height,peak_time",
            rows);

  std::vector<post::PlotSeries> waves, gauges;
  for (int i = 0; i < 4; ++i) {
    const auto folder = context.work / kRuns[i].name;
    waves.push_back({folder / "leading_wave_free_water.csv", 1, 3, kRuns[i].label});
    const auto gauge_csv = folder / "post" / "gauges.csv";
    if (std::filesystem::exists(gauge_csv))
      gauges.push_back({gauge_csv, 1, post::csv_column(gauge_csv, "X0"), kRuns[i].label});
  }
  const auto wave_png = context.work / "leading_wave.png";
  if (post::plot_xy(wave_png, "Case C: leading wave height (free water)", "time (s)",
                    "leading crest height (m)", waves, /*y_from_zero=*/true))
    result.plots.push_back(std::filesystem::relative(wave_png, context.report));
  const auto gauge_png = context.work / "gauge_X0.png";
  if (!gauges.empty() && post::plot_xy(gauge_png, "Case C: water surface at X = 0", "time (s)",
                                       "surface elevation (m)", gauges))
    result.plots.push_back(std::filesystem::relative(gauge_png, context.report));
}

}  // namespace lituya::verify
