// Case B of the reference paper: the first wave crest at the gauges X1 and X2
// (verification/case_b/README.md).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "case_support.hpp"
#include "lituya/post/postprocess.hpp"

namespace lituya::verify {

namespace {

struct Crest {
  double time = NAN, height = NAN;
};

// The first crest of a gauge record: the first sample of at least `min_height` that is as high
// as every sample within `window` on either side, with a full window after it (a rise cut off
// by the end of the record is no crest). Its time is refined by a parabola through the sample
// and its two neighbours; its height is the sample's.
Crest first_crest(const std::vector<double>& time, const std::vector<double>& eta,
                  double min_height, double window) {
  const std::size_t n = std::min(time.size(), eta.size());
  for (std::size_t k = 0; k < n; ++k) {
    if (!(eta[k] >= min_height) || time[k] > time[n - 1] - window) continue;
    bool highest = true;
    for (std::size_t j = 0; j < n && highest; ++j)
      if (std::abs(time[j] - time[k]) <= window && std::isfinite(eta[j]) && eta[j] > eta[k])
        highest = false;
    if (!highest) continue;
    Crest c{time[k], eta[k]};
    if (k > 0 && k + 1 < n && std::isfinite(eta[k - 1]) && std::isfinite(eta[k + 1])) {
      const double curvature = eta[k - 1] - 2 * eta[k] + eta[k + 1];
      const double h = 0.5 * (time[k + 1] - time[k - 1]);
      if (curvature < 0) {
        const double shift = 0.5 * h * (eta[k - 1] - eta[k + 1]) / curvature;
        c.time += std::clamp(shift, -0.5 * h, 0.5 * h);
      }
    }
    return c;
  }
  return {};
}

}  // namespace

void run_case_b(const CaseContext& context, CaseResult& result) {
  const double g = 9.81, h0 = 0.15;
  const double x1 = 0.3, x2 = 0.6;  // the paper's X1 = -0.3 m, X2 = -0.6 m (x = -X)
  const auto case_folder = run_scene(context);
  const auto post_folder = context.work / "post";
  const post::PostResult r = post::postprocess(case_folder, post_folder, /*overwrite=*/true);
  if (r.gauge_eta.size() != 2) throw std::runtime_error("case_b: post.toml must name 2 gauges");

  const double min_height = 0.005, window = 0.05;
  const Crest c1 = first_crest(r.liquid_time, r.gauge_eta[0], min_height, window);
  const Crest c2 = first_crest(r.liquid_time, r.gauge_eta[1], min_height, window);
  write_csv(context.work / "first_crests.csv", "gauge_x,first_crest_time,first_crest_height",
            {{x1, c1.time, c1.height}, {x2, c2.time, c2.height}});

  // X1 higher than X2: the ratio lies in [0, 1].
  add_check(result, "first-crest height ratio X2 / X1", "-", c2.height / c1.height, 0.5, 0.5);
  const double celerity = (x2 - x1) / (c2.time - c1.time);
  const double long_wave = std::sqrt(g * h0);
  add_check(result, "first-crest celerity from X1 to X2", "m/s", celerity, long_wave,
            0.2 * long_wave);

  for (const char* png : {"gauges.png", "leading_wave.png", "surface_profiles.png"})
    if (std::filesystem::exists(post_folder / png))
      result.plots.push_back(std::filesystem::relative(post_folder / png, context.report));
}

}  // namespace lituya::verify
