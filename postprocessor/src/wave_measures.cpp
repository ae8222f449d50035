// The water surface read off the liquid points: its elevation at wave gauges, its profile
// along the flume, and the leading wave crest on that profile.
//
// A column of the flume (a gauge's window, a profile bin) is read as a water fraction that
// varies with height: each liquid point stands for a square (a cube in 3D) of its spacing,
// filled with water at volume / spacing^d (1 for free water, the porosity for pore water),
// and counts with the share of its width that lies in the column. The surface is the top of
// the water body's highest (three quarters) full level, the body being the column from the
// bottom up to its first gap (below a quarter full), raised by all the water that stands
// above that level spread over the column. So a point riding a little above its neighbours
// lifts the surface by its own share of the column, not by its full height, and a drop or a
// sheet of spray adds its volume, not its elevation: the highest point's top (the reading
// until December 2026) jumped with single points and made crest records spiky on fine
// meshes, and the highest full level of the whole column (until the eighth session of
// December 2026) took a row of points thrown ahead of a crest over a gap for the surface
// (Case B at 0.01 m cells).
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lituya/post/postprocess.hpp"

namespace lituya::post {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A column counts as full where its water fraction reaches this share of its fullest level
// (of 1 for free water). Below a half the reading would take a single point standing on a
// full row two points wide for water; at 1 any gap between disordered points would count.
constexpr double kFullShare = 0.75;
// Below this share of its fullest level the column is empty there: water above such a gap is
// not part of the body below it (a sheet of spray flying over the surface), however full.
constexpr double kGapShare = 0.25;

// The part of one point that lies in a column: its vertical extent and the fraction of the
// column's cross-section it fills there.
struct Footprint {
  double bottom, top, fraction;
};

// The horizontal extent of the flume across the gauge line in 3D (z), from the liquid points'
// own extent; 1 in 2D, where the column is a slice of unit thickness.
double flume_width(const PointCloud& liquid) {
  if (liquid.dimension != 3) return 1.0;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (size_t i = 0; i < liquid.position.size(); ++i) {
    const double half = 0.5 * point_spacing(liquid, i);
    low = std::min(low, liquid.position[i].z() - half);
    high = std::max(high, liquid.position[i].z() + half);
  }
  return high > low ? high - low : 1.0;
}

// A column [left, right) of the flume and the points that belong to it (those whose centre
// lies in it; a point belongs to one bin or gauge window, as the old reading had it).
class Column {
 public:
  Column(double left, double right, double flume_width)
      : left_(left), right_(right), cross_section_(flume_width * (right - left)) {}

  void add(const PointCloud& liquid, size_t i) {
    const Eigen::Vector3d& p = liquid.position[i];
    const double s = point_spacing(liquid, i);
    if (!(s > 0)) {  // no volume: only its centre is known
      highest_centre_ = std::max(highest_centre_, p.y());
      return;
    }
    const double overlap = std::min(p.x() + 0.5 * s, right_) - std::max(p.x() - 0.5 * s, left_);
    if (!(overlap > 0)) return;
    const int d = liquid.dimension == 3 ? 3 : 2;
    const double fill = liquid.volume[i] / std::pow(s, d);  // porosity for pore water
    const double depth = d == 3 ? s : 1.0;                  // across the flume
    footprints_.push_back(
        {p.y() - 0.5 * s, p.y() + 0.5 * s, fill * overlap * depth / cross_section_});
  }

  bool empty() const { return footprints_.empty() && std::isinf(highest_centre_); }

