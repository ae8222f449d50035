#include "lock_exchange_measure.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

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
  double n = 0, st = 0, sx = 0, stt = 0, stx = 0;
  for (std::size_t k = 0; k < time.size() && k < front.size(); ++k) {
    if (!(front[k] >= low && front[k] <= high)) continue;
    n += 1;
    st += time[k];
    sx += front[k];
    stt += time[k] * time[k];
    stx += time[k] * front[k];
  }
  const double spread = n * stt - st * st;
  if (n < 3 || !(spread > 0)) return std::numeric_limits<double>::quiet_NaN();
  return (n * stx - st * sx) / spread;
}

double lock_exchange_speed(double gravity, double depth, double heavy, double light) {
  return 0.5 * std::sqrt(gravity * (heavy - light) / light * depth);
}

}  // namespace lituya::verify
