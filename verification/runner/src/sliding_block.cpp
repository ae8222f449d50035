// Block sliding on a rigid 25 degree incline with mu = 0.2: a = g (sin - mu cos)
// (verification/sliding_block/README.md).
#include <cmath>

#include "case_support.hpp"
#include "incline_travel.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::verify {

void run_sliding_block(const CaseContext& context, CaseResult& result) {
  constexpr double kPi = 3.14159265358979323846;
  const double theta = 25 * kPi / 180, mu = 0.2, g = 9.81;
  const double acceleration = g * (std::sin(theta) - mu * std::cos(theta));
  const double dx = std::cos(theta), dy = -std::sin(theta);

  // Runs a case folder's slide and checks its acceleration against the closed form (2 %).
  const auto check_slide = [&](const std::filesystem::path& case_folder,
                               const std::string& quantity) {
    const InclineTravel travel = along_slope_travel(case_folder, "slide", dx, dy);
    add_check(result, quantity, "m/s2", fitted_acceleration(travel), acceleration,
              0.02 * acceleration);
    return travel;
  };
  const InclineTravel block = check_slide(run_scene(context), "acceleration along the incline");
  // The quick scene with the volumetric smoothing on (README.md), in both variants.
  check_slide(
      run_scene(context, context.source / "scene_smoothing.toml", context.work / "smoothing"),
      "acceleration along the incline, volumetric_smoothing = true");
  // And on a crossed mesh ([mesh] crossed = true, README.md): the contact boundary on the
  // recombined incline and the cut cells must give the same closed form.
  check_slide(run_scene(context, context.source / "scene_crossed.toml", context.work / "crossed"),
              "acceleration along the incline, crossed mesh");

  std::vector<std::vector<double>> rows;
  for (std::size_t i = 0; i < block.time.size(); ++i)
    rows.push_back(
        {block.time[i], block.travel[i], 0.5 * acceleration * block.time[i] * block.time[i]});
  const auto csv = context.work / "travel.csv";
  write_csv(csv, "time,travel,exact_travel", rows);
  post::plot_xy(context.work / "travel.png",
                "Block on a 25 degree incline, mu = 0.2: travel along the slope", "time (s)",
                "travel (m)",
                {{csv, 1, 2, "Lituya", true}, {csv, 1, 3, "g (sin - mu cos) t^2 / 2"}});
  result.plots.push_back(std::filesystem::relative(context.work / "travel.png", context.report));
}

}  // namespace lituya::verify