  // The surface elevation (absolute), see the file comment.
  double surface() {
    if (footprints_.empty()) return highest_centre_;
    // Walking up from the bottom: +fraction at a footprint's bottom, -fraction at its top.
    events_.clear();
    for (const Footprint& f : footprints_) {
      events_.push_back({f.bottom, f.fraction});
      events_.push_back({f.top, -f.fraction});
    }
    std::sort(events_.begin(), events_.end(),
              [](const Event& a, const Event& b) { return a.y < b.y; });
    // Levels: events closer than a billionth of the column's width are one level, so that a
    // point's bottom and the top of the point below it (equal but for rounding) do not make
    // the column look doubly full, or empty, in between.
    const double same_level = 1e-9 * (right_ - left_);
    auto next_level = [&](size_t& k, double& fraction) {
      const double y = events_[k].y;
      for (; k < events_.size() && events_[k].y < y + same_level; ++k)
        fraction += events_[k].change;
      return y;
    };
    // The fullest level, capped at 1: free water is full at 1 even where disordered points
    // overlap; a column of pore water only (a saturated deposit) is full at its porosity.
    double fraction = 0, fullest = 0;
    for (size_t k = 0; k < events_.size();) {
      next_level(k, fraction);
      fullest = std::max(fullest, fraction);
    }
    fullest = std::min(fullest, 1.0);
    // Up through the water body, the stretch of the column from its first full level up to
    // where it empties (below a quarter full over half a point's height or more: a gap, not
    // the disorder of points within the water), to the top of the body's last full level; what
    // stands above that level, the body's partly filled top and any spray over a gap, is spread
    // over the column. A gap must be at least half a point high: between two rows of a sheared
    // lattice the column can be empty over a sliver.
    double spacing = 0;
    for (const Footprint& f : footprints_) spacing += f.top - f.bottom;
    const double min_gap = 0.5 * spacing / static_cast<double>(footprints_.size());
    const double full = kFullShare * fullest * (1 - 1e-12);
    const double gap = kGapShare * fullest;
    bool in_body = false, was_full = false;
    double top = kNaN, gap_start = kNaN;
    fraction = 0;
    for (size_t k = 0; k < events_.size();) {
      const double y = next_level(k, fraction);
      if (!std::isnan(gap_start) && y - gap_start >= min_gap) break;  // the body ended there
      if (!in_body && fraction >= full) in_body = true;
      if (!in_body) continue;
      const bool is_full = fraction >= full;
      if (was_full && !is_full) top = y;
      was_full = is_full;
      if (fraction < gap) {
        if (std::isnan(gap_start)) gap_start = y;
      } else {
        gap_start = kNaN;
      }
    }
    if (std::isnan(top)) return highest_centre_;  // not reached: the body empties somewhere
    double above = 0;  // the water over the top, as a height of full column
    fraction = 0;
    for (size_t k = 0; k < events_.size();) {
      const double y = next_level(k, fraction);
      if (k < events_.size() && y >= top - same_level) above += fraction * (events_[k].y - y);
    }
    return std::max(top + above / fullest, highest_centre_);
  }

 private:
  struct Event {
    double y, change;
  };
  double left_, right_, cross_section_;
  double highest_centre_ = -std::numeric_limits<double>::infinity();
  std::vector<Footprint> footprints_;
  std::vector<Event> events_;
};

}  // namespace

double gauge_elevation(const PointCloud& liquid, double gauge_x, double half_width,
                       double still_water_level) {
  Column column(gauge_x - half_width, gauge_x + half_width, flume_width(liquid));
  for (size_t i = 0; i < liquid.position.size(); ++i)
    if (std::abs(liquid.position[i].x() - gauge_x) <= half_width) column.add(liquid, i);
  return column.empty() ? kNaN : column.surface() - still_water_level;
}

