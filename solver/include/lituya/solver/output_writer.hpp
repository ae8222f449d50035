#pragma once
// Writes a simulation's state as VTU files that ParaView opens: the material points (position
// and the fields chosen in [output]) and the background grid (nodal mass and velocity), with
// one .pvd collection per stage and series so ParaView plays the time series.
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "lituya/common/vtu_writer.hpp"
#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

template <int dim>
class OutputWriter {
 public:
  OutputWriter(std::filesystem::path folder, OutputSettings settings);
  // Writes <stage>_points_NNNN.vtu (and _liquid_ with water, _grid_ if enabled) and updates
  // the .pvd files.
  void write(Simulation<dim>& simulation, const Stage& stage, double time, int index);
  const std::filesystem::path& folder() const { return folder_; }

 private:
  void write_points(const Simulation<dim>& simulation, const std::filesystem::path& file) const;
  void write_liquid(const Simulation<dim>& simulation, const std::filesystem::path& file) const;
  void write_grid(Simulation<dim>& simulation, const std::filesystem::path& file) const;

  std::filesystem::path folder_;
  OutputSettings settings_;
  std::map<std::string, std::unique_ptr<PvdWriter>> series_;
};

extern template class OutputWriter<2>;
extern template class OutputWriter<3>;

}  // namespace lituya::solver
