// Mesh convergence of a sweep's measures (convergence.hpp says why and how).
#include "lituya/sweep/convergence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

#include "lituya/common/csv_writer.hpp"
#include "lituya/sweep/measures.hpp"
#include "lituya/sweep/progress.hpp"
#include "lituya/sweep/repeats.hpp"
#include "lituya/sweep/sweep.hpp"

namespace lituya::sweep {

namespace {

// The observed order: the p > 0 with g(p) = e32 / e21, g(p) = r21^p (r32^p - 1) / (r21^p - 1),
// which is Celik et al. (2008) eq. (3), p ln r21 = ln(e32 / e21) + ln((r21^p - 1) / (r32^p - 1)),
// without its absolute value. g rises monotonically from ln r32 / ln r21 (p -> 0) without
// bound, so a root exists exactly when e32 / e21 exceeds ln r32 / ln r21 (the caller checks),
// and bisection on ln g finds it. (The absolute value of the paper's fixed-point form admits a
// spurious "order" for ratios below that bound when r21 != r32: Case B's X1 at 0.005 / 0.0075 /
// 0.015 m read as order 8.5 that way, where no positive order fits.) NaN above p = 64.
double observed_order(double r21, double r32, double ratio) {
  const double target = std::log(ratio);  // ln(e32 / e21)
  const double log_r21 = std::log(r21), log_r32 = std::log(r32);
  const auto log_g = [&](double p) {
    return p * log_r21 + std::log(std::expm1(p * log_r32)) - std::log(std::expm1(p * log_r21));
  };
  double low = 0, high = 64;
  if (!(log_g(high) >= target)) return NAN;
  for (int iteration = 0; iteration < 200 && high - low > 1e-14 * high; ++iteration) {
    const double p = 0.5 * (low + high);
    (log_g(p) < target ? low : high) = p;
  }
  return 0.5 * (low + high);
}

std::string percent(double fraction) {
  if (!std::isfinite(fraction)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%+.1f %%", 100.0 * fraction);
  return text;
}

// The grid convergence index, to two significant digits (it may be a small fraction of 1 %).
std::string gci_percent(double fraction) {
  if (!std::isfinite(fraction)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.2g %%", 100.0 * fraction);
  return text;
}

}  // namespace

double run_cell_size(const RunRecord& run, std::size_t cell_key) {
  try {
    std::size_t used = 0;
    const double h = std::stod(run.values[cell_key], &used);
    return used == run.values[cell_key].size() && h > 0 ? h : NAN;
  } catch (const std::exception&) {
    return NAN;
  }
}

std::string behaviour_text(ConvergenceBehaviour behaviour) {
  switch (behaviour) {
    case ConvergenceBehaviour::kUnchanged:
      return "unchanged";
    case ConvergenceBehaviour::kMonotone:
      return "monotone";
    case ConvergenceBehaviour::kOscillatory:
      return "oscillatory";
    case ConvergenceBehaviour::kNotConverging:
      return "not converging";
  }
  return "";
}

RichardsonEstimate richardson_estimate(const std::array<double, 3>& cell_size,
                                       const std::array<double, 3>& value) {
  std::array<int, 3> order{0, 1, 2};
  for (int k = 0; k < 3; ++k) {
    if (!(cell_size[k] > 0) || !std::isfinite(cell_size[k]))
      throw std::invalid_argument("a cell size must be positive and finite");
    if (!std::isfinite(value[k])) throw std::invalid_argument("a value must be finite");
  }
  std::sort(order.begin(), order.end(), [&](int a, int b) { return cell_size[a] < cell_size[b]; });
  RichardsonEstimate e;
  for (int k = 0; k < 3; ++k) {
    e.cell_size[k] = cell_size[order[k]];
    e.value[k] = value[order[k]];
  }
  if (e.cell_size[0] == e.cell_size[1] || e.cell_size[1] == e.cell_size[2])
    throw std::invalid_argument("the three cell sizes must differ");
  const auto [f1, f2, f3] = e.value;
  const double r21 = e.cell_size[1] / e.cell_size[0], r32 = e.cell_size[2] / e.cell_size[1];
  const double e21 = f2 - f1, e32 = f3 - f2;
  e.change_fine = f2 != 0 ? (f1 - f2) / std::abs(f2) : (f1 == f2 ? 0.0 : NAN);
  e.order = e.extrapolated = e.gci_fine = NAN;
  if (e21 == 0 && e32 == 0) {
    e.behaviour = ConvergenceBehaviour::kUnchanged;
    e.extrapolated = f1;
    e.gci_fine = 0;
    return e;
  }
  const double ratio = e32 != 0 ? e21 / e32 : INFINITY;  // R of the header
  if (ratio < 0) {
    e.behaviour = ConvergenceBehaviour::kOscillatory;
    e.note = "the changes alternate in sign: no order or extrapolation; refine further";
    return e;
  }
  // A positive order needs R < ln r21 / ln r32 (observed_order); with equal ratios, R < 1.
  if (!(ratio < std::log(r21) / std::log(r32))) {
    e.behaviour = ConvergenceBehaviour::kNotConverging;
    e.note = r21 == r32 ? "the finest step changed the value at least as much as the one before"
                        : "the finest step changed the value by more than any positive order "
                          "allows for these refinement ratios";
    return e;
  }
  e.behaviour = ConvergenceBehaviour::kMonotone;
  if (e21 == 0) {  // the two finest agree exactly: settled, order unbounded
    e.extrapolated = f1;
    e.gci_fine = 0;
    e.note = "the two finest values are equal";
    return e;
  }
  e.order = observed_order(r21, r32, e32 / e21);
  if (!std::isfinite(e.order)) {
    e.note = "the observed order could not be found";
    return e;
  }
  const double growth = std::pow(r21, e.order);
  e.extrapolated = (growth * f1 - f2) / (growth - 1.0);
  e.gci_fine = f1 != 0 ? 1.25 * std::abs((f1 - f2) / f1) / (growth - 1.0) : NAN;
  if (e.order > kHighestPlausibleOrder)
    e.note = "order above 3: not in the asymptotic range, read as levelling off, not as a limit";
  return e;
}

std::vector<MeshConvergenceRow> mesh_convergence(const SweepResult& result,
                                                 const std::vector<double>& cell_sizes) {
  if (!cell_sizes.empty()) {
    std::vector<double> sorted = cell_sizes;
    std::sort(sorted.begin(), sorted.end());
    if (sorted.size() != 3 || !(sorted[0] > 0) || !std::isfinite(sorted[2]) ||
        !(sorted[0] < sorted[1]) || !(sorted[1] < sorted[2]))
      throw std::invalid_argument("give three distinct positive cell sizes");
  }
  // A run's cell size is one of the chosen ones when it agrees to a part in 1e9 (the sizes
  // are read from text in both places, but may be written differently: 0.0050 and 5e-3).
  const auto chosen = [&](double h) {
    if (cell_sizes.empty()) return true;
    return std::any_of(cell_sizes.begin(), cell_sizes.end(),
                       [h](double c) { return std::abs(h - c) <= 1e-9 * c; });
  };
  const auto key = std::find(result.parameters.begin(), result.parameters.end(), kCellSizeKey);
  if (key == result.parameters.end()) return {};
  const std::size_t cell_key = static_cast<std::size_t>(key - result.parameters.begin());
  // Runs grouped by the values of the other parameters, in the order they first appear.
  std::vector<std::string> group_order;
  std::map<std::string, std::vector<const RunRecord*>> groups;
  for (const RunRecord& run : result.runs) {
    if (run.status != RunStatus::kOk) continue;
    const std::string group = group_of(result, run, cell_key);  // without the repeat key
    if (!groups.count(group)) group_order.push_back(group);
    groups[group].push_back(&run);
  }
  std::vector<MeshConvergenceRow> rows;
  for (const std::string& group : group_order) {
    for (std::size_t m = 0; m < result.measures.size(); ++m) {
      // The runs of each distinct cell size with a value: one, or the repeats (repeats.hpp),
      // whose mean is the value.
      std::map<double, std::vector<const RunRecord*>> by_size;
      for (const RunRecord* run : groups[group]) {
        const double h = run_cell_size(*run, cell_key);
        if (!(h > 0) || !chosen(h) || !std::isfinite(run->measures[m])) continue;
        by_size[h].push_back(run);
      }
      if (by_size.size() < 3) continue;
      MeshConvergenceRow row;
      row.group = group;
      row.measure = result.measures[m];
      std::array<double, 3> h{}, f{};
      auto it = by_size.begin();
      for (int k = 0; k < 3; ++k, ++it) {
        std::vector<double> values;
        for (const RunRecord* run : it->second) values.push_back(run->measures[m]);
        h[k] = it->first;
        row.spread[k] = spread_of(values);
        f[k] = row.spread[k].mean;
        row.runs[k] = it->second.front()->number;
      }
      row.estimate = richardson_estimate(h, f);
      // With repeats: is the last refinement's change larger than the readings' own scatter?
      const Spread& fine = row.spread[0];
      const Spread& medium = row.spread[1];
      if (fine.count > 1 && medium.count > 1) {
        const double standard_error =
            std::sqrt(fine.sd * fine.sd / fine.count + medium.sd * medium.sd / medium.count);
        if (std::abs(fine.mean - medium.mean) < 2.0 * standard_error) {
          const std::string within =
              "the last change is within twice its standard error from the repeats: not resolved";
          row.estimate.note =
              row.estimate.note.empty() ? within : row.estimate.note + "; " + within;
        }
      }
      rows.push_back(row);
    }
  }
  return rows;
}

void write_convergence_table(const std::filesystem::path& file,
                             const std::vector<MeshConvergenceRow>& rows) {
  CsvWriter table({"group",          "measure",        "runs",
                   "h_fine",         "h_medium",       "h_coarse",
                   "value_fine",     "value_medium",   "value_coarse",
                   "change_fine",    "behaviour",      "observed_order",
                   "extrapolated",   "gci_fine",       "repeats_fine",
                   "repeats_medium", "repeats_coarse", "sd_fine",
                   "sd_medium",      "sd_coarse",      "note"});
  for (const MeshConvergenceRow& row : rows) {
    const RichardsonEstimate& e = row.estimate;
    table.text(row.group).text(row.measure);
    table.text(std::to_string(row.runs[0]) + " " + std::to_string(row.runs[1]) + " " +
               std::to_string(row.runs[2]));
    for (double h : e.cell_size) table.number(h);
    for (double f : e.value) table.number(f);
    table.number(e.change_fine).text(behaviour_text(e.behaviour));
    table.number(e.order).number(e.extrapolated).number(e.gci_fine);
    for (const Spread& s : row.spread) table.number(s.count);
    for (const Spread& s : row.spread) table.number(s.sd);
    table.text(e.note);
    table.end_row();
  }
  table.write(file);
}

std::string format_convergence(const std::vector<MeshConvergenceRow>& rows, bool chosen_sizes) {
  if (rows.empty()) return "";
  std::vector<std::vector<std::string>> lines{{"measure", "cell sizes (m)", "values", "last change",
                                               "behaviour", "order", "extrapolated", "GCI"}};
  const bool grouped = std::any_of(rows.begin(), rows.end(),
                                   [](const MeshConvergenceRow& r) { return !r.group.empty(); });
  if (grouped) lines[0].insert(lines[0].begin(), "with");
  for (const MeshConvergenceRow& row : rows) {
    const RichardsonEstimate& e = row.estimate;
    std::vector<std::string> line{
        row.measure + " (" + measure_unit(row.measure) + ")",
        short_number(e.cell_size[0]) + " " + short_number(e.cell_size[1]) + " " +
            short_number(e.cell_size[2]),
        short_number(e.value[0]) + " " + short_number(e.value[1]) + " " + short_number(e.value[2]),
        percent(e.change_fine),
        behaviour_text(e.behaviour),
        short_number(e.order),
        short_number(e.extrapolated),
        gci_percent(e.gci_fine)};
    if (grouped) line.insert(line.begin(), row.group.empty() ? "-" : row.group);
    lines.push_back(line);
  }
  std::ostringstream out;
  out << "mesh convergence (" << (chosen_sizes ? "the three chosen" : "three finest")
      << " cell sizes, fine first; Richardson extrapolation and grid convergence index after "
         "Celik et al. 2008):\n"
      << align_columns(lines);
  for (const MeshConvergenceRow& row : rows)
    if (!row.estimate.note.empty())
      out << row.measure << (row.group.empty() ? "" : " (" + row.group + ")") << ": "
          << row.estimate.note << "\n";
  return out.str();
}

}  // namespace lituya::sweep
