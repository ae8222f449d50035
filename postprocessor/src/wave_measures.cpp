// The water surface read off the liquid points: its elevation at wave gauges, its profile
// along the flume, and the leading wave crest on that profile.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "lituya/post/postprocess.hpp"

namespace lituya::post {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The top of a liquid point: its centre plus half its spacing, the same rule the slide
// thickness uses, so a column of whole points reads the height of the water it stands for.
double top_of(const PointCloud& liquid, size_t i) {
  return liquid.position[i].y() + 0.5 * point_spacing(liquid, i);
}

}  // namespace

double gauge_elevation(const PointCloud& liquid, double gauge_x, double half_width,
                       double still_water_level) {
  double top = -std::numeric_limits<double>::infinity();
  bool wet = false;
  for (size_t i = 0; i < liquid.position.size(); ++i) {
    if (!(std::abs(liquid.position[i].x() - gauge_x) <= half_width)) continue;
    wet = true;
    top = std::max(top, top_of(liquid, i));
  }
  return wet ? top - still_water_level : kNaN;
}

std::vector<SurfaceBin> surface_profile(const PointCloud& liquid, double origin, double bin_width,
                                        double still_water_level) {
  std::map<long long, double> top;  // bin -> highest point top
  for (size_t i = 0; i < liquid.position.size(); ++i) {
    const double x = liquid.position[i].x();
    if (!std::isfinite(x)) continue;
    const auto k = static_cast<long long>(std::floor((x - origin) / bin_width));
    auto [bin, inserted] = top.try_emplace(k, top_of(liquid, i));
    if (!inserted) bin->second = std::max(bin->second, top_of(liquid, i));
  }
  std::vector<SurfaceBin> profile;
  if (top.empty()) return profile;
  auto centre = [&](long long k) { return origin + (static_cast<double>(k) + 0.5) * bin_width; };
  const long long first = top.begin()->first, last = top.rbegin()->first;
  constexpr long long kMaxListedBins = 1000000;
  if (last - first < kMaxListedBins) {
    for (long long k = first; k <= last; ++k) {
      auto bin = top.find(k);
      profile.push_back({centre(k), bin == top.end() ? kNaN : bin->second - still_water_level});
    }
  } else {
    for (const auto& [k, y] : top) profile.push_back({centre(k), y - still_water_level});
  }
  return profile;
}

LeadingWave find_leading_wave(const std::vector<SurfaceBin>& profile, double from_x,
                              double min_height) {
  LeadingWave wave;
  const auto n = static_cast<long long>(profile.size());
  for (const SurfaceBin& bin : profile)
    if (bin.x >= from_x && std::isfinite(bin.eta) &&
        (std::isnan(wave.max_eta) || bin.eta > wave.max_eta))
      wave.max_eta = bin.eta;
  if (std::isnan(wave.max_eta)) return wave;

  // A crest must stand out of the noise twice over: absolutely (min_height, ripples of
  // still water and the granularity of the points) and relative to the highest surface (a
  // leading wave a tenth of the main one is too small to follow through the splash).
  const double threshold = std::max(min_height, 0.1 * wave.max_eta);
  // From downstream: the first crest found is the leading one.
  for (long long k = n - 1; k >= 0; --k) {
    const SurfaceBin& bin = profile[k];
    if (bin.x < from_x) break;
    if (!(bin.eta > threshold)) continue;
    // A maximum over +-2 bins, not just +-1: a bump of one bin on the flank of a wave is a
    // +-1 maximum, but the crest two bins further up the flank is higher than it.
    bool crest = true;
    for (long long j = std::max(0LL, k - 2); j <= std::min(n - 1, k + 2) && crest; ++j)
      crest = j == k || !(profile[j].eta > bin.eta);
    if (crest) {
      wave.crest_x = bin.x;
      wave.crest_eta = bin.eta;
      return wave;
    }
  }
  return wave;
}

}  // namespace lituya::post
