// Case B of the reference paper: the first wave crest at the gauges X1 and X2
// (verification/case_b/README.md).
#include <cmath>
#include <stdexcept>
#include <vector>

#include "case_support.hpp"
#include "lituya/post/postprocess.hpp"
#include "lituya/post/reference_error.hpp"

namespace lituya::verify {

void run_case_b(const CaseContext& context, CaseResult& result) {
  const double g = 9.81, h0 = 0.15;
  const double x1 = 0.3, x2 = 0.6;  // the paper's X1 = -0.3 m, X2 = -0.6 m (x = -X)
  const auto case_folder = run_scene(context);
  const auto post_folder = context.work / "post";
  const post::PostResult r = post::postprocess(case_folder, post_folder, /*overwrite=*/true);
  if (r.gauge_eta.size() != 2) throw std::runtime_error("case_b: post.toml must name 2 gauges");

  // The first wave at each gauge (complete_first_wave). A wave still standing at the end of the
  // run has no crest yet (NaN: the checks fail).
  const post::WaveCrest c1 = complete_first_wave(r.liquid_time, r.gauge_eta[0]);
  const post::WaveCrest c2 = complete_first_wave(r.liquid_time, r.gauge_eta[1]);
  // The wave's arrival at a gauge: the record's first rise through half its first crest. The
  // crest's own time is a poor clock: at X1 the first wave has a flat top 0.05-0.1 s long,
  // and which sample of it is highest moves with the noise (crest-to-crest celerities of
  // 1.03-1.58 m/s over the cell sizes 0.03-0.01 m, against 1.21-1.30 m/s from half-height
  // arrivals).
  auto half_height_arrival = [&](const std::vector<double>& eta, double crest) {
    return r.liquid_time.empty() ? NAN
                                 : post::arrival_time(r.liquid_time, eta, 0.5 * crest,
                                                      r.liquid_time.front(), r.liquid_time.back());
  };
  const double t1 = half_height_arrival(r.gauge_eta[0], c1.height);
  const double t2 = half_height_arrival(r.gauge_eta[1], c2.height);
  write_csv(context.work / "first_crests.csv",
            "gauge_x,first_crest_time,first_crest_height,half_height_arrival_time",
            {{x1, c1.time, c1.height, t1}, {x2, c2.time, c2.height, t2}});

  // X1 higher than X2: the ratio lies in [0, 1].
  add_check(result, "first-crest height ratio X2 / X1", "-", c2.height / c1.height, 0.5, 0.5);
  const double celerity = (x2 - x1) / (t2 - t1);
  const double long_wave = std::sqrt(g * h0);
  add_check(result, "first-wave celerity from X1 to X2 (half-height arrivals)", "m/s", celerity,
            long_wave, 0.2 * long_wave);

  for (const char* png : {"gauges.png", "leading_wave.png", "surface_profiles.png"})
    if (std::filesystem::exists(post_folder / png))
      result.plots.push_back(std::filesystem::relative(post_folder / png, context.report));
}

}  // namespace lituya::verify
