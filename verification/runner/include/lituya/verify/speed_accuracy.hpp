#pragma once
// The speed/accuracy study (verification/speed_accuracy): which run is the cheapest one that
// is accurate enough, and how the cost scales with a knob. Pure functions, unit-tested.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lituya::verify {

// One run of the study: the knob changed from the base setting and its value, the run's
// error (dimensionless; NaN when the run failed), its wall time (s), and whether it may be
// chosen at all (false: it broke a condition the error does not see, e.g. the water's volume).
struct TradeRun {
  std::string knob;
  double value = 0;
  double error = 0;
  double wall_time = 0;
  bool admissible = true;
};

// The run with the smallest wall time among the admissible ones whose error is at most
// `max_error` (the bound included), restricted to runs of `knob` when it is not empty. Runs
// whose error or wall time is not finite are never taken; of two equally fast runs, the more
// accurate, then the first. Empty when no run qualifies.
std::optional<std::size_t> cheapest_within(const std::vector<TradeRun>& runs, double max_error,
                                           const std::string& knob = "");

// The median of `values` (the mean of the two middle ones for an even count); NaN when empty.
double median(std::vector<double> values);

// The least-squares slope of y against x (about the means); NaN with fewer than two pairs or
// no spread in x. The pairs are taken as given (no filtering).
double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y);

// The least-squares slope of log(y) against log(x): the exponent p of y ~ x^p. Pairs with a
// non-positive or non-finite x or y are left out; NaN when fewer than two distinct x remain.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

// Richardson extrapolation from one quantity at three cell sizes h, h / r, h / r^2 (coarse,
// medium, fine values f1, f2, f3): with f = f_limit + C h^p, the observed order
// p = log((f1 - f2) / (f2 - f3)) / log r and the limit f3 + (f3 - f2) / (r^p - 1). Both NaN when
// the two differences do not have the same sign (the values are not in the asymptotic range).
struct RichardsonEstimate {
  double order = 0;
  double limit = 0;
};
RichardsonEstimate richardson(double f1, double f2, double f3, double r);

}  // namespace lituya::verify
