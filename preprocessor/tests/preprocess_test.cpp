// The whole preprocessor on the shipped examples, read back with VTK and with the solver's
// own case reader.
#include "lituya/pre/preprocess.hpp"

#include <cmath>
#include <map>

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

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

constexpr double kPi = 3.14159265358979323846;
const double kSlope = 22.0 * kPi / 180.0;
// Case A: the column 0.2 m x 0.14 m, the layer 2 m x 0.0046 m (areas in m2).
constexpr double kColumnArea = 0.2 * 0.14, kLayerArea = 2.0 * 0.0046;
constexpr double kColumnDensity = 0.7 * 1500.0, kLayerDensity = 0.7 * 1800.0;  // dry, kg/m3

fs::path example(const std::string& name) {
  return testing::source_dir() / "examples" / name;
}

struct CaseCheck {
  int dimension;
  double thickness;  // out-of-plane size: 1 m per metre in 2D, 0.01 m in 3D
};

// Checks shared by the 2D and 3D Case A runs.
void check_case_a(const fs::path& folder, const PreprocessSummary& summary,
                  const CaseCheck& check) {
  const int dim = check.dimension;
  EXPECT_EQ(summary.dimension, dim);

  // The solver's own reader accepts stages.toml and materials.toml.
  const solver::CaseDescription c = solver::read_case(folder.string());
  EXPECT_EQ(c.dimension, dim);
  // A dry case: no liquid points, no liquid_points.vtu and no `liquid_points` key.
  EXPECT_EQ(summary.liquid_points, 0u);
  EXPECT_FALSE(fs::exists(folder / "liquid_points.vtu"));
  EXPECT_EQ(testing::read_bytes(folder / "stages.toml").find("liquid_points"), std::string::npos);
  EXPECT_TRUE(c.liquid_points_file.empty());
  EXPECT_EQ(c.gravity[1], -9.81);
  ASSERT_EQ(c.materials.size(), 2u);
  EXPECT_EQ(c.materials[0].name, "column");
  EXPECT_EQ(c.materials[1].cohesion, 3000.0);
  ASSERT_EQ(c.stages.size(), 2u);
  EXPECT_EQ(c.stages[0].type, solver::StageType::kQuasiStatic);
  EXPECT_EQ(c.stages[0].kinetic_energy_ratio, 1e-3);
  EXPECT_EQ(c.stages[1].output_interval, 0.02);
  std::map<std::string, int> group_id;
  for (std::size_t g = 0; g < c.groups.size(); ++g) {
    group_id[c.groups[g].name] = static_cast<int>(g);
    EXPECT_EQ(c.groups[g].dimension, c.groups[g].name == "column" || c.groups[g].name == "layer" ||
                                             c.groups[g].name == "air"
                                         ? dim
                                         : dim - 1)
        << c.groups[g].name;
  }
  for (const char* name : {"column", "layer", "air", "bed", "wall", "gate", "end", "top"})
    EXPECT_TRUE(group_id.count(name)) << name;

  // geometry.vtu: cells first (positive), then facets; `group` is the region group or -1.
  auto geometry = read_vtu(folder / "geometry.vtu");
  ASSERT_EQ(static_cast<std::size_t>(geometry->GetNumberOfPoints()), summary.nodes);
  ASSERT_GT(static_cast<std::size_t>(geometry->GetNumberOfCells()), summary.cells);
  vtkDataArray* group = geometry->GetCellData()->GetArray("group");
  ASSERT_NE(group, nullptr);
  EXPECT_EQ(group->GetDataType(), VTK_INT);
  const int cell_type = dim == 2 ? VTK_TRIANGLE : VTK_TETRA;
  const int facet_type = dim == 2 ? VTK_LINE : VTK_TRIANGLE;
  std::map<int, std::size_t> cells_per_group, facets_per_group;
  for (vtkIdType cell = 0; cell < geometry->GetNumberOfCells(); ++cell) {
    const int g = static_cast<int>(group->GetComponent(cell, 0));
    if (static_cast<std::size_t>(cell) < summary.cells) {
      ASSERT_EQ(geometry->GetCellType(cell), cell_type);
      ++cells_per_group[g];
      // Positive orientation: the cell's centroid has positive barycentric coordinates.
      vtkNew<vtkIdList> ids;
      geometry->GetCellPoints(cell, ids);
      double centroid[3] = {0, 0, 0};
      for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
        for (int k = 0; k < 3; ++k)
          centroid[k] += geometry->GetPoint(ids->GetId(i))[k] / ids->GetNumberOfIds();
      for (double b : barycentric(geometry, cell, centroid, dim)) ASSERT_GT(b, 0.2);
    } else {
      ASSERT_EQ(geometry->GetCellType(cell), facet_type);
      ++facets_per_group[g];
    }
  }
  EXPECT_GT(cells_per_group[-1], 0u);  // air
  EXPECT_GT(cells_per_group[group_id["column"]], 0u);
  EXPECT_GT(cells_per_group[group_id["layer"]], 0u);
  EXPECT_EQ(cells_per_group.count(group_id["air"]), 0u);  // not a region: -1
  for (const char* name : {"bed", "wall", "gate", "end", "top"})
    EXPECT_GT(facets_per_group[group_id[name]], 0u) << name;
  const std::size_t material_cells =
      cells_per_group[group_id["column"]] + cells_per_group[group_id["layer"]];
  EXPECT_EQ(summary.points, 4 * material_cells);

  // points.vtu: the column and the layer, exactly.
  auto points = read_vtu(folder / "points.vtu");
  ASSERT_EQ(static_cast<std::size_t>(points->GetNumberOfPoints()), summary.points);
  EXPECT_EQ(points->GetNumberOfCells(), points->GetNumberOfPoints());
  vtkDataArray* material = point_array(points, "material", 1);
  vtkDataArray* volume = point_array(points, "volume", 1);
  vtkDataArray* mass = point_array(points, "mass", 1);
  vtkDataArray* stress = point_array(points, "stress", 6);
  vtkDataArray* velocity = point_array(points, "velocity", 3);
  vtkDataArray* cell = point_array(points, "cell", 1);
  ASSERT_TRUE(material && volume && mass && stress && velocity && cell);
  EXPECT_EQ(material->GetDataType(), VTK_INT);
  EXPECT_EQ(cell->GetDataType(), VTK_INT);
  EXPECT_EQ(volume->GetDataType(), VTK_DOUBLE);

  const double t = check.thickness;
  EXPECT_NEAR(sum_of(volume), (kColumnArea + kLayerArea) * t,
              1e-9 * (kColumnArea + kLayerArea) * t);
  const double expected_mass = (kColumnDensity * kColumnArea + kLayerDensity * kLayerArea) * t;
  EXPECT_NEAR(sum_of(mass), expected_mass, 1e-9 * expected_mass);

  const double k0_column = 1 - std::sin(25.0 * kPi / 180),
               k0_layer = 1 - std::sin(23.0 * kPi / 180);
  double column_volume = 0, layer_under_column = 0;
  int layer_under_column_count = 0;
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p) {
    const int m = static_cast<int>(material->GetComponent(p, 0));
    ASSERT_TRUE(m == 0 || m == 1);
    if (m == 0) column_volume += volume->GetComponent(p, 0);
    const double density = m == 0 ? kColumnDensity : kLayerDensity;
    EXPECT_NEAR(mass->GetComponent(p, 0), density * volume->GetComponent(p, 0), 1e-12);
    // In its cell, and the cell holds the point's material.
    const auto c_index = static_cast<vtkIdType>(cell->GetComponent(p, 0));
    ASSERT_LT(static_cast<std::size_t>(c_index), summary.cells);
    EXPECT_EQ(static_cast<int>(group->GetComponent(c_index, 0)),
              group_id[m == 0 ? "column" : "layer"]);
    for (double b : barycentric(geometry, c_index, points->GetPoint(p), dim)) EXPECT_GT(b, 0.0);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(velocity->GetComponent(p, k), 0.0);
    // K0 stress, compression negative.
    const double syy = stress->GetComponent(p, 1);
    EXPECT_LT(syy, 0.0);
    EXPECT_NEAR(stress->GetComponent(p, 0), (m == 0 ? k0_column : k0_layer) * syy, 1e-9);
    EXPECT_NEAR(stress->GetComponent(p, 2), stress->GetComponent(p, 0), 1e-9);
    for (int k = 3; k < 6; ++k) EXPECT_EQ(stress->GetComponent(p, k), 0.0);
    const double x = points->GetPoint(p)[0];
    if (m == 1 && x > 0.06 && x < 0.18) {
      layer_under_column += syy;
      ++layer_under_column_count;
    }
  }
  EXPECT_NEAR(column_volume, kColumnArea * t, 1e-9 * kColumnArea * t);
  // Under the column, the layer carries the column's weight: its vertical extent is
  // 0.14 / cos(22 deg), plus on average half the layer's own.
  ASSERT_GT(layer_under_column_count, 0);
  const double overburden =
      9.81 * (kColumnDensity * 0.14 + kLayerDensity * 0.0046 / 2) / std::cos(kSlope);
  EXPECT_NEAR(layer_under_column / layer_under_column_count, -overburden, 0.03 * overburden);
}

