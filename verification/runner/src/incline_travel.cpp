#include "incline_travel.hpp"

#include <cmath>

#include "case_support.hpp"

namespace lituya::verify {

InclineTravel along_slope_travel(const std::filesystem::path& case_folder, const std::string& stage,
                                 double dx, double dy) {
  InclineTravel out;
  for (const Frame& f : read_series(case_folder, stage)) {
    int components = 0, mass_components = 0;
    const auto u = read_point_array(f.file, "displacement", components);
    const auto m = read_point_array(f.file, "mass", mass_components);
    double sum = 0, mass = 0;
    for (std::size_t p = 0; p < m.size(); ++p) {
      sum += m[p] * (u[components * p] * dx + u[components * p + 1] * dy);
      mass += m[p];
    }
    out.time.push_back(f.time);
    out.travel.push_back(mass > 0 ? sum / mass : NAN);
  }
  return out;
}

double fitted_acceleration(const InclineTravel& travel) {
  double st2 = 0, t4 = 0;
  for (std::size_t i = 0; i < travel.time.size(); ++i) {
    const double t2 = travel.time[i] * travel.time[i];
    st2 += travel.travel[i] * t2;
    t4 += t2 * t2;
  }
  return t4 > 0 ? 2 * st2 / t4 : NAN;
}

}  // namespace lituya::verify
