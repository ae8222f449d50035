#pragma once
// The standing wave's measures (verification/standing_wave/README.md): the first sloshing mode's
// amplitude read from the water's volume, and its period and decay fitted to that record.
#include <vector>

namespace lituya::verify {

// The amplitude of the surface mode cos(pi x / L) in a tank between walls at x = 0 and L:
// (2 / L) sum_q V_q cos(pi x_q / L) over the liquid points (positions 3 per point, volumes per
// metre in 2D). Over a flat bed the still depth drops out of the cosine moment, so this is the
// mode's amplitude with no surface read off the points.
double modal_amplitude(const std::vector<double>& positions, const std::vector<double>& volumes,
                       double length);

// The height of the water's volume centroid, sum_q V_q y_q / sum_q V_q. Points that keep their
// volumes but crowd towards the bed lower it; a standing wave of amplitude a in water h deep
// raises it by at most a^2 / 4 h (its potential energy).
double volume_centroid_height(const std::vector<double>& positions,
                              const std::vector<double>& volumes);

struct StandingWaveFit {
  double period = 0;            // s, twice the mean spacing of the record's zero crossings
  double decay_per_period = 0;  // 1 - exp(slope T), slope of ln|extreme| against time
  std::vector<double> extreme_time, extreme_amplitude;  // s; |A| at each extreme
};

// Fits a record A(t) that starts at an extreme (released from rest): zero crossings interpolated
// linearly; the extremes are the largest |A| of each half cycle, refined by a parabola through the
// sample and its neighbours (the first is the record's first sample). Half cycles cut by the end
// of the record are left out. Throws std::runtime_error with fewer than two zero crossings.
StandingWaveFit fit_standing_wave(const std::vector<double>& time,
                                  const std::vector<double>& amplitude);

}  // namespace lituya::verify
