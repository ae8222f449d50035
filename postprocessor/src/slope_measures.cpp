// Front, thickness and wall height of the sliding mass, measured in the slope frame.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "lituya/post/postprocess.hpp"

namespace lituya::post {

SlopeFrame::SlopeFrame(const Eigen::Vector3d& origin, double slope_angle_deg)
    : origin_(origin.x(), origin.y(), 0.0) {
  const double angle = slope_angle_deg * std::numbers::pi / 180.0;
  downslope_ = Eigen::Vector3d(std::cos(angle), -std::sin(angle), 0.0);
  slope_normal_ = Eigen::Vector3d(std::sin(angle), std::cos(angle), 0.0);
}

// Both axes have a zero z component, so the flume width never enters s or t.
double SlopeFrame::s(const Eigen::Vector3d& p) const {
  return (p - origin_).dot(downslope_);
}
double SlopeFrame::t(const Eigen::Vector3d& p) const {
  return (p - origin_).dot(slope_normal_);
}

Eigen::Vector3d SlopeFrame::point(double s, double t, double z) const {
  Eigen::Vector3d p = origin_ + s * downslope_ + t * slope_normal_;
  p.z() = z;
  return p;
}

namespace {

struct BinStats {
  int count = 0;
  double top = -std::numeric_limits<double>::infinity();  // largest t + half spacing
};

bool is_tracked(const PointCloud& points, const std::vector<bool>& tracked_material, size_t i) {
  // Output written without the material field: only meaningful for a single-material case.
  if (points.material.empty()) return tracked_material.size() == 1 && tracked_material[0];
  const int m = points.material[i];
  return m >= 0 && m < static_cast<int>(tracked_material.size()) && tracked_material[m];
}

// A point's top lies half its spacing above its centre, so a block of points reports its real
// height rather than that of its top row.
double half_spacing(const PointCloud& points, size_t i) {
  return 0.5 * point_spacing(points, i);
}

long long bin_of(double s, double bin_width) {
  return static_cast<long long>(std::floor(s / bin_width));
}

std::map<long long, BinStats> bin_tracked_points(const PointCloud& points,
                                                 const std::vector<bool>& tracked_material,
                                                 const SlopeFrame& frame, double bin_width) {
  std::map<long long, BinStats> bins;
  for (size_t i = 0; i < points.position.size(); ++i) {
    if (!is_tracked(points, tracked_material, i)) continue;
    const Eigen::Vector3d& p = points.position[i];
    BinStats& bin = bins[bin_of(frame.s(p), bin_width)];
    ++bin.count;
    bin.top = std::max(bin.top, frame.t(p) + half_spacing(points, i));
  }
  return bins;
}

}  // namespace

double front_position(const PointCloud& points, const std::vector<bool>& tracked_material,
                      const SlopeFrame& frame, double bin_width, int min_points) {
  const auto bins = bin_tracked_points(points, tracked_material, frame, bin_width);
  // Start at the most upslope bin that is part of the mass (not at a lone point left
  // behind), then follow the mass downslope until the first bin that is not.
  auto start = bins.begin();
  while (start != bins.end() && start->second.count < min_points) ++start;
  if (start == bins.end()) return std::numeric_limits<double>::quiet_NaN();
  long long last = start->first;
  for (auto next = bins.find(last + 1); next != bins.end() && next->second.count >= min_points;
       next = bins.find(last + 1))
    last = next->first;
  return static_cast<double>(last + 1) * bin_width;
}

double mass_front_position(const PointCloud& points, const std::vector<bool>& tracked_material,
                           const SlopeFrame& frame, double share) {
  std::vector<std::pair<double, double>> by_s;  // (s, mass) of the tracked points
  double total = 0;
  if (points.mass.size() == points.position.size())
    for (size_t i = 0; i < points.position.size(); ++i)
      if (is_tracked(points, tracked_material, i)) {
        by_s.emplace_back(frame.s(points.position[i]), points.mass[i]);
        total += points.mass[i];
      }
  if (!(total > 0)) return std::numeric_limits<double>::quiet_NaN();
  std::sort(by_s.begin(), by_s.end());
  double behind = 0;
  for (const auto& [s, mass] : by_s) {
    behind += mass;
    if (behind >= share * total) return s;
  }
  return by_s.back().first;  // rounding: the sum fell short of share * total by an ulp
}

std::vector<ProfileBin> thickness_profile(const PointCloud& points,
                                          const std::vector<bool>& tracked_material,
                                          const SlopeFrame& frame, double bin_width,
                                          int min_points) {
  const auto bins = bin_tracked_points(points, tracked_material, frame, bin_width);
  std::vector<ProfileBin> profile;
  if (bins.empty()) return profile;
  auto thickness = [&](const BinStats& b) { return b.count >= min_points ? b.top : 0.0; };
  // One empty bin on each side closes a plotted profile on the slope surface.
  const long long first = bins.begin()->first - 1, last = bins.rbegin()->first + 1;
  // Empty bins inside the range are listed with thickness 0 so that a plotted profile drops
  // to the slope where the mass is torn apart; a point flung absurdly far would make that
  // list huge, so then only occupied bins are listed.
  constexpr long long kMaxListedBins = 1000000;
  if (last - first < kMaxListedBins) {
    for (long long k = first; k <= last; ++k) {
      auto b = bins.find(k);
      profile.push_back({(static_cast<double>(k) + 0.5) * bin_width,
                         b == bins.end() ? 0.0 : thickness(b->second)});
    }
  } else {
    for (const auto& [k, b] : bins)
      profile.push_back({(static_cast<double>(k) + 0.5) * bin_width, thickness(b)});
  }
  return profile;
}

double wall_height(const PointCloud& points, const std::vector<bool>& tracked_material,
                   const SlopeFrame& frame, double wall_position, double bin_width,
                   int min_points) {
  // The bin is anchored on the wall itself rather than on the slope-origin grid, so that the
  // height is measured against the wall whatever its position.
  BinStats bin;
  for (size_t i = 0; i < points.position.size(); ++i) {
    if (!is_tracked(points, tracked_material, i)) continue;
    const Eigen::Vector3d& p = points.position[i];
    const double s = frame.s(p);
    if (s < wall_position || s >= wall_position + bin_width) continue;
    ++bin.count;
    bin.top = std::max(bin.top, frame.t(p) + half_spacing(points, i));
  }
  return bin.count >= min_points ? bin.top : 0.0;
}

}  // namespace lituya::post
