#include "seepage_column.hpp"

#include <gtest/gtest.h>

namespace lituya::verify {
namespace {

// The scene's column (verification/seepage): K_w = 2.15e5 Pa, E = 10 MPa, nu = 0.3.
SeepageColumn scene_column() {
  SeepageColumn c;
  c.constrained_modulus = SeepageColumn::constrained_modulus_of(1e7, 0.3);
  return c;
}

// Every cubic metre the pond loses has left through the plate or is still held by the column:
// the discrete balance of the transient update, to rounding.
TEST(SeepageColumn, PondLossIsOutflowPlusStorage) {
  const SeepageColumn c = scene_column();
  const auto r = c.transient(0.1, {0.1, 0.5, 1.0}, 40);
  for (std::size_t k = 0; k < r.pond_depth.size(); ++k)
    EXPECT_NEAR(0.1 - r.pond_depth[k], r.outflow[k] + r.stored[k], 1e-12);
  // The column releases water: its pore pressure falls from hydrostatic towards the steady
  // profile, by rho_w g (d + L) at the plate, about half that on average, times S L.
  const double released = c.storage() * 1000 * 9.81 * (0.1 + 0.3) / 2 * 0.3;
  EXPECT_NEAR(-r.stored.back(), released, 0.05 * released);
}

// Linear diffusion (Darcy alone) from a hydrostatic column whose plate is opened: the excess
// over the steady profile starts as rho_w g (d + L) times the depth fraction below the top and
// leaves through the top in proportion to its distance from the plate, so the pond keeps
// S rho_w g (d + L) L / 6 more than the steady reading says. The pond's own fall of 12 mm
// changes the steady profile by 3 % of the head, hence 5 %.
TEST(SeepageColumn, DarcyColumnKeepsASixthOfTheReleasedStorageInThePond) {
  SeepageColumn c = scene_column();
  c.forchheimer = false;
  const double kept = c.transient(0.1, {1.0}).pond_depth[0] - c.steady_depth(0.1, {1.0})[0];
  const double expected = c.storage() * 1000 * 9.81 * (0.1 + 0.3) * 0.3 / 6;
  EXPECT_NEAR(kept, expected, 0.05 * expected);
}

// What the pond keeps is the column's storage: ten times stiffer water and skeleton keep a
// tenth, and the steady reading is the limit of no storage.
TEST(SeepageColumn, WhatThePondKeepsScalesWithTheStorage) {
  const SeepageColumn c = scene_column();
  SeepageColumn stiff = c;
  stiff.bulk_modulus *= 10;
  stiff.constrained_modulus *= 10;
  const double steady = c.steady_depth(0.1, {0.6})[0];
  const double kept = c.transient(0.1, {0.6}).pond_depth[0] - steady;
  const double kept_stiff = stiff.transient(0.1, {0.6}).pond_depth[0] - steady;
  EXPECT_GT(kept, 2e-4);  // the scene's column: a third of a millimetre
  EXPECT_NEAR(kept_stiff, kept / 10, 0.05 * kept / 10);
}

// The default 100 cells resolve the column: 200 give the same pond to a micrometre.
TEST(SeepageColumn, TransientPondIsConvergedInTheCells) {
  const SeepageColumn c = scene_column();
  EXPECT_NEAR(c.transient(0.1, {1.0}).pond_depth[0], c.transient(0.1, {1.0}, 200).pond_depth[0],
              1e-6);
}

}  // namespace
}  // namespace lituya::verify
