#pragma once
// The explicit MPM time loop for the solid phase (dry granular flows), eqs. (11) and (19)-(22)
// of the reference paper with n and the water terms absent: momentum balance on the nodes of
// the background mesh, stress update at the material points.
//
// With liquid points (two-layer two-phase MPM, section 2) each step also carries the water:
// nodes hold liquid mass, momentum and force beside the solid's, the porosity field comes from
// the solid points, the pore-pressure gradient is shared between the phases by porosity
// (eqs. 15, 16), the drag (23) couples the nodal velocities implicitly, and the liquid
// pressure follows eq. (8). A dry case allocates none of this (two_phase.cpp).
//
// One step (MUSL, Sulsky et al. 1994; USL skips step 4):
//   1. points -> nodes: mass, momentum, internal force -V sigma . grad N, gravity m g;
//   2. nodes: local damping, velocity update, boundary conditions;
//   3. nodes -> points: velocity (FLIP/PIC blend), position, displacement;
//   4. points -> nodes again: momentum of the updated point velocities, boundary conditions;
//   5. points: strain and spin increments from the nodal velocities, Jaumann-rotated stress,
//      constitutive update, volume update, relocation in the mesh, stability checks.
#include <cmath>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lituya/solver/boundary_conditions.hpp"
#include "lituya/solver/case_description.hpp"
#include "lituya/solver/conjugate_gradient.hpp"
#include "lituya/solver/crossed_quadrangles.hpp"
#include "lituya/solver/liquid_points.hpp"
#include "lituya/solver/material_points.hpp"
#include "lituya/solver/mesh.hpp"
#include "lituya/solver/mohr_coulomb.hpp"
#include "lituya/solver/nodal_average.hpp"
#include "lituya/solver/nodal_scatter.hpp"
#include "lituya/solver/phase.hpp"
#include "lituya/solver/transfer_damping.hpp"
#include "lituya/solver/water_in_flight.hpp"
#include "lituya/solver/xpic.hpp"

namespace lituya::solver {

struct StageReport {
  std::string stage;
  long steps = 0;
  double simulated_time = 0;  // s
  double wall_time = 0;       // s
  double point_steps_per_second = 0;
  std::size_t peak_memory = 0;  // bytes (process peak resident set)
  std::string stop_reason;      // "duration reached", "kinetic energy ratio below ..."
};

// Called at each output time of a stage: (stage, stage time, output index).
using OutputCallback = std::function<void(const Stage&, double, int)>;

// Where a running stage stands between two steps: what run_stage keeps besides the
// simulation's own state, so that a checkpoint (checkpoint.hpp) can continue the stage exactly.
struct StageProgress {
  double time = 0;                // s since the start of the stage
  int next_output_index = 0;      // the number of the next output file
  double next_output_time = 0;    // s, stage time of the next scheduled output
  double max_kinetic_energy = 0;  // quasi-static stop criterion: the peak so far
  long steps = 0;                 // steps taken in the stage
  double wall_time = 0;           // s of wall time spent in the stage so far
};

// Called after every step of a stage, its outputs written (checkpoints, stop requests).
using StepCallback = std::function<void(const Stage&, const StageProgress&)>;

namespace detail {
template <int dim>
struct CheckpointAccess;  // checkpoint.cpp: reads and restores the state below
}  // namespace detail

template <int dim>
class Simulation {
 public:
  using Vec = Eigen::Matrix<double, dim, 1>;
  using Shape = typename Mesh<dim>::Shape;

  // `constraints[i]` belongs to `description.boundaries[i]`. Points must lie in the mesh
  // (their `cell` is a valid starting cell or -1).
  // `liquid` may be empty (a dry case): then no liquid-phase storage is allocated.
  Simulation(CaseDescription description, Mesh<dim> mesh, MaterialPoints<dim> points,
             std::vector<NodalConstraint<dim>> constraints, LiquidPoints<dim> liquid = {});

  void set_threads(int threads);
  int threads() const { return threads_; }
  // Where the progress line goes (nullptr: silent).
  void set_progress_stream(std::ostream* stream) { progress_ = stream; }

  // Runs `stage` from its start, or with `resume` from where a checkpoint left it (no output
  // at its start then). `after_step` is called after each step.
  StageReport run_stage(const Stage& stage, const OutputCallback& on_output,
                        const StepCallback& after_step = {}, const StageProgress* resume = nullptr);

