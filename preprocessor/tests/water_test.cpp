// Scenes with water: free water (liquid points only) and saturated soil (solid and liquid
// points at the same positions), their masses, the hydrostatic water pressure and the
// effective K0 stress, as written to points.vtu / liquid_points.vtu / stages.toml.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkUnstructuredGrid.h>

#include "lituya/pre/preprocess.hpp"
#include "lituya/solver/case_description.hpp"
#include "test_support.hpp"
#include "vtk_support.hpp"

namespace lituya::pre {
namespace {

namespace fs = std::filesystem;
using testing::barycentric;
using testing::point_array;
using testing::read_vtu;
using testing::sum_of;
using testing::TempFolder;

constexpr double kGravity = 9.81;
constexpr double kWaterDensity = 1000.0;  // rho_w, kg/m3
constexpr double kGrainDensity = 2650.0;  // rho_s, kg/m3
constexpr double kPorosity = 0.4;         // n0

constexpr double kWaterBulkModulus = 2.0e6;  // Pa, as in kWaterMaterial
const std::string kWaterMaterial = R"(
[[material]]
name = "water"
model = "water"
density = 1000.0
bulk_modulus = 2.0e6
viscosity = 1.0e-3
)";

const std::string kSandMaterial = R"(
[[material]]
name = "sand"
model = "mohr-coulomb"
solid_density = 2650.0
porosity = 0.4
youngs_modulus = 2.0e7
poisson_ratio = 0.3
friction_angle = 30.0
grain_diameter = 0.001
)";

// A scene with the given geometry, materials and regions, gravity along -y and one
// quasi-static stage.
std::string scene_text(const std::string& geometry, int dimension, double cell_size,
                       const std::string& materials_and_regions,
                       const std::string& boundary_group) {
  return "format = \"lituya-scene\"\nversion = 1\ngravity = [0.0, -9.81" +
         std::string(dimension == 3 ? ", 0.0" : "") + "]\n\n[mesh]\ngeometry = \"" + geometry +
         "\"\ndimension = " + std::to_string(dimension) +
         "\ncell_size = " + std::to_string(cell_size) + "\npoints_per_cell = 4\n" +
         materials_and_regions + "\n[[boundary]]\ngroup = \"" + boundary_group +
         "\"\ntype = \"fixed\"\n\n[[stage]]\nname = \"settle\"\ntype = \"quasi-static\"\n"
         "duration = 0.1\nboundaries = [\"" +
         boundary_group + "\"]\n";
}

// Writes the scene next to a copy of its geometry and runs the preprocessor into case/.
PreprocessSummary run(const TempFolder& folder, const std::string& geometry,
                      const std::string& scene) {
  fs::copy_file(testing::test_data(geometry), folder / geometry);
  testing::write_text(folder / "scene.toml", scene);
  return preprocess(folder / "scene.toml", folder / "case", false);
}

// The arrays of liquid_points.vtu, checked for presence, type and size.
struct LiquidArrays {
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  vtkDataArray *material, *volume, *mass, *pressure, *velocity, *cell;
};

LiquidArrays read_liquid_points(const fs::path& file, std::size_t expected_points) {
  LiquidArrays a;
  a.grid = read_vtu(file);
  EXPECT_EQ(static_cast<std::size_t>(a.grid->GetNumberOfPoints()), expected_points);
  EXPECT_EQ(a.grid->GetNumberOfCells(), a.grid->GetNumberOfPoints());  // one vertex each
  a.material = point_array(a.grid, "material", 1);
  a.volume = point_array(a.grid, "volume", 1);
  a.mass = point_array(a.grid, "mass", 1);
  a.pressure = point_array(a.grid, "pressure", 1);
  a.velocity = point_array(a.grid, "velocity", 3);
  a.cell = point_array(a.grid, "cell", 1);
  EXPECT_EQ(a.grid->GetPointData()->GetArray("stress"), nullptr);
  if (a.material && a.cell && a.volume && a.pressure) {
    EXPECT_EQ(a.material->GetDataType(), VTK_INT);
    EXPECT_EQ(a.cell->GetDataType(), VTK_INT);
    EXPECT_EQ(a.volume->GetDataType(), VTK_DOUBLE);
    EXPECT_EQ(a.pressure->GetDataType(), VTK_DOUBLE);
  }
  return a;
}

