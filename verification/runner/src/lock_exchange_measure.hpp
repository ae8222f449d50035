#pragma once
// The measures of verification/lock_exchange: where the heavy current's front is, how fast it
// runs, and how fast an energy-conserving lock exchange runs.
#include <vector>

namespace lituya::verify {

// The front of a current along the bed: the largest x of the points (positions, 3 per point)
// lower than `below`, after setting aside the `strays` farthest of them (single points thrown
// ahead are not the current). NaN when no more than `strays` points are that low.
double current_front(const std::vector<double>& positions, double below, int strays);

// The least-squares slope of front(time) over the samples whose front lies in [low, high]: the
// current's speed over that stretch. NaN with fewer than three samples there.
double front_speed(const std::vector<double>& time, const std::vector<double>& front, double low,
                   double high);

// The front speed of a full-depth lock exchange of two fluids of densities heavy > light in a
// channel of depth H, energy conserving and in the Boussinesq limit (Benjamin 1968, J. Fluid
// Mech. 31, 209; Shin, Dalziel and Linden 2004, J. Fluid Mech. 521, 1):
//     U = sqrt(g' H) / 2,   g' = g (heavy - light) / light.
double lock_exchange_speed(double gravity, double depth, double heavy, double light);

}  // namespace lituya::verify
