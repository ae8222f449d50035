#pragma once
// The infiltration case's reference (verification/infiltration/README.md): a pond of depth d0
// over dry sand, whose water enters the pores from t = 0. Green and Ampt (1911, J. Agric. Sci.
// 4, 1): behind a sharp wetting front at depth L the pores are full, ahead of it they are empty
// and the water's pressure there is zero (the model has no capillary suction, so the suction
// head of the front is zero). The water in the wetted zone is driven by the pond's head and
// its own weight, G = rho_w g (d + L) / L, against the drag of eqs. (23), (24) (Ergun's law:
// SeepageColumn::flux), and the front moves at the pores' speed, n dL/dt = q(G). With a falling
// head the pond gives what the pores take, d = d0 - n L.
#include <vector>

#include "seepage_column.hpp"

namespace lituya::verify {

struct GreenAmptColumn {
  SeepageColumn sand;        // porosity, grains and water (its length and storage are not used)
  bool falling_head = true;  // false: the pond's depth is held at d0

  // The front's depth L (m) at each of `times` (ascending, s), L(0) = 0. From the time the
  // front takes to each depth, t(L) = integral of n / q(G(L')) dL' from 0 to L, by Simpson's
  // rule in s = sqrt(L) (the integrand n / q vanishes like sqrt(L) at the surface, where G is
  // unbounded), on `intervals` equal intervals up to the depth where the pond runs dry (or
  // `max_depth`), inverted by linear interpolation in s. Throws when a time lies beyond it.
  std::vector<double> front_depth(double d0, const std::vector<double>& times, double max_depth,
                                  int intervals = 20000) const;
  // The pond's depth at the front's depth L.
  double pond_depth(double d0, double front) const;
};

}  // namespace lituya::verify
