#pragma once
// How far a simulated time series lies from the reference it is plotted against (a wave gauge
// against its laboratory record, the front travel against the paper's values): the error
// figures `lituya post` prints in the plot titles and writes to errors.csv.
//
// All three are taken over the common span, the times that both the simulation and the
// reference cover, [max(first times), min(last times)]:
// - RMS error: the simulation is interpolated linearly onto each reference time in the span
//   (a reference time in a gap of the simulation, next to a sample without a value, is left
//   out), and rms = sqrt(mean((sim - ref)^2)) over those samples;
// - peak error: the largest simulated value minus the largest reference value, both in the
//   span (the simulation also at the span's ends, interpolated), and that difference over
//   |reference peak|;
// - arrival-time error: the arrival is the first time, in the span, at which a series rises
//   above the threshold, `arrival_fraction` (10 %) of the reference peak, with the crossing
//   interpolated linearly between the two samples around it. A series that is already above
//   the threshold at the start of the span has no arrival (a wall height that only falls), nor
//   has one that never reaches it, nor any when the reference peak is not positive. The
//   error is the simulated arrival minus the reference's: positive when the simulation is
//   late.
// Every figure is NaN when it cannot be computed.
#include <cmath>
#include <string>
#include <vector>

namespace lituya::post {

struct ReferenceError {
  std::string plot;                         // the PNG the series is drawn in, e.g. "gauges.png"
  std::string series;                       // the series' name, e.g. "X1" or "front_travel"
  std::string unit;                         // of the values, e.g. "m"
  double span_start = NAN, span_end = NAN;  // s, the common span
  int samples = 0;                          // reference samples the RMS error is taken over
  double rms = NAN;
  double simulated_peak = NAN, reference_peak = NAN;
  double peak_error = NAN, peak_error_relative = NAN;  // simulated - reference; / |reference|
  double threshold = NAN;                              // of the arrival
  double simulated_arrival = NAN, reference_arrival = NAN;
  double arrival_error = NAN;  // s, simulated - reference
};

// The errors of the series (sim_time, sim_value) against (ref_time, ref_value), both sorted by
// time; a NaN value is a sample without a value. `plot`, `series` and `unit` are left empty.
ReferenceError compare_with_reference(const std::vector<double>& sim_time,
                                      const std::vector<double>& sim_value,
                                      const std::vector<double>& ref_time,
                                      const std::vector<double>& ref_value,
                                      double arrival_fraction = 0.1);

// The series (time sorted) at `t`, interpolated linearly between the samples around it; NaN
// outside [time.front(), time.back()] or when one of those samples has no value.
double interpolate_series(const std::vector<double>& time, const std::vector<double>& value,
                          double t);

// The first time in [from, to] at which the series rises above `threshold` (see above); NaN
// when it is above it already at `from`, never gets above it, or has no value at `from`.
double arrival_time(const std::vector<double>& time, const std::vector<double>& value,
                    double threshold, double from, double to);

// One short line for a plot title: "RMS 0.0021 m, peak +0.0013 m (+5.2 %), arrival +0.021 s",
// with "-" for a figure that could not be computed, prefixed by `name: ` when name is given.
std::string error_summary(const ReferenceError& error, const std::string& name = "");

}  // namespace lituya::post