  // Activates the named boundary conditions (a stage's list).
  void activate_boundaries(const std::vector<std::string>& names);
  // Largest stable time step for the given Courant number: min over points of
  // courant * h_cell / (c_p + |v_p|), c_p the P-wave speed of the point's material.
  double stable_time_step(double courant) const;
  // One explicit step of length dt with local damping coefficient `damping`.
  void step(double dt, double damping);
  // Fills nodal mass and the grid velocities below from the points (for grid output); the
  // nodal velocities the next step reads are left as they are.
  void map_to_grid();
  const std::vector<Vec>& grid_velocity() const { return grid_velocity_; }
  const std::vector<Vec>& grid_liquid_velocity() const { return grid_liquid_velocity_; }

  double kinetic_energy() const;
  long step_count() const { return step_count_; }
  // s, the length of the last step taken (0 before the first).
  double last_time_step() const { return last_dt_; }
  const Mesh<dim>& mesh() const { return mesh_; }
  const TransferDamping& transfer_damping() const { return damping_; }
  // s between two pressure projections when they are counted in time (0: by steps or none),
  // and a line for the log saying which.
  double pressure_projection_time() const { return projection_time_; }
  const std::string& pressure_projection_description() const { return projection_description_; }
  // Pressure projections run so far (pressure_projection.cpp).
  long pressure_projection_count() const { return projection_count_; }
  const MaterialPoints<dim>& points() const { return solid_.points; }
  MaterialPoints<dim>& points() { return solid_.points; }
  const CaseDescription& description() const { return description_; }
  const std::vector<double>& node_mass() const { return solid_.nodal.sums().mass; }
  const std::vector<Vec>& node_velocity() const { return solid_.node_velocity; }
  bool has_liquid() const { return has_liquid_; }
  const LiquidPoints<dim>& liquid() const { return water_.points; }
  LiquidPoints<dim>& liquid() { return water_.points; }
  const std::vector<double>& node_liquid_mass() const { return water_.nodal.sums().mass; }
  // The water's velocity at the nodes: the mass-weighted mean of the free and the pore water.
  const std::vector<Vec>& node_liquid_velocity() const { return mean_water_velocity_; }
  const std::vector<double>& node_porosity() const { return node_porosity_; }
  const std::vector<double>& node_pressure() const { return node_pressure_; }
  // The water pressure the forces act with at each liquid point (two_phase.cpp): the points'
  // own with liquid_pressure = "points", the nodal fit with "nodal_fit".
  const std::vector<double>& acting_liquid_pressure() const;
  // With liquid_pressure = "nodal_fit", the nodes' fitted water pressures of the last step
  // (the probes read them); nullptr otherwise, and before the first step.
  const std::vector<double>* fitted_node_pressure() const {
    return nodal_pressure_ && !node_fitted_pressure_.empty() ? &node_fitted_pressure_ : nullptr;
  }
  // Porosity of solid point p: 1 - m / (rho_s V), the Lagrangian form of eq. (5).
  double porosity(std::size_t p) const;
  // Adds a boundary condition built in code (tests of scenes without gmsh groups).
  void add_constraint_for_test(NodalConstraint<dim> constraint, const BoundaryCondition& bc) {
    description_.boundaries.push_back(bc);
    constraints_.push_back(std::move(constraint));
  }
  // Applies the liquid pressure projection now (pressure_projection.cpp); for tests.
  int project_pressure_for_test() { return project_liquid_pressure(); }
  // Applies the pore water volume projection now (pore_volume_projection.cpp); for tests.
  // Needs the nodal porosity of a step (or of liquid_to_nodes) before it.
  int project_pore_volume_for_test() { return project_pore_water_volume(); }
  // Finds the cells of the liquid points again after a test has moved them.
  void relocate_liquid_for_test();
  // What the material pushes on each boundary condition with (wall_loads.cpp), summed as
  // impulses over the steps since the running stage started or since the last
  // take_wall_impulses(); index i is description().boundaries[i]. Tractions and inactive
  // conditions stay zero. The sums are state: a checkpoint holds them.
  struct WallImpulse {
    Vec force = Vec::Zero();       // N s (2D: per metre), the sum of the nodes' forces
    double normal = 0;             // N s, the sum of each node's force along its wall's
                                   // outward normal: positive where the material presses
    Vec tangential = Vec::Zero();  // N s, the sum of each node's force across that normal
    double pore_pressure = 0;      // N s, contact walls with water: the pore pressure's share
                                   // of `normal`; normal - pore_pressure is the effective one
  };
  const std::vector<WallImpulse>& wall_impulses() const { return wall_impulse_; }
  // s: the time those impulses were summed over.
  double wall_impulse_time() const { return wall_impulse_time_; }
  // Moves the sums into `impulses` and starts them afresh; returns the time they cover (the
  // stage history takes them at each of its rows, probe_recorder.cpp).
  double take_wall_impulses(std::vector<WallImpulse>& impulses);
  // Liquid points that landed after a free flight and were merged since this object was
  // built (liquid_landing.cpp); a count for tests and diagnostics, not state.
  long landed_point_count() const { return landed_point_count_; }
  // Total number of points (solid + liquid), for throughput figures.
  std::size_t point_count() const { return solid_.points.size() + water_.points.size(); }
  // Bytes held by points, nodes and mesh (for the memory-per-point report).
  std::size_t storage_bytes() const;

