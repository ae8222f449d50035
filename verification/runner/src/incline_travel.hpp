#pragma once
// A block sliding down an incline (verification/sliding_block, verification/saturated_block):
// how far its points travel along the slope, and the constant acceleration that fits it.
#include <filesystem>
#include <string>
#include <vector>

namespace lituya::verify {

struct InclineTravel {
  std::vector<double> time, travel;  // s, m (down the slope positive)
};

// The mass-weighted mean displacement of the solid points along the unit vector (dx, dy), at
// each output of `stage`.
InclineTravel along_slope_travel(const std::filesystem::path& case_folder, const std::string& stage,
                                 double dx, double dy);

// Least squares of s = a t^2 / 2 through the origin: a = 2 sum(s t^2) / sum(t^4); NaN without
// a sample after t = 0.
double fitted_acceleration(const InclineTravel& travel);

}  // namespace lituya::verify