// Every liquid point lies in its cell, at rest, with mass = rho_w (1 + p / K_w) volume: water
// compressed to its pressure.
void check_points_in_cells_at_rest(const LiquidArrays& a, const fs::path& geometry_file,
                                   int dimension) {
  auto geometry = read_vtu(geometry_file);
  for (vtkIdType p = 0; p < a.grid->GetNumberOfPoints(); ++p) {
    const auto cell = static_cast<vtkIdType>(a.cell->GetComponent(p, 0));
    ASSERT_GE(cell, 0);
    ASSERT_LT(cell, geometry->GetNumberOfCells());
    for (double b : barycentric(geometry, cell, a.grid->GetPoint(p), dimension))
      EXPECT_GT(b, -1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a.velocity->GetComponent(p, k), 0.0);
    EXPECT_NEAR(a.mass->GetComponent(p, 0),
                kWaterDensity * (1.0 + a.pressure->GetComponent(p, 0) / kWaterBulkModulus) *
                    a.volume->GetComponent(p, 0),
                1e-12 * a.mass->GetComponent(p, 0));
  }
}

const std::string kTankRegions = kWaterMaterial + R"(
[[region]]
group = "water"
material = "water"
)";

// (a) A 2D tank of water 1 m wide and 0.5 m deep, air above: liquid points only.
TEST(Water, HydrostaticTank2D) {
  TempFolder folder;
  const PreprocessSummary summary =
      run(folder, "tank.geo", scene_text("tank.geo", 2, 0.05, kTankRegions, "bottom"));
  const fs::path case_folder = folder / "case";
  EXPECT_EQ(summary.points, 0u);
  ASSERT_GT(summary.liquid_points, 0u);
  EXPECT_EQ(summary.liquid_points % 4, 0u);

  // The solver's reader finds the liquid points through stages.toml.
  const solver::CaseDescription c = solver::read_case(case_folder.string());
  EXPECT_EQ(fs::path(c.liquid_points_file), case_folder / "liquid_points.vtu");
  ASSERT_EQ(c.materials.size(), 1u);
  EXPECT_TRUE(c.materials[0].is_liquid());

  // points.vtu exists, with no points but all its arrays, and VTK reads it.
  auto solid = read_vtu(case_folder / "points.vtu");
  EXPECT_EQ(solid->GetNumberOfPoints(), 0);
  EXPECT_EQ(solid->GetNumberOfCells(), 0);
  for (const char* name : {"material", "volume", "mass", "stress", "velocity", "cell"})
    EXPECT_NE(solid->GetPointData()->GetArray(name), nullptr) << name;

  const LiquidArrays a =
      read_liquid_points(case_folder / "liquid_points.vtu", summary.liquid_points);
  ASSERT_TRUE(a.material && a.volume && a.mass && a.pressure && a.velocity && a.cell);
  // Free water: porosity 1, so the points' water volumes tile the tank. Each weighs what
  // water compressed to its pressure weighs, rho_w (1 + p / K_w) V, so that the solver's
  // volume m / (rho_w (1 + p / K_w)) is the seeded one; over the tank the mean pressure is
  // rho_w g 0.25 m exactly (points symmetric about mid-depth in every column).
  const double area = 1.0 * 0.5;
  EXPECT_NEAR(sum_of(a.volume), area, 1e-12 * area);
  const double mean_compression = 1.0 + kWaterDensity * kGravity * 0.25 / kWaterBulkModulus;
  EXPECT_NEAR(sum_of(a.mass), kWaterDensity * area * mean_compression,
              1e-12 * kWaterDensity * area);
  for (vtkIdType p = 0; p < a.grid->GetNumberOfPoints(); ++p)
    EXPECT_NEAR(a.mass->GetComponent(p, 0),
                kWaterDensity * (1.0 + a.pressure->GetComponent(p, 0) / kWaterBulkModulus) *
                    a.volume->GetComponent(p, 0),
                1e-12 * kWaterDensity * a.volume->GetComponent(p, 0));
  // The pressure integral is exact for a horizontal free surface: p = rho_w g (0.5 - y) up to
  // roundoff.
  const double bottom_pressure = kWaterDensity * kGravity * 0.5;
  for (vtkIdType p = 0; p < a.grid->GetNumberOfPoints(); ++p) {
    EXPECT_EQ(a.material->GetComponent(p, 0), 0.0);
    const double y = a.grid->GetPoint(p)[1];
    EXPECT_NEAR(a.pressure->GetComponent(p, 0), kWaterDensity * kGravity * (0.5 - y),
                1e-9 * bottom_pressure)
        << "y = " << y;
  }
  check_points_in_cells_at_rest(a, case_folder / "geometry.vtu", 2);
}

TEST(Water, TankAtZeroPressure) {
  TempFolder folder;
  const PreprocessSummary summary =
      run(folder, "tank.geo",
          scene_text("tank.geo", 2, 0.1, kTankRegions + "initial_stress = \"zero\"\n", "bottom"));
  const LiquidArrays a =
      read_liquid_points(folder / "case" / "liquid_points.vtu", summary.liquid_points);
  ASSERT_TRUE(a.pressure);
  for (vtkIdType p = 0; p < a.grid->GetNumberOfPoints(); ++p)
    EXPECT_EQ(a.pressure->GetComponent(p, 0), 0.0);
}

