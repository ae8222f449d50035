#pragma once
// What a case is made of, as read from materials.toml and stages.toml (and, by the
// preprocessor, from the matching tables of scene.toml). The readers validate every value and
// name the file and line of anything wrong; the writers produce the tables the solver reads,
// so a scene and a case folder share one definition of each key.
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "lituya/common/toml_reader.hpp"

namespace lituya::solver {

// Soil skeletons (solid points) are linear elastic or Mohr-Coulomb; water (liquid points) is a
// weakly compressible Newtonian liquid, eqs. (7), (8), (17).
enum class MaterialModel { kLinearElastic, kMohrCoulomb, kWater };

struct Material {
  std::string name;
  MaterialModel model = MaterialModel::kMohrCoulomb;
  double solid_density = 0;     // kg/m3, intrinsic grain density rho_s, eq. (1)
  double porosity = 0;          // initial porosity n0
  double youngs_modulus = 0;    // Pa
  double poisson_ratio = 0;     // -
  double friction_angle = 0;    // deg
  double dilatancy_angle = 0;   // deg
  double cohesion = 0;          // Pa
  double tensile_strength = 0;  // Pa (apex value c cot(phi) when not given)
  double grain_diameter = 0;    // m, D_p in eq. (24); 0 = not given
  // n_max: above it the soil grains separate, the effective stress vanishes and the soil-water
  // mixture flows like a liquid (section 2.3 of the paper). 1 = never.
  double max_porosity = 1.0;

  // Water only (model kWater):
  double liquid_density = 0;  // kg/m3, intrinsic rho_w at zero pressure, eq. (2)
  double bulk_modulus = 0;    // Pa, K_w of eq. (7); a reduced value is a speed knob
  double viscosity = 0;       // Pa s, dynamic viscosity mu of eqs. (17) and (23)

