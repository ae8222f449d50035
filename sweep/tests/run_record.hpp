#pragma once
// A finished run of a sweep, as the tables of repeats and mesh convergence read it.
#include <string>
#include <utility>
#include <vector>

#include "lituya/sweep/sweep.hpp"

namespace lituya::sweep::testing {

inline RunRecord run(int number, std::vector<std::string> values, std::vector<double> measures,
                     RunStatus status = RunStatus::kOk) {
  RunRecord r;
  r.number = number;
  r.values = std::move(values);
  r.measures = std::move(measures);
  r.status = status;
  return r;
}

}  // namespace lituya::sweep::testing