TEST(Water, HydrostaticCube3D) {
  // The unit cube of tetrahedra full of water: p = rho_w g (1 - y), mass rho_w (1 + p / K_w)
  // summed over 1 m3: rho_w (1 + rho_w g 0.5 m / K_w) when the points' mean depth is 0.5 m.
  TempFolder folder;
  const std::string regions = kWaterMaterial +
                              "\n[[region]]\ngroup = \"block\"\nmaterial = "
                              "\"water\"\ninitial_stress = \"hydrostatic\"\n";
  const PreprocessSummary summary =
      run(folder, "cube.geo", scene_text("cube.geo", 3, 0.25, regions, "base"));
  const LiquidArrays a =
      read_liquid_points(folder / "case" / "liquid_points.vtu", summary.liquid_points);
  ASSERT_TRUE(a.mass && a.pressure);
  double weighted_depth = 0;  // sum of V (1 - y)
  for (vtkIdType p = 0; p < a.grid->GetNumberOfPoints(); ++p)
    weighted_depth += a.volume->GetComponent(p, 0) * (1.0 - a.grid->GetPoint(p)[1]);
  EXPECT_NEAR(weighted_depth, 0.5, 1e-12);  // the cube's centroid depth, exact for tetrahedra
  EXPECT_NEAR(sum_of(a.mass),
              kWaterDensity * (1.0 + kWaterDensity * kGravity * 0.5 / kWaterBulkModulus),
              1e-9 * kWaterDensity);
  for (vtkIdType p = 0; p < a.grid->GetNumberOfPoints(); ++p)
    EXPECT_NEAR(a.pressure->GetComponent(p, 0),
                kWaterDensity * kGravity * (1.0 - a.grid->GetPoint(p)[1]),
                1e-9 * kWaterDensity * kGravity);
  check_points_in_cells_at_rest(a, folder / "case" / "geometry.vtu", 3);
}

// (b) A saturated sand layer 0.3 m thick under 0.2 m of free water.
std::string seabed_regions(const std::string& initial_stress) {
  return kSandMaterial + kWaterMaterial + R"(
[[region]]
group = "soil"
material = "sand"
water = "water"
initial_stress = ")" +
         initial_stress + "\"\n" + (initial_stress == "k0" ? "k0 = 0.5\n" : "") + R"(
[[region]]
group = "water"
material = "water"
initial_stress = ")" +
         (initial_stress == "k0" ? "hydrostatic" : "zero") + "\"\n";
}