 private:
  // Every member that carries state from one step to the next must be in the checkpoint, or a
  // resumed run drifts from an uninterrupted one (checkpoint_test.cpp compares them bit for bit).
  friend struct detail::CheckpointAccess<dim>;
  using SolidPhase = detail::Phase<dim, MaterialPoints<dim>, detail::PhaseSums<dim>>;
  using LiquidPhase = detail::Phase<dim, LiquidPoints<dim>, detail::LiquidSums<dim>>;
  using Transfer = detail::Transfer;
  // Nodal sums of the solid points that only the coupling needs (two-phase cases only).
  struct CouplingSums {
    std::vector<double> solid_volume;       // sum N V (1 - n) of the solid points
    std::vector<double> soil_volume;        // sum N V of the solid points (grains and pores)
    std::vector<double> drag;               // sum N V C, C the drag coefficient of eq. (23)
    std::vector<Vec> grain_pressure_force;  // sum p V (1 - n) grad N over the grains
    std::vector<Vec> solid_mass_gradient;   // sum m grad N: points into the soil at its surface
    void assign(std::size_t n) {
      solid_volume.assign(n, 0.0);
      soil_volume.assign(n, 0.0);
      drag.assign(n, 0.0);
      grain_pressure_force.assign(n, Vec::Zero());
      solid_mass_gradient.assign(n, Vec::Zero());
    }
  };
  struct MaterialModelData {
    MaterialModel model;
    ElasticConstants elastic;
    std::unique_ptr<MohrCoulomb> mohr_coulomb;
    double wave_speed;  // sqrt((lambda + 2G) / rho_dry); water: sqrt(K_w / rho_w)
    double solid_density = 0, max_porosity = 1, grain_diameter = 0;
    double dry_density = 0;  // (1 - n_0) rho_s: the density at which J = 1 (Kirchhoff stress)
    double liquid_density = 0, bulk_modulus = 0, viscosity = 0;  // water only
  };

  void points_to_nodes(Transfer what);
  void nodal_update(double dt, double damping);
  void remap_momentum();
  void smooth_volumetric_strain(double dt);
  double reference_volume(std::size_t p) const;  // m / rho_d: the Kirchhoff stress's volume
  void update_stress_and_relocate(double dt);
  // Two-phase parts (two_phase.cpp).
  void setup_liquid();
  void update_pore_pressure_cell_scale();
  void liquid_to_nodes();
  void two_phase_nodal_update(double dt, double damping);
  Vec wall_pore_pressure_push(int node, double dt) const;
  // W_i: the wall's reaction to the whole pore-pressure force at wall node i (two_phase.cpp).
  Vec wall_pore_pressure_load(int node) const;
  // Adds the step's boundary forces to wall_impulse_ (wall_loads.cpp); `damping` the step's.
  void accumulate_wall_impulses(double dt, double damping);
  // A node's masses, velocities before the step and explicit forces in the nodal update (the
  // grains; with water also its free and pore fields), as the update computes them and as
  // the boundary forces recompute them at the wall nodes.
  struct NodeStep {
    double ms = 0, mf = 0, mp = 0;
    Vec vs_old, vf_old, vp_old, fs, ff, fp;
  };
  NodeStep dry_node_step(std::size_t i, double damping) const;
  NodeStep two_phase_node_step(std::size_t i, double damping) const;
  // The water's share of the nodal pore-pressure force (eqs. 15, 16; two_phase.cpp).
  double pore_pressure_water_share(std::size_t node) const;
  // Where free and pore water meet: common normal velocity, drag, free tangential slip.
  void couple_across_soil_surface(std::size_t node, double a, double ms, Vec& vs, double mf,
                                  Vec& vf, double mp, Vec& vp) const;
  void remap_liquid_momentum();
  void update_liquid_and_relocate(double dt);
  void advect_liquid_by_flux(double dt);
  // Landed spray takes the velocity of the water it lands in (liquid_landing.cpp).
  void merge_landed_liquid();
  // Pressure-projection stabilisation (pressure_projection.cpp); returns CG iterations.
  int project_liquid_pressure();
  // Pore water volume projection (pore_volume_projection.cpp); returns CG iterations.
  int project_pore_water_volume();
  // sum_q V_q N_i(x_q) point_values_q at each node; the result lives in projection_.sums.
  const std::vector<double>& scatter_liquid(const std::vector<double>& point_values);
  void gather_liquid(const std::vector<double>& nodal, std::vector<double>& point_values) const;
  void report_progress(const Stage& stage, double t, double wall, bool final_line);
  void apply_tractions();

