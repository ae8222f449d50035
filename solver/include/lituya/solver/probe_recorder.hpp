#pragma once
// Time histories written beside the VTU series: the [[probe]] sensors of the case
// (output/probes/<name>.csv) and each stage's history of time step, kinetic energy per phase
// and largest point speed (output/<stage>_history.csv). manuals/file-formats.md describes the
// columns.
//
// Both are sampled between steps, from solve.cpp's output and after-step callbacks, so the time
// loop itself is untouched; a sample allocates nothing but the growth of its in-memory table.
// A probe sample costs one pass over the points (the few nodes around the probe are summed
// directly from the points, without touching the simulation's nodal arrays, which the next
// step reads); a history row costs three. History rows are taken about a thousand times per
// stage plus once per output; a probe samples at each output and, with an interval, at most
// once per step.
//
// The tables are kept in memory and written whole, atomically, at each output, before each
// checkpoint and at the end of each stage, so a file on disk is always a complete table, and at
// a checkpoint it holds every row sampled up to that state. A resumed run (restart()) drops the
// rows sampled after the checkpoint it goes on from and samples them again, so no row is lost
// or written twice.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lituya/common/csv_writer.hpp"
#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

// Values of the probe fields at one place, NaN where no point of the phase is near (written
// as an empty CSV field).
struct ProbeValues {
  double pore_pressure = 0;         // Pa, compression positive
  Voigt6 effective_stress;          // Pa, tension positive: xx, yy, zz, xy, yz, xz
  Eigen::Vector3d velocity;         // m/s, of the soil skeleton
  Eigen::Vector3d liquid_velocity;  // m/s
  double porosity = 0;              // -, 1 where there are no grains
};

// The fields at x in `cell` (shape values `shape`): each phase's point values are summed onto
// the cell's nodes with the shape-function weights of the points in the cells around them
// (velocities weighted by mass, stress and pressure by volume, as the solver's own nodal
// fields), then interpolated at x over the nodes that have points of the phase. Porosity is
// eq. (5) on the nodes, 1 - (grain volume near the node) / (lumped mesh volume of the node),
// as the solver computes the porosity the water sees.
// `patch`, when given, marks the cells that share a node with `cell` (probe_patch()): points
// elsewhere are then skipped at the cost of one look-up, instead of comparing node numbers.
template <int dim>
ProbeValues interpolate_probe(const Simulation<dim>& simulation, int cell,
                              const typename Mesh<dim>::Shape& shape,
                              const std::vector<double>& node_mesh_volume,
                              const std::vector<unsigned char>* patch = nullptr);

// 1 for the cells of `mesh` that share a node with `cell`, 0 for the others.
template <int dim>
std::vector<unsigned char> probe_patch(const Mesh<dim>& mesh, int cell);

// The run-wide time at which a stage starts: the sum of the simulated times of the stages
// before it, added in order (as output_writer.cpp's run clock).
double run_time_at_stage_start(const std::vector<StageReport>& finished_stages);

template <int dim>
class ProbeRecorder {
 public:
  // Locates the fixed probes and checks the point probes' ids; InputError naming stages.toml
  // when a probe lies outside the mesh or its point does not exist.
  // `probes` are the case's (description().probes); tests pass their own.
  ProbeRecorder(const Simulation<dim>& simulation, const std::vector<Probe>& probes,
                std::filesystem::path output_folder);

  // Goes on from a checkpoint: the rows of the stages before `stage` are kept, those of
  // `stage` only up to stage time `within` (none with no `within`: the checkpoint is at the
  // stage's start), later ones dropped. Files of stages after the checkpoint are removed.
  void restart(const std::vector<Stage>& stages, std::size_t stage, std::optional<double> within);

  // Before a stage runs (or goes on from a checkpoint at stage time `resume_time`):
  // `run_start` is the run time at its start.
  void begin_stage(const Stage& stage, double run_start, std::optional<double> resume_time);
  // At an output of the running stage (stage time t): every probe and a history row.
  // A history row takes the simulation's boundary forces summed since the row before
  // (Simulation::take_wall_impulses), the only change it makes to the simulation.
  void at_output(Simulation<dim>& simulation, double t);
  // After a step (stage time t): the probes and history rows that are due.
  void after_step(Simulation<dim>& simulation, double t);
  // Writes every table (atomically).
  void write() const;

  // The columns of a probe's table, and of the history (the columns every stage has; a
  // stage's table adds its walls' columns, wall_columns()).
  static std::vector<std::string> probe_header(const Probe& probe);
  static std::vector<std::string> history_header();
  // Rows of the history per stage (besides one per output).
  static constexpr int kHistoryRowsPerStage = 1000;

 private:
  struct Site {
    Probe probe;
    std::filesystem::path file;
    int cell = -1;  // fixed probes: the cell that holds the position
    typename Mesh<dim>::Shape shape;
    CsvWriter table;
    std::vector<unsigned char> patch;  // fixed probes: probe_patch() of `cell`
    long next_mark = 1;                // index of the next multiple of the interval to sample at
    double last_sample = -1;           // stage time of the last row of the running stage
    std::size_t point_index = 0;       // point probes: where the point's id was last found
  };
  // A boundary name of the running stage and the conditions of that name it holds
  // (tractions are loads, not walls).
  struct Wall {
    std::string name;
    std::vector<std::size_t> conditions;  // indices into the case's boundaries
    bool effective_normal = false;        // a contact wall in a case with water
  };
  std::vector<std::string> wall_columns() const;
  void sample(const Simulation<dim>& simulation, Site& site, double t);
  void history_row(Simulation<dim>& simulation, double t);
  std::filesystem::path history_file(const std::string& stage) const;

  std::filesystem::path folder_;
  std::vector<double> node_mesh_volume_;
  std::vector<Site> sites_;
  // The running stage.
  Stage stage_;
  double run_start_ = 0;
  std::optional<CsvWriter> history_;
  std::string history_stage_;
  long next_history_mark_ = 1;
  double last_history_time_ = -1;
  // The case's boundary conditions, and the walls of the running stage (each history row
  // writes the mean force on them since the row before).
  std::vector<BoundaryCondition> boundaries_;
  bool has_liquid_ = false;
  std::vector<Wall> walls_;
  std::vector<typename Simulation<dim>::WallImpulse> wall_impulses_;  // scratch of a row
};

extern template class ProbeRecorder<2>;
extern template class ProbeRecorder<3>;

}  // namespace lituya::solver
