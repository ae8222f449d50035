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
  double friction = 0;           // contact only
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
  double max_velocity = 100.0;
  // Average the volumetric strain increment over the cells around each node before the
  // stress update (nodal mixed discretisation): removes the volumetric locking of linear
  // triangles and tetrahedra under isochoric plastic flow (psi = 0). Off by default: with
  // FLIP transfer it feeds velocity noise (a sliding block then gains speed it should not,
  // see verification/sliding_block), so it is an experimental option for now.
  bool volumetric_smoothing = false;
  // Every this many steps, the liquid point pressures are replaced by their L2 projection onto
  // continuous linear fields (pressure_projection.cpp): removes the cell-to-cell pressure
  // noise of linear cells, keeps linear (hydrostatic) fields exactly. 0 = never.
  int pressure_projection_interval = 10;
};

struct OutputSettings {
  std::vector<std::string> point_fields = {"displacement", "velocity", "stress", "plastic_strain",
                                           "material",     "mass",     "volume", "porosity"};
  bool grid = true;
};

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

// Writers: the same keys, for materials.toml / stages.toml.
toml::table to_toml(const Material& m);
toml::table to_toml(const BoundaryCondition& b);
toml::table to_toml(const Stage& s);
toml::table to_toml(const SolverSettings& s);
toml::table to_toml(const OutputSettings& o);

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
};

// Reads case/stages.toml and case/materials.toml; checks cross references (stage boundaries
// exist, boundary groups exist and have dimension - 1, ...).
CaseDescription read_case(const std::string& case_folder);

// Cross checks shared by the scene reader and read_case: stage boundary names exist, names are
// unique. `where` is used in messages.
void check_stage_boundaries(const std::vector<Stage>& stages,
                            const std::vector<BoundaryCondition>& boundaries,
                            const std::vector<TomlTable>& stage_tables);

}  // namespace lituya::solver