std::vector<SurfaceBin> surface_profile(const PointCloud& liquid, double origin, double bin_width,
                                        double still_water_level) {
  const double width = flume_width(liquid);
  std::map<long long, Column> columns;
  for (size_t i = 0; i < liquid.position.size(); ++i) {
    const double x = liquid.position[i].x();
    if (!std::isfinite(x)) continue;
    const auto k = static_cast<long long>(std::floor((x - origin) / bin_width));
    const double left = origin + static_cast<double>(k) * bin_width;
    columns.try_emplace(k, left, left + bin_width, width).first->second.add(liquid, i);
  }
  std::map<long long, double> top;  // bin -> surface elevation
  for (auto& [k, column] : columns) top[k] = column.surface();
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

namespace {

// The highest eta of the bins whose centre is at or beyond from_x; NaN when none holds liquid.
double highest_surface(const std::vector<SurfaceBin>& profile, double from_x) {
  double highest = kNaN;
  for (const SurfaceBin& bin : profile)
    if (bin.x >= from_x && std::isfinite(bin.eta) && (std::isnan(highest) || bin.eta > highest))
      highest = bin.eta;
  return highest;
}

// Bin k (holding liquid) is a crest when it is at least as high as every non-empty bin within
// 2 bins on either side. A maximum over +-2 bins, not just +-1: a bump of one bin on the flank
// of a wave is a +-1 maximum, but the crest two bins further up the flank is higher than it.
bool is_crest(const std::vector<SurfaceBin>& profile, size_t k) {
  const size_t first = k >= 2 ? k - 2 : 0, last = std::min(profile.size() - 1, k + 2);
  for (size_t j = first; j <= last; ++j)
    if (j != k && profile[j].eta > profile[k].eta) return false;
  return true;
}

// The width of the profile's bins: the smallest spacing of neighbouring bins (a profile lists
// its bins in order, gaps only where a point was flung absurdly far); 0 with fewer than two.
double bin_width(const std::vector<SurfaceBin>& profile) {
  double width = 0;
  for (size_t k = 1; k < profile.size(); ++k) {
    const double step = profile[k].x - profile[k - 1].x;
    if (step > 0 && (width == 0 || step < width)) width = step;
  }
  return width;
}

}  // namespace

LeadingWave find_leading_wave(const std::vector<SurfaceBin>& profile, double from_x,
                              double min_height) {
  LeadingWave wave;
  wave.max_eta = highest_surface(profile, from_x);
  if (std::isnan(wave.max_eta)) return wave;

  // A crest must stand out of the noise twice over: absolutely (min_height, ripples of
  // still water and the granularity of the points) and relative to the highest surface (a
  // leading wave a tenth of the main one is too small to follow through the splash).
  const double threshold = std::max(min_height, 0.1 * wave.max_eta);
  // From downstream: the first crest found is the leading one.
  for (size_t k = profile.size(); k-- > 0;) {
    const SurfaceBin& bin = profile[k];
    if (bin.x < from_x) break;
    if (bin.eta > threshold && is_crest(profile, k)) {
      wave.crest_x = bin.x;
      wave.crest_eta = bin.eta;
      return wave;
    }
  }
  return wave;
}

std::vector<LeadingWave> track_leading_wave(const std::vector<double>& time,
                                            const std::vector<std::vector<SurfaceBin>>& profiles,
                                            double from_x, double min_height,
                                            double still_water_depth, double gravity) {
  if (time.size() != profiles.size())
    throw std::invalid_argument("track_leading_wave: " + std::to_string(time.size()) +
                                " times for " + std::to_string(profiles.size()) + " profiles");
  if (!(gravity > 0)) throw std::invalid_argument("track_leading_wave: gravity must be > 0");
  const double depth = std::fmax(still_water_depth, 0.0);  // NaN counts as 0

  std::vector<LeadingWave> record;
  record.reserve(profiles.size());
  bool tracking = false;
  double x_last = kNaN, t_last = kNaN, max_eta_last = kNaN;  // of the last position taken
  for (size_t k = 0; k < profiles.size(); ++k) {
    const std::vector<SurfaceBin>& profile = profiles[k];
    if (!tracking) {
      const LeadingWave wave = find_leading_wave(profile, from_x, min_height);
      if (std::isfinite(wave.crest_x)) {
        tracking = true;
        x_last = wave.crest_x;
        t_last = time[k];
        max_eta_last = wave.max_eta;
      }
      record.push_back(wave);
      continue;
    }

    LeadingWave wave;
    wave.max_eta = highest_surface(profile, from_x);
    // The wave can have been no higher than the highest surface of either frame; a bore or a
    // solitary wave runs faster the higher it is, so that height goes into the bound.
    const double highest = std::fmax(std::fmax(max_eta_last, wave.max_eta), 0.0);
    const double fastest = kLeadingWaveSpeedMargin * std::sqrt(gravity * (depth + highest));
    const double reach = fastest * (time[k] - t_last) + bin_width(profile);
    // The highest bin of the window. Inside the window it is a crest by find_leading_wave's
    // test; on the window's edge it need not be (higher water just beyond): the crest then
    // lies further on (a broad crest whose highest bin the noise had put at its rear), and the
    // track climbs towards it, never faster than the wave can run.
    std::optional<size_t> best;
    for (size_t j = 0; j < profile.size(); ++j) {
      const SurfaceBin& bin = profile[j];
      if (bin.x < from_x || !(std::abs(bin.x - x_last) <= reach) || !(bin.eta > min_height))
        continue;
      // >= on the height: of two equal bins the more downstream one leads.
      if (!best || bin.eta >= profile[*best].eta) best = j;
    }
    if (best) {
      wave.crest_x = x_last = profile[*best].x;
      wave.crest_eta = profile[*best].eta;
      t_last = time[k];
      max_eta_last = wave.max_eta;
    }
    record.push_back(wave);
  }
  return record;
}

double still_water_depth(const PointCloud& liquid, double still_water_level) {
  double lowest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < liquid.position.size(); ++i)
    lowest = std::min(lowest, liquid.position[i].y() - 0.5 * point_spacing(liquid, i));
  return std::isfinite(lowest) ? still_water_level - lowest : kNaN;
}

