#include "case_support.hpp"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/csv_writer.hpp"
#include "lituya/post/postprocess.hpp"
#include "lituya/pre/preprocess.hpp"
#include "lituya/solver/solve.hpp"
#include "lituya/sweep/measures.hpp"

namespace lituya::verify {

bool CaseResult::passed() const {
  if (!error.empty() || checks.empty()) return false;
  for (const Check& c : checks)
    if (!c.passed) return false;
  return true;
}

void add_check(CaseResult& result, const std::string& quantity, const std::string& unit,
               double measured, double reference, double tolerance) {
  Check c{quantity, unit, measured, reference, tolerance, false};
  c.passed = std::isfinite(measured) && std::abs(measured - reference) <= tolerance;
  result.checks.push_back(c);
}

solver::SolveOptions report_solve_options(int threads) {
  solver::SolveOptions options;
  options.threads = threads;
  options.overwrite = true;
  options.keep_previous_output = false;  // the report is rebuilt each time: no output.previous
  return options;
}

std::filesystem::path run_scene(const CaseContext& context, const std::filesystem::path& scene,
                                const std::filesystem::path& case_folder) {
  pre::preprocess(scene, case_folder, /*overwrite=*/true);
  solver::solve_case(case_folder, report_solve_options(context.threads));
  return case_folder;
}

std::filesystem::path run_scene(const CaseContext& context) {
  return run_scene(context,
                   context.source / (context.full ? "scene_full.toml" : "scene_quick.toml"),
                   context.work / "case");
}

double largest_in_history(const std::filesystem::path& case_folder, const std::string& stage,
                          const std::string& column) {
  const auto file = (case_folder / "output" / (stage + "_history.csv")).string();
  double largest = 0;  // blank cells read as NaN, which std::max passes over
  for (double value : sweep::read_csv(file, true).column(column, file))
    largest = std::max(largest, value);
  return largest;
}

std::vector<Frame> read_series(const std::filesystem::path& case_folder, const std::string& stage,
                               const std::string& kind) {
  std::vector<Frame> frames;
  for (const auto& e : post::read_pvd(case_folder / "output" / (stage + "_" + kind + ".pvd")))
    frames.push_back({e.time, e.file});
  return frames;
}

vtkSmartPointer<vtkUnstructuredGrid> read_unstructured_grid(const std::filesystem::path& vtu) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  if (!grid || grid->GetNumberOfPoints() == 0)
    throw std::runtime_error("cannot read " + vtu.string());
  return grid;
}

std::vector<double> read_point_array(const std::filesystem::path& vtu, const std::string& name,
                                     int& components) {
  auto grid = read_unstructured_grid(vtu);
  vtkDataArray* a = grid->GetPointData()->GetArray(name.c_str());
  if (!a) throw std::runtime_error(vtu.string() + " has no point array '" + name + "'");
  components = a->GetNumberOfComponents();
  std::vector<double> out(static_cast<std::size_t>(a->GetNumberOfTuples()) * components);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int k = 0; k < components; ++k) out[i * components + k] = a->GetComponent(i, k);
  return out;
}

std::vector<double> read_positions(const std::filesystem::path& vtu) {
  auto grid = read_unstructured_grid(vtu);
  std::vector<double> out(3 * grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) grid->GetPoint(i, &out[3 * i]);
  return out;
}

void write_csv(const std::filesystem::path& file, const std::string& header,
               const std::vector<std::vector<double>>& rows) {
  // The header is written as the cases give it, comma-separated plain names.
  CsvWriter table(csv_split(header));
  for (const auto& row : rows) table.row(row);
  table.write(file);
}

post::WaveCrest complete_first_wave(const std::vector<double>& time,
                                    const std::vector<double>& eta) {
  const double onset = 0.005;  // m above still water
  post::WaveCrest c = post::first_wave_crest(time, eta, onset);
  if (!c.complete) c.time = c.height = c.area = NAN;
  return c;
}

void run_at_cell_sizes(const CaseContext& context, CaseResult& result, const CellSizes& h,
                       const std::string& measure, double tolerance, SceneRun run_one) {
  if (!context.full) {
    run_one(context, "scene_quick.toml", "quick", h.quick, result);
    return;
  }
  const double coarse = run_one(context, "scene_full_coarse.toml", "coarse", h.coarse, result);
  const double fine = run_one(context, "scene_full_fine.toml", "fine", h.fine, result);
  std::ostringstream quantity;
  quantity << "relative change of " << measure << " from " << h.coarse << " to " << h.fine << " m";
  add_check(result, quantity.str(), "-", std::abs(fine - coarse) / coarse, 0.0, tolerance);
}

std::string cell_size_tag(double cell_size) {
  return " (h = " + std::to_string(cell_size).substr(0, 6) + " m)";
}

}  // namespace lituya::verify
