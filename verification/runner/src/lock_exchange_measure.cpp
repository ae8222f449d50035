#include "lock_exchange_measure.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "lituya/verify/speed_accuracy.hpp"

namespace lituya::verify {

double current_front(const std::vector<double>& positions, double below, int strays) {
  std::vector<double> x;
  for (std::size_t p = 0; 3 * p + 1 < positions.size(); ++p)
    if (positions[3 * p + 1] < below) x.push_back(positions[3 * p]);
  if (x.size() <= static_cast<std::size_t>(strays)) return std::numeric_limits<double>::quiet_NaN();
  std::nth_element(x.begin(), x.begin() + strays, x.end(), std::greater<>());
  return x[static_cast<std::size_t>(strays)];
}

double front_speed(const std::vector<double>& time, const std::vector<double>& front, double low,
                   double high) {
  std::vector<double> t, x;
  for (std::size_t k = 0; k < time.size() && k < front.size(); ++k)
    if (front[k] >= low && front[k] <= high) {
      t.push_back(time[k]);
      x.push_back(front[k]);
    }
  return t.size() < 3 ? std::numeric_limits<double>::quiet_NaN() : least_squares_slope(t, x);
}

double lock_exchange_speed(double gravity, double depth, double heavy, double light) {
  return 0.5 * std::sqrt(gravity * (heavy - light) / light * depth);
}

}  // namespace lituya::verify
