// The memory check before meshing: the estimate against gmsh's real cell counts, the refusal
// of a cell size far too small (quickly, naming scene.toml's cell_size line), the override.
#include "lituya/pre/mesh_size.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "lituya/pre/gmsh_mesh.hpp"
#include "lituya/pre/preprocess.hpp"
#include "test_support.hpp"

namespace lituya::pre {
namespace {

namespace fs = std::filesystem;
using testing::expect_input_error;
using testing::TempFolder;
using testing::test_data;

// The estimate is meant to be within a few tens of percent, not exact: 30 % is the brief's
// tolerance, and what makes the refusal threshold meaningful.
void expect_estimate_close(const fs::path& geometry, const MeshingOptions& options) {
  const MeshSizeEstimate estimate = estimate_gmsh_mesh(geometry, options);
  const double actual = static_cast<double>(read_gmsh_mesh(geometry, options).cell_count());
  std::cout << geometry.filename().string() << " at " << options.cell_size << " m: estimate "
            << estimate.cells << " cells, gmsh " << actual << "\n";
  EXPECT_NEAR(estimate.cells, actual, 0.3 * actual);
  EXPECT_DOUBLE_EQ(estimate.points, estimate.cells * options.size_check.points_per_cell);
  EXPECT_GT(estimate.bytes, estimate.cells * kBytesPerCell);
}

TEST(MeshSize, EstimateOf2DRectangle) {
  // Built-in kernel: the bounding boxes of the two unit squares, 2 m^2.
  MeshingOptions options{2, 0.02, false};
  options.size_check.points_per_cell = 4;
  expect_estimate_close(test_data("two_squares.geo"), options);
}

TEST(MeshSize, EstimateOfCrossed2DRectangle) {
  // Quadrangles of about h^2, four triangles each: about 1.7 times the plain mesh's cells.
  MeshingOptions options{2, 0.02, false, true};
  options.size_check.points_per_cell = 4;
  expect_estimate_close(test_data("two_squares.geo"), options);
}

TEST(MeshSize, EstimateOf3DCube) {
  // OpenCASCADE kernel: the unit cube's exact volume.
  MeshingOptions options{3, 0.08, false};
  options.size_check.points_per_cell = 4;
  expect_estimate_close(test_data("cube.geo"), options);
}

TEST(MeshSize, EstimateScalesWithCellSize) {
  const MeshSizeEstimate coarse = estimate_mesh_size(1.0, 2, 0.02, 4);
  const MeshSizeEstimate fine = estimate_mesh_size(1.0, 2, 0.01, 4);
  EXPECT_NEAR(fine.cells / coarse.cells, 4.0, 1e-12);
  EXPECT_NEAR(estimate_mesh_size(1.0, 3, 0.01, 1).cells / estimate_mesh_size(1.0, 3, 0.02, 1).cells,
              8.0, 1e-12);
  EXPECT_GT(available_memory_bytes(), 0.0);
}

// A copy of examples/case_b_2d with `cell_size` changed; returns the scene and the line.
std::pair<fs::path, int> case_b_with_cell_size(const TempFolder& folder, const std::string& h) {
  const fs::path scene_folder = folder / "scene";
  fs::copy(testing::source_dir() / "examples" / "case_b_2d", scene_folder,
           fs::copy_options::recursive);
  const fs::path scene = scene_folder / "scene.toml";
  std::string text = testing::read_bytes(scene);
  const std::regex cell_size(R"(\ncell_size = [^\n]*)");
  std::smatch m;
  EXPECT_TRUE(std::regex_search(text, m, cell_size));
  const int line =
      static_cast<int>(std::count(text.begin(), text.begin() + m.position(0) + 1, '\n')) + 1;
  text = std::regex_replace(text, cell_size, "\ncell_size = " + h);
  testing::write_text(scene, text);
  return {scene, line};
}

TEST(MeshSize, TinyCellSizeIsRefusedBeforeMeshing) {
  TempFolder folder;
  const auto [scene, line] = case_b_with_cell_size(folder, "1e-6");
  const auto start = std::chrono::steady_clock::now();
  const std::string message = expect_input_error(
      [&] { preprocess(scene, folder / "case", false); }, "scene.toml", line,
      {"cell_size = 1e-06 would give about ", " cells and ", " points, needing about ",
       " GB; this machine has ", "--allow-large-mesh"});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << message << "\n(" << seconds << " s)\n";
  EXPECT_LT(seconds, 1.0);
  EXPECT_FALSE(fs::exists(folder / "case"));  // refused before anything is written
  // case_b's flume holds square metres: some 1e12 cells at a micrometre.
  EXPECT_TRUE(std::regex_search(message, std::regex(R"(about \d(\.\d)?e\+1[12] cells)")))
      << message;
}

TEST(MeshSize, OverrideLetsAModerateMeshThrough) {
  // A machine with 1 MB: two_squares at 0.02 m (some 11 000 cells) does not fit...
  MeshingOptions options{2, 0.02, false};
  options.size_check = {true, 4, "scene.toml", 7, 1e6};
  expect_input_error([&] { read_gmsh_mesh(test_data("two_squares.geo"), options); }, "scene.toml",
                     7, {"cell_size = 0.02", "0.001 GB available"});
  // ...unless the check is off, which is what --allow-large-mesh does.
  options.size_check.enabled = false;
  EXPECT_GT(read_gmsh_mesh(test_data("two_squares.geo"), options).cell_count(), 5000u);
}

TEST(MeshSize, ModerateSceneMeshesWithAndWithoutOverride) {
  TempFolder folder;
  const auto [scene, line] = case_b_with_cell_size(folder, "0.05");
  EXPECT_GT(line, 0);
  EXPECT_GT(preprocess(scene, folder / "checked", false).cells, 0u);
  EXPECT_GT(preprocess(scene, folder / "allowed", false, /*allow_large_mesh=*/true).cells, 0u);
}

}  // namespace
}  // namespace lituya::pre
