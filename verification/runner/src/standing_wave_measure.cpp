#include "standing_wave_measure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace lituya::verify {

double modal_amplitude(const std::vector<double>& positions, const std::vector<double>& volumes,
                       double length) {
  const double k = std::numbers::pi / length;
  double moment = 0;
  for (std::size_t q = 0; q < volumes.size(); ++q)
    moment += volumes[q] * std::cos(k * positions[3 * q]);
  return 2 / length * moment;
}

double volume_centroid_height(const std::vector<double>& positions,
                              const std::vector<double>& volumes) {
  double moment = 0, volume = 0;
  for (std::size_t q = 0; q < volumes.size(); ++q) {
    moment += volumes[q] * positions[3 * q + 1];
    volume += volumes[q];
  }
  return moment / volume;
}

StandingWaveFit fit_standing_wave(const std::vector<double>& time,
                                  const std::vector<double>& amplitude) {
  const std::size_t n = std::min(time.size(), amplitude.size());
  // Indices k with a sign change between samples k and k + 1, and the interpolated crossings.
  std::vector<std::size_t> change;
  std::vector<double> crossing;
  for (std::size_t k = 0; k + 1 < n; ++k)
    if (amplitude[k] * amplitude[k + 1] < 0) {
      change.push_back(k);
      crossing.push_back(time[k] - amplitude[k] * (time[k + 1] - time[k]) /
                                       (amplitude[k + 1] - amplitude[k]));
    }
  if (crossing.size() < 2)
    throw std::runtime_error("standing wave: fewer than two zero crossings in the record");
  StandingWaveFit fit;
  fit.period = 2 * (crossing.back() - crossing.front()) / static_cast<double>(crossing.size() - 1);

  // The release's extreme, then one per half cycle bounded by two crossings.
  fit.extreme_time.push_back(time[0]);
  fit.extreme_amplitude.push_back(std::abs(amplitude[0]));
  for (std::size_t c = 0; c + 1 < change.size(); ++c) {
    std::size_t j = change[c] + 1;
    for (std::size_t k = j; k <= change[c + 1]; ++k)
      if (std::abs(amplitude[k]) > std::abs(amplitude[j])) j = k;
    const double y0 = std::abs(amplitude[j - 1]), y1 = std::abs(amplitude[j]),
                 y2 = std::abs(amplitude[j + 1]);
    const double curvature = y0 - 2 * y1 + y2;
    const double shift = curvature < 0 ? 0.5 * (y0 - y2) / curvature : 0.0;  // in samples
    fit.extreme_time.push_back(time[j] + shift * 0.5 * (time[j + 1] - time[j - 1]));
    fit.extreme_amplitude.push_back(y1 - 0.25 * (y0 - y2) * shift);
  }
  // Least squares of ln|A| against t.
  const auto m = static_cast<double>(fit.extreme_time.size());
  double st = 0, sl = 0, stt = 0, stl = 0;
  for (std::size_t e = 0; e < fit.extreme_time.size(); ++e) {
    const double t = fit.extreme_time[e], l = std::log(fit.extreme_amplitude[e]);
    st += t;
    sl += l;
    stt += t * t;
    stl += t * l;
  }
  const double slope = m > 1 ? (m * stl - st * sl) / (m * stt - st * st) : 0.0;
  fit.decay_per_period = 1 - std::exp(slope * fit.period);
  return fit;
}

}  // namespace lituya::verify