  bool is_liquid() const { return model == MaterialModel::kWater; }
  // Dry bulk density (1 - n0) rho_s: the apparent solid density of eq. (1).
  double dry_density() const { return (1.0 - porosity) * solid_density; }
};

// kTraction is a surface load (a force per unit area on the group's facets), the others
// constrain nodal velocities.
enum class BoundaryType { kFixed, kRoller, kContact, kFixity, kTraction };

// Which phase a boundary condition acts on (two-phase cases): a perforated plate holds the
// soil and lets the water through (kSolid), a membrane the other way round (kLiquid).
enum class BoundaryPhase { kBoth, kSolid, kLiquid };

struct BoundaryCondition {
  std::string name;
  std::string group;
  BoundaryType type = BoundaryType::kFixed;
  double friction = 0;  // contact only
  // contact only: the soil material whose rough_wall_friction (mohr_coulomb.hpp) sets
  // `friction`; resolved by the scene reader, which knows the materials. Empty: `friction`
  // as given.
  std::string rough;
  std::vector<int> directions;   // fixity only: 0 = x, 1 = y, 2 = z
  std::vector<double> traction;  // traction only: Pa, `dimension` components
  double ramp_time = 0;          // traction only: s, linear rise from 0 at the stage start
  BoundaryPhase phase = BoundaryPhase::kBoth;  // traction: kSolid (default) or kLiquid
};

enum class StageType { kQuasiStatic, kDynamic };

struct Stage {
  std::string name;
  StageType type = StageType::kDynamic;
  double duration = 0;
  double courant = 0.5;
  double damping = 0;
  double output_interval = 0;
  std::vector<std::string> boundaries;
  double kinetic_energy_ratio = 0;  // quasi-static stop criterion; 0 = run the full duration
  bool reset_displacement = true;
};

enum class TransferScheme { kMUSL, kUSL };

// Which pressure the water's nodal force sees (scientific manual 10.4).
// - kPoints: each liquid point's own pressure (eq. 8 per point), with the periodic L2
//   pressure projection against the P1/P0 checkerboard. The default.
// - kNodalFit: the pressure fitted at each node, every step, by a volume-weighted linear
//   least-squares fit of the point pressures around it (exact for linear fields, so a
//   hydrostatic state is untouched, at free surfaces too); eq. (8) takes the adjoint
//   smoothing of the flux divergence, so the pair is energy-consistent and the checkerboard
//   exerts no force and is not driven. No periodic projection. Experimental (December 2026).
enum class LiquidPressure { kPoints, kNodalFit };

// Over which volume a soil cell's water points spread the pore pressure they act with
// (two_phase.cpp, update_pore_pressure_cell_scale; scientific manual 10.4). Inside a soil each
// point's pressure force, and eq. (8)'s volume change, are weighed so that an even pressure
// pushes with the cell's own volume, whatever the points' spread. The grains always take the
// cell's volume over their points' volume sum. The water:
// - kSoil: the same factor as the grains, |c| / (the soil points' volume sum). Right while the
//   water points sit where the soil points do; water that crowds the soil's pores pushes out.
//   The default.
// - kWater: the cell's pores, n |c| (n the soil points' porosity in the cell), over the water
//   points' own volume sum. An even pressure then pushes the cell's water with exactly its
//   pores' volume wherever the water points are (December 2026, stop 31: the pore water
//   volume projection moves them off the grains, and with kSoil a fine-sand block then lost
//   its pore pressure as it travelled).
enum class PorePressureMeasure { kSoil, kWater };

// How the liquid points move (Simulation::advect_liquid_by_flux; scientific manual 10.4):
// - kVelocity: each with its own water field's nodal velocity, interpolated. The default.
// - kFlux: each with the grains' velocity plus the water's volume flux relative to them,
//   n (v_w - v_s) interpolated from the nodes, over the pores of its cell's soil (1 for free
//   water): Darcy's seepage velocity. The two differ only where the nodal porosity varies
//   across a cell, at a soil's surface: there the grid's porosity ramps over a cell while the
//   soil's pores do not, and water entering a sand with the field's velocity crowded its top
//   centimetre (1.24 of its pores in the seepage column) and left the one below under-filled
//   (December 2026, stop 32).
enum class LiquidAdvection { kVelocity, kFlux };
enum class LiquidLanding { kMerge, kKeepVelocity };

struct SolverSettings {
  TransferScheme scheme = TransferScheme::kMUSL;
  // FLIP/PIC blend. By default the PIC share is set per unit time, not per step, so that
  // results do not depend on the Courant number (user manual, section 3): each step keeps
  // the FLIP share exp(-dt / tau) of the point's own velocity update. The damping times tau
  // default to multiples of the grid's gravity time sqrt(h / g) (h: the mesh's cell size),
  // see resolve_transfer_damping(). Give at most one of the two forms:
  //  - flip_fraction: the old fixed share per step, for both phases (0.99 = 1 % PIC a step);
  //  - pic_damping_time (solid) and liquid_pic_damping_time (water), in seconds.
  std::optional<double> flip_fraction;
  std::optional<double> pic_damping_time;
  std::optional<double> liquid_pic_damping_time;
  // The water's damped share by XPIC(m) (xpic.hpp; scientific manual 4.1): m = 1 is the plain
  // PIC blend, m >= 2 damps what the grid resolves as (1 - lambda)^m instead of 1 - lambda.
  // Experimental (stop 56): measured on the standing wave and on Case B at 0.02 / 0.015 m.
  int liquid_xpic_order = 1;
  double max_velocity = 100.0;
  // Average the volumetric strain increment over the cells around each node before the
  // stress update (nodal mixed discretisation): removes the volumetric locking of linear
  // triangles and tetrahedra under isochoric plastic flow (psi = 0). Off by default: with
  // FLIP transfer it feeds velocity noise (a sliding block then gains speed it should not,
  // see verification/sliding_block), so it is an experimental option for now.
  bool volumetric_smoothing = false;
  // How often the liquid point pressures are replaced by their L2 projection onto continuous
  // linear fields (pressure_projection.cpp): removes the cell-to-cell pressure noise of linear
  // cells, keeps linear (hydrostatic) fields exactly. Every pressure_projection_interval steps
  // when given (0 = never); otherwise every pressure_projection_time seconds of simulated time,
  // by default 10 still-water steps at Courant 0.5 (Simulation::resolve_pressure_projection).
  // By time, because each projection damps the water a little: counted in steps, halving the
  // Courant number doubled the projections and so their damping (user manual 2.6).
  std::optional<int> pressure_projection_interval;
  std::optional<double> pressure_projection_time;
  // At the same steps, liquid points that over-fill the pores of a soil are moved out until
  // each soil node holds no more water than its pore volume (pore_volume_projection.cpp;
  // scientific manual 10.4). A pore can be partly empty (unsaturated), never over-full.
  bool pore_volume_projection = true;
  LiquidPressure liquid_pressure = LiquidPressure::kPoints;
  PorePressureMeasure pore_pressure_cell_measure = PorePressureMeasure::kSoil;
  // In free water too, each interior cell's pressure acts over the cell's own volume, not over
  // its points' volume sum (two_phase.cpp, update_pore_pressure_cell_scale; scientific manual
  // 10.4): the periodic pressure projection then no longer lets the water's points settle
  // (verification/standing_wave). On by default since December 2026 (stop 35); false gives
  // back the points' own volumes, under which water in motion settles.
  bool free_water_cell_volume = true;
  // On a crossed mesh ([mesh] crossed = true), each step removes from every quadrangle the one
  // pattern of the water's pressure over its four triangles that exerts no nodal force
  // (crossed_quadrangles.hpp; scientific manual, section 3). Carried in by points that cross
  // cells, it grew unchecked and fed the bursts of Case B's deposit. No effect on a plain mesh.
  bool crossed_pressure_filter = true;
  LiquidAdvection liquid_advection = LiquidAdvection::kVelocity;
  // Water in free flight (spray, a sheet off a crest; water_in_flight.hpp) that lands on a
  // body of water: kMerge gives each landing point the velocity of the water it lands in and
  // hands its excess momentum to the nodes there (liquid_landing.cpp; scientific manual
  // 10.4), an inelastic impact. kKeepVelocity is FLIP's own behaviour: the point keeps its
  // velocity relative to the water and is deflected by the pressure, elastically (before
  // December 2026, stop 51).
  LiquidLanding liquid_landing = LiquidLanding::kMerge;
  // Artificial bulk viscosity of the water (scientific manual 10.5; not in the paper): a
  // viscous pressure -zeta div(v) with zeta = liquid_bulk_viscosity * rho_w c_w h. It acts only
  // on compression, so it damps the sound waves of the weakly compressible water (an artefact
  // of a finite K_w; incompressible water has none) and leaves free-surface waves alone.
  // 0 = off.
  double liquid_bulk_viscosity = 0.1;
  // Wall time between two checkpoints within a stage (checkpoint.hpp), in minutes; a
  // checkpoint is also written at the end of every stage and when the run is asked to stop.
  // Half an hour loses little of a long run and costs little disk time. 0 = only those.
  double checkpoint_interval_minutes = 30.0;
};

// The fields each output file can hold, in the order they are written (output/README.txt
// describes them). The point `id` and the positions and cells are always written.
inline const std::vector<std::string> kSolidPointFields = {"displacement",   "velocity", "stress",
                                                           "plastic_strain", "material", "mass",
                                                           "volume",         "porosity"};
inline const std::vector<std::string> kLiquidPointFields = {
    "velocity", "pressure", "porosity", "mass", "volume", "material", "in_flight"};
inline const std::vector<std::string> kGridFields = {
    "mass", "velocity", "liquid_mass", "liquid_velocity", "porosity", "liquid_pressure"};

// The scene's [output] table: which fields of the solid points (`point_fields`), the liquid
// points and the grid are written, whether the grid is written, and whether the VTU arrays
// are zlib-compressed (`compression = "zlib" | "none"`).
struct OutputSettings {
  std::vector<std::string> point_fields = kSolidPointFields;
  std::vector<std::string> liquid_fields = kLiquidPointFields;
  std::vector<std::string> grid_fields = kGridFields;
  bool grid = true;
  bool compress = true;
  bool writes(const std::vector<std::string>& fields, const std::string& field) const;
};

// A probe: a sensor that records fields over time (output/probes/<name>.csv), either at a
// fixed position (interpolated from nodal values of the points around it) or riding on one
// material point (its own values, and the nodal interpolation at its position for the fields
// the point does not carry), like Anura3D's OUTPUT_MATERIAL_POINTS.
inline const std::vector<std::string> kProbeFields = {"pore_pressure", "effective_stress",
                                                      "velocity", "liquid_velocity", "porosity"};

struct Probe {
  std::string name;
  std::vector<double> position;  // m, `dimension` components; empty for a point probe
  enum class Follows { kPosition, kSolidPoint, kLiquidPoint };
  Follows follows = Follows::kPosition;
  long long point_id = -1;  // id (index in points.vtu / liquid_points.vtu) of a point probe
  std::vector<std::string> fields = kProbeFields;
  // s between two samples; 0 = at each output of the stage only. A finer interval samples at
  // the first step on or after each multiple of it (and at each output too).
  double interval = 0;
  bool records(const std::string& field) const;
};

// A sponge (absorbing) zone at a tank end: in it the water's nodal velocity relaxes towards
// rest, v <- v / (1 + dt sigma(x)) each step (implicit, so stable at any step), with a rate
// that rises quadratically from 0 where the waves enter (x_start) to damping_rate at the far
// end (x_end) and stays there beyond it. The zone runs along x and may face either way
// (x_end < x_start: a sponge at the -x end); it spans the whole height (and depth in 3D).
// The slow start keeps the reflection from the zone's own edge small, the rate's end value
// and the zone's length set how much of a wave survives its way in and out (user manual,
// water section). The soil is not damped: a slide that runs into the zone keeps its motion.
struct Sponge {
  double x_start = 0;       // m, where waves enter the zone: sigma = 0
  double x_end = 0;         // m, the far end: sigma = damping_rate here and beyond
  double damping_rate = 0;  // 1/s, sigma at x_end; 0 in a scene = the default (lituya pre)
  // sigma(x) in 1/s.
  double rate_at(double x) const;
};

// Default damping_rate, in units of sqrt(g / h) (h: the still water depth in the zone): a
// wave some 6 h long has an angular frequency of about sqrt(g / h), and a rate of that order
// damps it within a zone of a wavelength or two without turning the zone into a wall. In
// verification/sponge (a zone of 1.5 wavelengths) it sends back 5.4 % of the wave's height;
// twice this 11 %, half of it 16 %.
inline constexpr double kDefaultSpongeStrength = 1.0;

struct Group {
  std::string name;
  int dimension = 0;
};

// Readers: validate one table (a [[material]], [[boundary]], [[stage]], [solver], [output]).
// `dimension` is needed to check direction names and vector lengths.
Material read_material(const TomlTable& t);
BoundaryCondition read_boundary(const TomlTable& t, int dimension);
Stage read_stage(const TomlTable& t);
SolverSettings read_solver_settings(const TomlTable& t);
OutputSettings read_output_settings(const TomlTable& t);
// A [[probe]] table; `has_water` false refuses the water fields (the case has no liquid).
Probe read_probe(const TomlTable& t, int dimension, bool has_water);
// A [[sponge]] table. With `rate_required` (a case's stages.toml) damping_rate must be given;
// a scene may leave it out for the default (kDefaultSpongeStrength).
Sponge read_sponge(const TomlTable& t, bool rate_required);

// Writers: the same keys, for materials.toml / stages.toml.
toml::table to_toml(const Material& m);
toml::table to_toml(const BoundaryCondition& b);
toml::table to_toml(const Stage& s);
toml::table to_toml(const SolverSettings& s);
toml::table to_toml(const OutputSettings& o);
toml::table to_toml(const Probe& p);
toml::table to_toml(const Sponge& s);

// The whole case folder as the solver sees it (everything but the mesh and points).
struct CaseDescription {
  std::string folder;  // the case folder
  int dimension = 2;
  std::vector<double> gravity;  // `dimension` components
  std::string geometry_file, points_file, materials_file;
  std::string liquid_points_file;  // empty: a dry case (no liquid phase is allocated)
  std::vector<Group> groups;
  std::vector<Material> materials;
  std::vector<BoundaryCondition> boundaries;
  std::vector<Stage> stages;
  SolverSettings solver;
  OutputSettings output;
  std::vector<Probe> probes;
  std::vector<Sponge> sponges;  // absorbing zones for the water; empty: none
};

// Reads case/stages.toml and case/materials.toml; checks cross references (stage boundaries
// exist, boundary groups exist and have dimension - 1, ...).
CaseDescription read_case(const std::string& case_folder);

// Cross checks shared by the scene reader and read_case: stage boundary names exist, names are
// unique. `where` is used in messages.
void check_stage_boundaries(const std::vector<Stage>& stages,
                            const std::vector<BoundaryCondition>& boundaries,
                            const std::vector<TomlTable>& stage_tables);

// Probe names become file names (output/probes/<name>.csv): refuses a second probe of the same
// name at its `name` line.
void check_probe_names(const std::vector<Probe>& probes,
                       const std::vector<TomlTable>& probe_tables);

}  // namespace lituya::solver
