#include <algorithm>
#include <cmath>
#include <limits>

#include "lituya/verify/speed_accuracy.hpp"

namespace lituya::verify {

std::optional<std::size_t> cheapest_within(const std::vector<TradeRun>& runs, double max_error,
                                           const std::string& knob) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const TradeRun& r = runs[i];
    if ((!knob.empty() && r.knob != knob) || !r.admissible) continue;
    if (!std::isfinite(r.error) || !std::isfinite(r.wall_time) || r.error > max_error) continue;
    if (!best || r.wall_time < runs[*best].wall_time ||
        (r.wall_time == runs[*best].wall_time && r.error < runs[*best].error))
      best = i;
  }
  return best;
}

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t count = std::min(x.size(), y.size());
  const double n = static_cast<double>(count);
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < count; ++i) {
    mx += x[i] / n;
    my += y[i] / n;
  }
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < count; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (count < 2 || !(sxx > 0)) return std::numeric_limits<double>::quiet_NaN();
  return sxy / sxx;
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> lx, ly;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    if (std::isfinite(x[i]) && std::isfinite(y[i]) && x[i] > 0 && y[i] > 0) {
      lx.push_back(std::log(x[i]));
      ly.push_back(std::log(y[i]));
    }
  return least_squares_slope(lx, ly);
}

RichardsonEstimate richardson(double f1, double f2, double f3, double r) {
  const double d12 = f1 - f2, d23 = f2 - f3;
  if (!(d12 * d23 > 0) || !(r > 1)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan};
  }
  const double p = std::log(d12 / d23) / std::log(r);
  return {p, f3 + (f3 - f2) / (std::pow(r, p) - 1)};
}

}  // namespace lituya::verify
