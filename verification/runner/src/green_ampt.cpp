#include "green_ampt.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lituya::verify {

double GreenAmptColumn::pond_depth(double d0, double front) const {
  return falling_head ? d0 - sand.porosity * front : d0;
}

std::vector<double> GreenAmptColumn::front_depth(double d0, const std::vector<double>& times,
                                                 double max_depth, int intervals) const {
  const double n = sand.porosity;
  const double depth_limit = falling_head ? std::min(max_depth, d0 / n) : max_depth;
  // dt/ds = 2 s n / q at L = s^2; zero at the surface, where the drive is unbounded.
  auto time_rate = [&](double s) {
    if (s <= 0) return 0.0;
    const double front = s * s;
    const double drive = sand.density * sand.gravity * (pond_depth(d0, front) + front) / front;
    return 2 * s * n / sand.flux(drive);
  };
  // t_at[k]: the time the front takes to depth (k ds)^2.
  const double ds = std::sqrt(depth_limit) / intervals;
  std::vector<double> t_at(intervals + 1);
  double rate0 = time_rate(0.0);
  for (int k = 1; k <= intervals; ++k) {
    const double rate1 = time_rate(k * ds);
    t_at[k] = t_at[k - 1] + ds / 6 * (rate0 + 4 * time_rate((k - 0.5) * ds) + rate1);
    rate0 = rate1;
  }
  std::vector<double> front;
  for (const double t : times) {
    if (t > t_at.back())
      throw std::runtime_error("Green-Ampt reference: t = " + std::to_string(t) +
                               " s lies beyond the column (the front reaches " +
                               std::to_string(depth_limit) + " m at " +
                               std::to_string(t_at.back()) + " s)");
    const auto k = static_cast<std::size_t>(
        std::max<std::ptrdiff_t>(1, std::lower_bound(t_at.begin(), t_at.end(), t) - t_at.begin()));
    const double w = (t - t_at[k - 1]) / (t_at[k] - t_at[k - 1]);
    const double s = (static_cast<double>(k) - 1 + w) * ds;
    front.push_back(s * s);
  }
  return front;
}

}  // namespace lituya::verify