TEST(Water, SaturatedLayerUnderFreeWater) {
  TempFolder folder;
  const PreprocessSummary summary =
      run(folder, "seabed.geo", scene_text("seabed.geo", 2, 0.05, seabed_regions("k0"), "bottom"));
  const fs::path case_folder = folder / "case";
  const std::size_t solid_count = summary.points;
  ASSERT_GT(solid_count, 0u);
  ASSERT_GT(summary.liquid_points, solid_count);  // the pore water, then the free water

  auto solid = read_vtu(case_folder / "points.vtu");
  ASSERT_EQ(static_cast<std::size_t>(solid->GetNumberOfPoints()), solid_count);
  vtkDataArray* solid_material = point_array(solid, "material", 1);
  vtkDataArray* solid_volume = point_array(solid, "volume", 1);
  vtkDataArray* solid_mass = point_array(solid, "mass", 1);
  vtkDataArray* stress = point_array(solid, "stress", 6);
  vtkDataArray* solid_cell = point_array(solid, "cell", 1);
  ASSERT_TRUE(solid_material && solid_volume && solid_mass && stress && solid_cell);
  const LiquidArrays a =
      read_liquid_points(case_folder / "liquid_points.vtu", summary.liquid_points);
  ASSERT_TRUE(a.material && a.volume && a.mass && a.pressure && a.velocity && a.cell);

  // Masses: the skeleton (1 - n0) rho_s, the pore water n0 rho_w (eqs. (1), (2)) over the
  // layer; free water rho_w over the 0.2 m above it.
  const double layer = 1.0 * 0.3, free_water = 1.0 * 0.2;
  const double skeleton_mass = (1 - kPorosity) * kGrainDensity * layer;
  // The water is compressed to its pressure, p = rho_w g (0.5 - y) (below): the free water's
  // mean depth is 0.1 m, the pore water's 0.35 m.
  auto compressed = [](double depth) {
    return 1.0 + kWaterDensity * kGravity * depth / kWaterBulkModulus;
  };
  const double water_mass =
      kWaterDensity * (kPorosity * layer * compressed(0.35) + free_water * compressed(0.1));
  EXPECT_NEAR(sum_of(solid_mass), skeleton_mass, 1e-12 * skeleton_mass);
  EXPECT_NEAR(sum_of(a.mass), water_mass, 1e-9 * water_mass);

  // The soil region comes first in both sets: liquid point p < solid_count is the pore water
  // of solid point p, at the same position in the same cell, with n0 of its volume.
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(solid_count); ++p) {
    EXPECT_EQ(solid_material->GetComponent(p, 0), 0.0);  // sand
    EXPECT_EQ(a.material->GetComponent(p, 0), 1.0);      // water
    for (int k = 0; k < 3; ++k) ASSERT_EQ(a.grid->GetPoint(p)[k], solid->GetPoint(p)[k]);
    EXPECT_EQ(a.cell->GetComponent(p, 0), solid_cell->GetComponent(p, 0));
    const double mixture_volume = solid_volume->GetComponent(p, 0);
    EXPECT_NEAR(a.volume->GetComponent(p, 0), kPorosity * mixture_volume,
                1e-12 * kPorosity * mixture_volume);
    EXPECT_NEAR(
        a.mass->GetComponent(p, 0),
        kPorosity * kWaterDensity * mixture_volume * compressed(0.5 - a.grid->GetPoint(p)[1]),
        1e-9 * kPorosity * kWaterDensity * mixture_volume);
  }

  // Pore and free water: hydrostatic from the free surface at y = 0.5.
  const double bottom_pressure = kWaterDensity * kGravity * 0.5;
  for (vtkIdType p = 0; p < a.grid->GetNumberOfPoints(); ++p) {
    const double y = a.grid->GetPoint(p)[1];
    EXPECT_NEAR(a.pressure->GetComponent(p, 0), kWaterDensity * kGravity * (0.5 - y),
                1e-9 * bottom_pressure)
        << "y = " << y;
  }

  // Effective stress: the total overburden rho_w g 0.2 + ((1 - n0) rho_s + n0 rho_w) g d less
  // the pore pressure rho_w g (0.2 + d) leaves the buoyant weight (1 - n0)(rho_s - rho_w) g d
  // at depth d into the soil. Both integrals are exact up to roundoff of their own size (a few
  // kPa), and the difference keeps that absolute roundoff, so the tolerance is relative to
  // the total overburden at the bottom, not to the (smaller) effective stress.
  const double total_at_bottom =
      kGravity *
      (kWaterDensity * 0.2 + ((1 - kPorosity) * kGrainDensity + kPorosity * kWaterDensity) * 0.3);
  for (vtkIdType p = 0; p < solid->GetNumberOfPoints(); ++p) {
    const double depth = 0.3 - solid->GetPoint(p)[1];
    const double expected = -(1 - kPorosity) * (kGrainDensity - kWaterDensity) * kGravity * depth;
    const double syy = stress->GetComponent(p, 1);
    EXPECT_NEAR(syy, expected, 1e-9 * total_at_bottom) << "depth = " << depth;
    EXPECT_NEAR(stress->GetComponent(p, 0), 0.5 * syy, 1e-12 * total_at_bottom);
    EXPECT_NEAR(stress->GetComponent(p, 2), 0.5 * syy, 1e-12 * total_at_bottom);
    for (int k = 3; k < 6; ++k) EXPECT_EQ(stress->GetComponent(p, k), 0.0);
  }
  check_points_in_cells_at_rest(a, case_folder / "geometry.vtu", 2);
}

TEST(Water, SaturatedLayerAtZeroStress) {
  // "zero": a stress-free skeleton and water at zero pressure; the quasi-static stage settles
  // both.
  TempFolder folder;
  const PreprocessSummary summary =
      run(folder, "seabed.geo", scene_text("seabed.geo", 2, 0.1, seabed_regions("zero"), "bottom"));
  auto solid = read_vtu(folder / "case" / "points.vtu");
  vtkDataArray* stress = point_array(solid, "stress", 6);
  ASSERT_TRUE(stress);
  for (vtkIdType p = 0; p < solid->GetNumberOfPoints(); ++p)
    for (int k = 0; k < 6; ++k) EXPECT_EQ(stress->GetComponent(p, k), 0.0);
  const LiquidArrays a =
      read_liquid_points(folder / "case" / "liquid_points.vtu", summary.liquid_points);
  ASSERT_TRUE(a.pressure);
  for (vtkIdType p = 0; p < a.grid->GetNumberOfPoints(); ++p)
    EXPECT_EQ(a.pressure->GetComponent(p, 0), 0.0);
}

}  // namespace
}  // namespace lituya::pre