  CaseDescription description_;
  Mesh<dim> mesh_;
  SolidPhase solid_;
  std::vector<NodalConstraint<dim>> constraints_;
  std::vector<const NodalConstraint<dim>*> active_tractions_;
  double stage_time_ = 0;  // time since the start of the running stage (load ramps)
  // The pressure projection's clock: the period (s, 0 = counted in steps or off), the simulated
  // time since the last projection (state: checkpointed), the count, and the log's line.
  double projection_time_ = 0;
  double projection_clock_ = 0;
  long projection_count_ = 0;
  std::string projection_description_;
  bool pressure_projection_due(double dt);
  void resolve_pressure_projection();
  std::vector<MaterialModelData> materials_;
  Vec gravity_;
  int threads_ = 1;
  // Volumetric strain smoothing: the nodal sums and the smoothed value per point.
  bool volumetric_smoothing_;
  detail::NodalScatter<detail::NodalAverageSums> smoothing_;
  std::vector<double> point_volumetric_strain_;
  TransferDamping damping_;  // the FLIP/PIC blend of each phase (copied into the phases)
  bool musl_;
  double max_velocity_;
  // Liquid phase and coupling (empty in a dry case).
  bool has_liquid_ = false;
  LiquidPhase water_;
  detail::NodalScatter<CouplingSums> coupling_;
  // Sums of liquid_pressure = "nodal_fit" (two_phase.cpp): the water volume's moments about
  // each node and the water's force from the fitted pressure. Allocated only in that mode.
  struct PressureFitSums {
    std::vector<Vec> volume_first_moment;                               // sum N V (x - x_i)
    std::vector<Vec> pressure_first_moment;                             // sum N V (x - x_i) p
    std::vector<Eigen::Matrix<double, dim, dim>> volume_second_moment;  // sum N V d d^T
    std::vector<Vec> water_pressure_force;                              // sum V (S p) grad N
    void assign(std::size_t n) {
      volume_first_moment.assign(n, Vec::Zero());
      pressure_first_moment.assign(n, Vec::Zero());
      volume_second_moment.assign(n, Eigen::Matrix<double, dim, dim>::Zero());
      water_pressure_force.assign(n, Vec::Zero());
    }
  };
  detail::NodalScatter<PressureFitSums> pressure_fit_;
  std::vector<double> node_porosity_;
  std::vector<double> node_pressure_;  // volume-weighted nodal liquid pressure
  // Two velocity fields of the water at the nodes (two_phase.cpp): the free water's is
  // water_.node_velocity (and _acceleration); the pore water's, the water of the liquid
  // points whose cell holds solid points, is below. Only the pore water feels the drag.
  std::vector<char> cell_has_soil_;  // per cell: it holds solid points
  // Per cell: |c| / sum of the soil points' volumes in c inside a soil, 1 elsewhere
  // (two_phase.cpp, update_pore_pressure_cell_scale).
  std::vector<double> pore_pressure_cell_scale_;
  // The water points' factor: pore_pressure_cell_scale_ itself with the "soil" measure; with
  // "water", n |c| / sum of the water points' volumes in c inside a soil, 1 elsewhere. With
  // free_water_cell_volume also |c| / sum of the water points' volumes in free water's
  // interior cells (none of whose nodes touches a cell without water).
  std::vector<double> pore_water_cell_scale_;
  std::vector<double> pore_water_cell_volume_;  // scratch: the water points' volume per cell
  // Per cell, with the water's measure or the flux advection: the porosity of the cell's soil
  // points (their pore volume over their volume), 1 in a cell without soil.
  std::vector<double> cell_soil_porosity_;
  const std::vector<double>& water_cell_scale() const {
    return description_.solver.pore_pressure_cell_measure == PorePressureMeasure::kWater ||
                   description_.solver.free_water_cell_volume
               ? pore_water_cell_scale_
               : pore_pressure_cell_scale_;
  }
  std::vector<char> pore_pressure_surface_node_;  // scratch: nodes of cells without soil
  std::vector<char> water_surface_node_;          // scratch: nodes of cells without free water
  std::vector<char> liquid_in_soil_;              // per liquid point: it is pore water
  std::vector<Vec> pore_water_velocity_, pore_water_acceleration_;
  std::vector<Vec> mean_water_velocity_;  // mass-weighted mean of the two (eq. 8's flux)
  // Landing of water in free flight (liquid_landing.cpp): the bodies' finder, the points that
  // landed this step, the water at their nodes and the momentum they hand to each node.
  detail::WaterInFlight<dim> water_in_flight_;
  std::vector<std::size_t> landed_;
  std::vector<Vec> landing_impulse_, body_momentum_;
  std::vector<double> body_mass_;
  std::vector<char> landing_node_;
  long landed_point_count_ = 0;
  double smallest_cell_height_ = 0;  // of the mesh (a length scale for the surface)
  // Per contact-wall node, dt (1 - n) W / m_s: the velocity the wall's reaction to the grains'
  // share of the pore pressure gives them (W: the wall part of the nodal pore-pressure force).
  std::vector<Vec> node_wall_pore_pressure_push_;
  // Boundary forces (wall_loads.cpp): the wall nodes of the running stage, with their
  // conditions and normals, and the sums per boundary condition.
  struct WallEntry {
    int node;
    std::size_t boundary;     // index into constraints_
    Vec normal;               // the wall's outward normal at the node
    Vec dual;                 // the node's force . dual is this wall's normal part
    double tangential_share;  // of the force across all the node's walls
  };
  struct WallNode {
    int node;
    std::size_t first, count;  // its entries in wall_entries_
    bool contact;              // a contact wall in a case with water: pore pressure summed
  };
  void collect_wall_nodes();
  std::vector<WallEntry> wall_entries_;
  std::vector<WallNode> wall_nodes_;
  std::vector<WallImpulse> wall_impulse_;
  double wall_impulse_time_ = 0;
  std::vector<Vec> grid_velocity_, grid_liquid_velocity_;  // map_to_grid (output only)
  std::vector<double> node_mesh_volume_;        // integral of N_i over the mesh (lumped volume)
  std::vector<double> liquid_flux_divergence_;  // per liquid point, div((1-n) v_s + n v_w)
  std::vector<double> smoothed_flux_divergence_;
  bool nodal_pressure_ = false;
  // The quadrangles of a crossed mesh, whose free pressure pattern each step removes
  // (crossed_quadrangles.hpp); empty on a plain mesh, in 3D and with crossed_pressure_filter off.
  CrossedQuadrangles crossed_quadrangles_;
  FreePatternScratch free_pattern_scratch_;
  // The free water's XPIC(m) correction ([solver] liquid_xpic_order > 1; xpic.hpp).
  Xpic<dim> xpic_;
  std::vector<double> node_fit_alpha_;
  std::vector<double> node_fitted_pressure_;  // a_i of the fit, nodal_fit only
  mutable std::vector<double> acting_pressure_;
  std::vector<Vec> node_fit_beta_;
  // Per node, dt-independent sponge rate sigma (1/s) of the description's [[sponge]] zones;
  // empty when the case has none, so the nodal update skips it (two_phase.cpp).
  std::vector<double> node_sponge_rate_;
  struct ProjectionScratch {
    std::vector<double> solution, rhs, diagonal;  // on all nodes (solution: the warm start)
    detail::ConjugateGradientScratch cg;
    std::vector<double> point_values;
    detail::NodalScatter<detail::ScalarSums> sums;
    detail::PointMassMatrix<dim> mass;          // M assembled (pattern once per mesh)
    std::vector<double> row_rhs, row_solution;  // the same on M's rows
  };
  ProjectionScratch projection_;
  // Scratch of the pore water volume projection (nothing in it outlives a call).
  struct PoreVolumeScratch {
    std::vector<char> wet_cell, unknown;
    std::vector<double> rhs, diagonal, potential;
    detail::ConjugateGradientScratch cg;
    detail::MeshMatrix<dim> laplacian;           // L assembled (pattern once per mesh)
    std::vector<double> row_rhs, row_potential;  // rhs and phi on L's rows
    std::vector<double> cell_weight;
    std::vector<Vec> cell_gradient, displacement;
  };
  PoreVolumeScratch pore_volume_;
  int pore_liquid_ = -1;  // the water material that fills the pores (drag, eq. 23)
  long step_count_ = 0;
  double next_time_step_ = 0;  // stable dt from the last stress update (for courant 1)
  std::ostream* progress_ = nullptr;
  double last_progress_wall_ = -1e9;
  long stage_steps_ = 0;
  double last_dt_ = 0;
};

extern template class Simulation<2>;
extern template class Simulation<3>;

}  // namespace lituya::solver
