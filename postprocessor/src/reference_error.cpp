// The error figures of a simulated series against its reference (reference_error.hpp).
#include "lituya/post/reference_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lituya::post {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The time span a series covers: from its first to its last sample with a value.
bool finite_span(const std::vector<double>& time, const std::vector<double>& value, double& first,
                 double& last) {
  first = last = kNaN;
  for (size_t i = 0; i < time.size() && i < value.size(); ++i) {
    if (!std::isfinite(value[i]) || !std::isfinite(time[i])) continue;
    if (std::isnan(first)) first = time[i];
    last = time[i];
  }
  return std::isfinite(first);
}

// The largest value over [a, b]: the samples inside, and the series interpolated at the ends.
double peak_in(const std::vector<double>& time, const std::vector<double>& value, double a,
               double b) {
  double peak = kNaN;
  auto take = [&](double v) {
    if (std::isfinite(v) && !(v <= peak)) peak = v;
  };
  take(interpolate_series(time, value, a));
  take(interpolate_series(time, value, b));
  for (size_t i = 0; i < time.size() && i < value.size(); ++i)
    if (time[i] >= a && time[i] <= b) take(value[i]);
  return peak;
}

}  // namespace

double interpolate_series(const std::vector<double>& time, const std::vector<double>& value,
                          double t) {
  const size_t n = std::min(time.size(), value.size());
  if (n == 0 || !(t >= time.front()) || !(t <= time[n - 1])) return kNaN;
  // The first sample at or after t.
  const size_t j = std::lower_bound(time.begin(), time.begin() + n, t) - time.begin();
  if (time[j] == t) return value[j];
  const size_t i = j - 1;  // j > 0, since t > time.front() here
  if (!std::isfinite(value[i]) || !std::isfinite(value[j])) return kNaN;
  const double w = (t - time[i]) / (time[j] - time[i]);
  return value[i] + w * (value[j] - value[i]);
}

double arrival_time(const std::vector<double>& time, const std::vector<double>& value,
                    double threshold, double from, double to) {
  if (!std::isfinite(threshold) || !(from <= to)) return kNaN;
  // The samples with a value in [from, to], with the series interpolated at both ends.
  std::vector<std::pair<double, double>> samples;
  const double at_from = interpolate_series(time, value, from);
  if (std::isfinite(at_from)) samples.emplace_back(from, at_from);
  for (size_t i = 0; i < time.size() && i < value.size(); ++i)
    if (time[i] > from && time[i] < to && std::isfinite(value[i]))
      samples.emplace_back(time[i], value[i]);
  const double at_to = interpolate_series(time, value, to);
  if (to > from && std::isfinite(at_to)) samples.emplace_back(to, at_to);
  if (samples.empty() || samples.front().second > threshold) return kNaN;
  for (size_t k = 1; k < samples.size(); ++k) {
    const auto [t0, v0] = samples[k - 1];
    const auto [t1, v1] = samples[k];
    if (v1 > threshold) return t0 + (threshold - v0) / (v1 - v0) * (t1 - t0);
  }
  return kNaN;
}

ReferenceError compare_with_reference(const std::vector<double>& sim_time,
                                      const std::vector<double>& sim_value,
                                      const std::vector<double>& ref_time,
                                      const std::vector<double>& ref_value,
                                      double arrival_fraction) {
  ReferenceError e;
  double sim_first, sim_last, ref_first, ref_last;
  if (!finite_span(sim_time, sim_value, sim_first, sim_last) ||
      !finite_span(ref_time, ref_value, ref_first, ref_last))
    return e;
  e.span_start = std::max(sim_first, ref_first);
  e.span_end = std::min(sim_last, ref_last);
  if (!(e.span_start <= e.span_end)) {
    e.span_start = e.span_end = kNaN;
    return e;
  }

  double sum = 0;
  for (size_t i = 0; i < ref_time.size() && i < ref_value.size(); ++i) {
    if (!std::isfinite(ref_value[i]) || ref_time[i] < e.span_start || ref_time[i] > e.span_end)
      continue;
    const double sim = interpolate_series(sim_time, sim_value, ref_time[i]);
    if (!std::isfinite(sim)) continue;
    sum += (sim - ref_value[i]) * (sim - ref_value[i]);
    ++e.samples;
  }
  if (e.samples > 0) e.rms = std::sqrt(sum / e.samples);

  e.simulated_peak = peak_in(sim_time, sim_value, e.span_start, e.span_end);
  e.reference_peak = peak_in(ref_time, ref_value, e.span_start, e.span_end);
  e.peak_error = e.simulated_peak - e.reference_peak;
  if (std::abs(e.reference_peak) > 0)
    e.peak_error_relative = e.peak_error / std::abs(e.reference_peak);

  if (e.reference_peak > 0) {
    e.threshold = arrival_fraction * e.reference_peak;
    e.simulated_arrival = arrival_time(sim_time, sim_value, e.threshold, e.span_start, e.span_end);
    e.reference_arrival = arrival_time(ref_time, ref_value, e.threshold, e.span_start, e.span_end);
    e.arrival_error = e.simulated_arrival - e.reference_arrival;
  }
  return e;
}

std::string error_summary(const ReferenceError& e, const std::string& name) {
  // A figure with its unit, or "-" when it could not be computed.
  auto figure = [](const char* format, double v, const std::string& unit) {
    if (!std::isfinite(v)) return std::string("-");
    char text[48];
    std::snprintf(text, sizeof text, format, v);
    return std::string(text) + unit;
  };
  const std::string unit = e.unit.empty() ? "" : " " + e.unit;
  std::string out = name.empty() ? "" : name + ": ";
  out += "RMS " + figure("%.3g", e.rms, unit);
  out += ", peak " + figure("%+.3g", e.peak_error, unit);
  if (std::isfinite(e.peak_error) && std::isfinite(e.peak_error_relative))
    out += " (" + figure("%+.1f", 100 * e.peak_error_relative, " %") + ")";
  out += ", arrival " + figure("%+.3g", e.arrival_error, " s");
  return out;
}

}  // namespace lituya::post