WaveCrest first_wave_crest(const std::vector<double>& time, const std::vector<double>& eta,
                           double onset) {
  std::vector<double> t, e;  // the samples with water at the gauge
  for (size_t i = 0; i < eta.size() && i < time.size(); ++i)
    if (std::isfinite(eta[i])) {
      t.push_back(time[i]);
      e.push_back(eta[i]);
    }
  WaveCrest crest;
  size_t k = 0;
  while (k < e.size() && !(e[k] > onset)) ++k;
  if (k == e.size()) return crest;
  size_t first = k;  // the first sample of the wave: back to the rise through still water
  while (first > 0 && e[first - 1] > 0) --first;
  size_t highest = k;
  for (; k < e.size() && !(e[k] < 0); ++k)
    if (e[k] > e[highest]) highest = k;
  crest.complete = k < e.size();
  // The area: trapezoids over the wave's samples, and the triangles out to the interpolated
  // crossings of still water on either side (a sample exactly at 0 is its own crossing).
  auto crossing_triangle = [&](size_t inside, size_t outside) {
    const double rise = e[inside] - e[outside];
    return rise > 0 ? 0.5 * e[inside] * std::abs(t[inside] - t[outside]) * e[inside] / rise : 0.0;
  };
  crest.area = 0;
  for (size_t i = first; i + 1 < k; ++i) crest.area += 0.5 * (e[i] + e[i + 1]) * (t[i + 1] - t[i]);
  if (first > 0) crest.area += crossing_triangle(first, first - 1);
  if (crest.complete) crest.area += crossing_triangle(k - 1, k);
  crest.time = t[highest];
  crest.height = e[highest];
  if (highest > 0 && highest + 1 < e.size()) {
    const double curvature = e[highest - 1] - 2 * e[highest] + e[highest + 1];
    const double step = 0.5 * (t[highest + 1] - t[highest - 1]);
    if (curvature < 0) {
      const double shift = 0.5 * step * (e[highest - 1] - e[highest + 1]) / curvature;
      crest.time += std::clamp(shift, -0.5 * step, 0.5 * step);
    }
  }
  return crest;
}

}  // namespace lituya::post
