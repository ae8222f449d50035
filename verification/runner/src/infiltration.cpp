// Infiltration of a pond into dry sand, against Green and Ampt's sharp-front solution with the
// drag of eqs. (23), (24) (verification/infiltration/README.md).
#include <cmath>

#include "case_support.hpp"
#include "green_ampt.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

namespace {

// The water of a frame: its points' positions (3 per point) and volumes.
struct Water {
  std::vector<double> position, volume;
};

Water water_of(const Frame& f) {
  int c = 0;
  return Water{read_positions(f.file), read_point_array(f.file, "volume", c)};
}

// Volume per unit width (m) of the water with y in [low, high).
double depth_between(const Water& w, double low, double high) {
  constexpr double kWidth = 0.1;  // infiltration.geo
  double sum = 0;
  for (std::size_t q = 0; q < w.volume.size(); ++q) {
    const double y = w.position[3 * q + 1];
    if (y >= low && y < high) sum += w.volume[q];
  }
  return sum / kWidth;
}

// Runs one scene into <work>/<label>, adds its three checks (labelled with the cell size),
// writes its records and plots; returns the water in the sand at the end over the reference.
double run_one(const CaseContext& context, const std::string& scene_name, const std::string& label,
               double cell_size, CaseResult& result) {
  const double sand_top = 0.3, t_rate = 0.5, band = 0.01;  // infiltration.geo, README
  const GreenAmptColumn reference;  // the scene's sand (n = 0.4, D_p = 1 mm) and water
  const double n = reference.sand.porosity;
  const auto folder = context.work / label;
  const auto case_folder = run_scene(context, context.source / scene_name, folder / "case");
  const auto frames = read_series(case_folder, "infiltration", "liquid");

  std::vector<double> times, infiltrated, pond;
  Water end;  // the last frame's, for the checks and the profile at the end
  for (const Frame& f : frames) {
    end = water_of(f);
    times.push_back(f.time);
    infiltrated.push_back(depth_between(end, -1, sand_top));
    pond.push_back(depth_between(end, sand_top, 1e9));
  }
  const double d0 = pond.front() + infiltrated.front();
  const std::vector<double> front = reference.front_depth(d0, times, sand_top);

  std::vector<std::vector<double>> rows;
  std::size_t k_rate = 0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    rows.push_back({times[k], infiltrated[k], n * front[k], pond[k],
                    reference.pond_depth(d0, front[k]), front[k]});
    if (std::abs(times[k] - t_rate) < 1e-6) k_rate = k;
  }
  const std::size_t last = times.size() - 1;
  const std::string at = cell_size_tag(cell_size);
  const double infiltrated_ratio = infiltrated[last] / (n * front[last]);
  add_check(result, "water infiltrated by the end / Green-Ampt with Ergun's drag" + at, "-",
            infiltrated_ratio, 1.0, 0.05);
  const double rate = (infiltrated[last] - infiltrated[k_rate]) / (times[last] - times[k_rate]);
  const double rate_reference = n * (front[last] - front[k_rate]) / (times[last] - times[k_rate]);
  add_check(result, "mean infiltration rate over 0.5 s to the end / reference" + at, "-",
            rate / rate_reference, 1.0, 0.10);
  const double wetted = front[last];
  add_check(result, "water / pores in the upper half of the wetted zone at the end" + at, "-",
            depth_between(end, sand_top - wetted / 2, sand_top) / (n * wetted / 2), 1.0, 0.05);

  const auto csv = folder / "infiltration.csv";
  write_csv(csv, "time,infiltrated,green_ampt,pond_depth,green_ampt_pond,green_ampt_front", rows);
  post::plot_xy(folder / "infiltration.png",
                "Infiltration into dry sand" + at + ": water in the sand and in the pond",
                "time (s)", "water depth (m)",
                {{csv, 1, 2, "in the sand, Lituya", true},
                 {csv, 1, 3, "in the sand, Green-Ampt with Ergun's drag"},
                 {csv, 1, 4, "pond, Lituya", true},
                 {csv, 1, 5, "pond, Green-Ampt"}});
  result.plots.push_back(std::filesystem::relative(folder / "infiltration.png", context.report));

  // The water content at the end in bands 1 cm deep, against the sharp front.
  std::vector<std::vector<double>> profile;
  const int bands = static_cast<int>(std::lround(sand_top / band));
  for (int k = 0; k < bands; ++k) {
    const double top = sand_top - k * band, depth = (k + 0.5) * band;
    profile.push_back(
        {depth, depth_between(end, top - band, top) / (n * band), depth < wetted ? 1.0 : 0.0});
  }
  const auto profile_csv = folder / "water_content.csv";
  write_csv(profile_csv, "depth,water_over_pores,green_ampt", profile);
  post::plot_xy(folder / "water_content.png",
                "Water content of the sand at the end" + at + ", bands 1 cm deep",
                "depth below the sand's surface (m)", "water volume / pore volume",
                {{profile_csv, 1, 2, "Lituya", true}, {profile_csv, 1, 3, "Green-Ampt"}});
  result.plots.push_back(std::filesystem::relative(folder / "water_content.png", context.report));
  return infiltrated_ratio;
}

}  // namespace

void run_infiltration(const CaseContext& context, CaseResult& result) {
  run_at_cell_sizes(context, result, {0.01, 0.005, 0.0025}, "the water infiltrated by 1 s", 0.05,
                    run_one);
}

}  // namespace lituya::verify
