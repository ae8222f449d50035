#pragma once
// Writes a simulation's state as VTU files that ParaView opens: the solid points, the liquid
// points and the background grid, each with the fields chosen in [output]. Each set has one
// .pvd per stage (stage time, the clock of [post]) and one for the whole run (points.pvd,
// liquid.pvd, grid.pvd), on which time runs on from stage to stage. output/README.txt names
// every field with its unit and sign convention.
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lituya/common/vtu_writer.hpp"
#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

// One .pvd series as a checkpoint keeps it: the writer's name for it, its file (in the output
// folder) and its entries.
struct SeriesRecord {
  std::string name;
  std::string file;
  std::vector<PvdWriter::Entry> entries;
};

// The times of one frame: since the start of the run, and since the start of its stage.
struct FrameTimes {
  double run = 0;
  double stage = 0;
};

// The text of output/README.txt: every file of the output folder and every field they hold
// with these settings, with units and sign conventions.
std::string output_readme(const OutputSettings& settings, int dimension, bool has_liquid);

template <int dim>
class OutputWriter {
 public:
  OutputWriter(std::filesystem::path folder, OutputSettings settings);
  // Writes <stage>_points_NNNN.vtu (and _liquid_ with water, _grid_ if enabled) and updates
  // the .pvd files.
  void write(Simulation<dim>& simulation, const Stage& stage, double time, int index);
  const std::filesystem::path& folder() const { return folder_; }
  // The series written so far, and the series to go on from (a run resumed from a checkpoint:
  // its .pvd files then list the frames written before the checkpoint too).
  std::vector<SeriesRecord> series() const;
  void restore_series(const std::vector<SeriesRecord>& series);

 private:
  void write_points(const Simulation<dim>& simulation, const FrameTimes& times,
                    const std::filesystem::path& file) const;
  void write_liquid(const Simulation<dim>& simulation, const FrameTimes& times,
                    const std::filesystem::path& file) const;
  void write_grid(Simulation<dim>& simulation, const FrameTimes& times,
                  const std::filesystem::path& file) const;
  // The run time at which `stage` started.
  double stage_start(const std::string& stage);
  // Lists `file` in the stage's series of `set` ("points", "liquid", "grid") and the run's.
  void add_frame(const std::string& set, const Stage& stage, const FrameTimes& times,
                 const std::string& file);
  void write_readme(bool has_liquid) const;

  std::filesystem::path folder_;
  OutputSettings settings_;
  std::map<std::string, std::unique_ptr<PvdWriter>> series_;
  std::map<std::string, double> stage_start_;
  bool readme_written_ = false;
};

extern template class OutputWriter<2>;
extern template class OutputWriter<3>;

}  // namespace lituya::solver