TEST(Preprocess, CaseA2D) {
  TempFolder folder;
  const fs::path case_folder = folder / "case";
  const PreprocessSummary summary =
      preprocess(example("case_a_2d") / "scene.toml", case_folder, false);
  std::cout << "case_a_2d: " << summary.nodes << " nodes, " << summary.cells << " cells, "
            << summary.points << " points\n";
  check_case_a(case_folder, summary, {2, 1.0});

  // post.toml: the scene's [post] with a header, and the reference data beside it.
  const toml::table post = toml::parse_file((case_folder / "post.toml").string());
  EXPECT_EQ(post["format"].value<std::string>(), "lituya-post");
  EXPECT_EQ(post["version"].value<int64_t>(), 1);
  EXPECT_EQ(post["stage"].value<std::string>(), "release");
  EXPECT_EQ(post["reference"].value<std::string>(), "reference.csv");
  EXPECT_EQ(post["slope_angle"].value<double>(), 22.0);
  EXPECT_EQ(testing::read_bytes(case_folder / "reference.csv"),
            testing::read_bytes(example("case_a_2d") / "reference.csv"));
  // The header keys come first, as every Lituya file starts.
  EXPECT_EQ(testing::read_bytes(case_folder / "stages.toml")
                .rfind("format = \"lituya-stages\"\n"
                       "version = 1\n",
                       0),
            0u);
}

