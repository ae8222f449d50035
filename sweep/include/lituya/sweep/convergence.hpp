#pragma once
// Mesh convergence of a sweep's measures: a sweep over `mesh.cell_size` reports, for each
// measure, what its three finest resolutions say about where the value goes as the cells shrink.
//
// Why: a figure that moves with the cell size is not a result until a refinement study shows
// where it goes (issue 8, item 5 asks for the Case B crests' three-resolution Richardson
// estimate and its observed order). Done by hand it was done wrong once: an order-1.55 estimate
// from three coarse resolutions was withdrawn when finer ones fell below it (user manual 3).
//
// How (Celik et al. 2008, "Procedure for estimation and reporting of uncertainty due to
// discretization in CFD applications", J. Fluids Eng. 130, 078001; Roache 1994 for the grid
// convergence index): with h1 < h2 < h3 and values f1, f2, f3, r21 = h2 / h1, r32 = h3 / h2,
// e21 = f2 - f1, e32 = f3 - f2, the ratio R = e21 / e32 says how the value behaves:
//   0 < R < ln r21 / ln r32 (R < 1 for equal ratios)
//              monotone convergence: the observed order p > 0 solves
//                p ln r21 = ln(e32 / e21) + ln((r21^p - 1) / (r32^p - 1))
//              (Celik's eq. 3 without its absolute value, which admits spurious orders when
//              r21 != r32; for r21 = r32 = r it is ln(e32 / e21) / ln r), the extrapolated value
//              is f_ext = (r21^p f1 - f2) / (r21^p - 1) and the fine grid convergence index
//              GCI = 1.25 |(f1 - f2) / f1| / (r21^p - 1);
//   R < 0      oscillatory: the changes alternate in sign, no order or extrapolation;
//   R >= ln r21 / ln r32
//              not converging: the finest step changed the value by more than any positive
//              order allows (at least as much as the one before, for equal ratios); no order
//              or extrapolation. The bound is where the right-hand side's p -> 0 limit lies.
// An order far above the scheme's own (linear shape functions: at most 2) means the values are
// not yet in the asymptotic range (or are levelling off by chance); the note says so.
#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "lituya/sweep/definition.hpp"
#include "lituya/sweep/repeats.hpp"

namespace lituya::sweep {

struct SweepResult;
struct RunRecord;

// Above this observed order the three values are not in the asymptotic range of a scheme
// with linear shape functions (formal order at most 2): they level off by chance, or the
// coarsest is too coarse. The estimate's note says so, and the report's plots leave such an
// extrapolation out.
inline constexpr double kHighestPlausibleOrder = 3.0;

// A run's value of the cell size (kCellSizeKey, definition.hpp): NaN unless the whole text is
// a positive number.
double run_cell_size(const RunRecord& run, std::size_t cell_key);

enum class ConvergenceBehaviour { kUnchanged, kMonotone, kOscillatory, kNotConverging };
// "unchanged", "monotone", "oscillatory", "not converging"
std::string behaviour_text(ConvergenceBehaviour behaviour);

struct RichardsonEstimate {
  std::array<double, 3> cell_size{};  // h1 < h2 < h3 (fine, medium, coarse), m
  std::array<double, 3> value{};      // f1, f2, f3
  ConvergenceBehaviour behaviour = ConvergenceBehaviour::kNotConverging;
  double change_fine = 0;   // (f1 - f2) / |f2|: the last refinement's relative change
  double order = 0;         // observed order p; NaN unless monotone (or not found)
  double extrapolated = 0;  // f_ext; NaN unless monotone
  double gci_fine = 0;      // relative grid convergence index of f1; NaN unless monotone
  std::string note;         // what to make of it, empty when nothing to add
};

// The estimate from three (cell size, value) pairs in any order. Throws std::invalid_argument
// for cell sizes that are not positive, finite and distinct, or values that are not finite.
RichardsonEstimate richardson_estimate(const std::array<double, 3>& cell_size,
                                       const std::array<double, 3>& value);

// One estimate of a sweep: a measure over the runs that differ only in `mesh.cell_size`.
struct MeshConvergenceRow {
  std::string group;          // the other parameters' values ("key=value ..."), empty for none
  std::string measure;        // as in sweep.csv
  std::array<int, 3> runs{};  // run numbers of h1, h2, h3 (the first repeat of each)
  // The runs' values at h1, h2, h3: one run each, or the repeats (repeats.hpp), whose means
  // the estimate is made from (sd NaN for a single run).
  std::array<Spread, 3> spread{};
  RichardsonEstimate estimate;
};

// The estimates of a sweep whose parameters include `mesh.cell_size`: for each measure and each
// set of values of the other parameters (the repeat key aside), from the three finest distinct
// cell sizes among the runs that finished with a value of that measure, each size's value the
// mean of its repeats. With repeats, the note says when the last change is within twice its
// standard error. Nothing for other sweeps, or where fewer than
// three cell sizes are left. With `cell_sizes` (three distinct positive sizes, in any order;
// std::invalid_argument otherwise) the estimate is made from those sizes instead of the three
// finest, and nothing for a measure that lacks a finished run at one of them.
std::vector<MeshConvergenceRow> mesh_convergence(const SweepResult& result,
                                                 const std::vector<double>& cell_sizes = {});

// DIR/convergence.csv: one row per estimate (file-formats manual).
void write_convergence_table(const std::filesystem::path& file,
                             const std::vector<MeshConvergenceRow>& rows);

// The table printed at the end of the sweep's report (`chosen_sizes`: the estimates were made
// from sizes the user chose, not the three finest; the heading says so).
std::string format_convergence(const std::vector<MeshConvergenceRow>& rows,
                               bool chosen_sizes = false);

}  // namespace lituya::sweep
