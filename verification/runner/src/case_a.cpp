// Case A of the reference paper: front travel and wall height at 0.32 s and 0.64 s
// (verification/case_a/README.md).
#include <cmath>

#include "case_support.hpp"
#include "lituya/post/postprocess.hpp"

namespace lituya::verify {

namespace {
double at_time(const std::vector<double>& time, const std::vector<double>& value, double t) {
  for (std::size_t i = 0; i < time.size(); ++i)
    if (std::abs(time[i] - t) < 1e-6) return value[i];
  return NAN;
}
}  // namespace

void run_case_a(const CaseContext& context, CaseResult& result) {
  const auto case_folder = run_scene(context);
  const auto post_folder = context.work / "post";
  const post::PostResult r = post::postprocess(case_folder, post_folder, /*overwrite=*/true);
  add_check(result, "front travel at 0.32 s", "m", at_time(r.time, r.front_travel, 0.32), 0.3,
            0.06);
  add_check(result, "front travel at 0.64 s", "m", at_time(r.time, r.front_travel, 0.64), 0.9,
            0.12);
  add_check(result, "wall height at 0.32 s", "m", at_time(r.time, r.wall_height, 0.32), 0.125,
            0.010);
  add_check(result, "wall height at 0.64 s", "m", at_time(r.time, r.wall_height, 0.64), 0.08,
            0.015);
  for (const char* png : {"runout.png", "wall_height.png", "profiles.png"})
    if (std::filesystem::exists(post_folder / png))
      result.plots.push_back(std::filesystem::relative(post_folder / png, context.report));
}

}  // namespace lituya::verify