TEST(Preprocess, CaseA3D) {
  TempFolder folder;
  const fs::path case_folder = folder / "case";
  const PreprocessSummary summary =
      preprocess(example("case_a_3d") / "scene.toml", case_folder, false);
  std::cout << "case_a_3d: " << summary.nodes << " nodes, " << summary.cells << " cells, "
            << summary.points << " points\n";
  check_case_a(case_folder, summary, {3, 0.01});
  const solver::CaseDescription c = solver::read_case(case_folder.string());
  bool sides = false;
  for (const auto& g : c.groups) sides = sides || (g.name == "sides" && g.dimension == 2);
  EXPECT_TRUE(sides);
  EXPECT_EQ(c.boundaries.size(), 5u);
}

TEST(Preprocess, SecondRunDoesNotOverwrite) {
  TempFolder folder;
  const fs::path case_folder = folder / "case";
  const fs::path scene = example("case_a_2d") / "scene.toml";
  preprocess(scene, case_folder, false);
  const std::string geometry = testing::read_bytes(case_folder / "geometry.vtu");
  const std::string points = testing::read_bytes(case_folder / "points.vtu");
  const auto stamp = fs::last_write_time(case_folder / "points.vtu");
  testing::expect_input_error([&] { preprocess(scene, case_folder, false); }, "case", 0,
                              {"--force"});
  EXPECT_EQ(testing::read_bytes(case_folder / "geometry.vtu"), geometry);
  EXPECT_EQ(testing::read_bytes(case_folder / "points.vtu"), points);
  EXPECT_EQ(fs::last_write_time(case_folder / "points.vtu"), stamp);
  // Asked to, it overwrites (and writes the same case again).
  preprocess(scene, case_folder, true);
  EXPECT_EQ(testing::read_bytes(case_folder / "points.vtu"), points);
}

TEST(Preprocess, RefusesAFileAsCaseFolder) {
  TempFolder folder;
  testing::write_text(folder / "case", "not a folder");
  testing::expect_input_error(
      [&] { preprocess(example("case_a_2d") / "scene.toml", folder / "case", true); }, "case", 0,
      {"not a folder"});
}

}  // namespace
}  // namespace lituya::pre
