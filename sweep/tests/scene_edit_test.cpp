#include "lituya/sweep/scene_edit.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lituya/common/error_message.hpp"
#include "lituya/common/input_error.hpp"

namespace {

namespace fs = std::filesystem;
using lituya::sweep::KeyTarget;
using lituya::sweep::SceneText;
using lituya::sweep::ValueType;

// A scene in its own folder, with the geometry and reference files it names.
const char* kScene = R"(format = "lituya-scene"
version = 1
gravity = [0.0, -9.81]

[mesh]
geometry = "slide.geo"   # relative to this file
dimension = 2
cell_size = 0.01         # m
points_per_cell = 4

[[material]]
name = "beads"
model = "mohr-coulomb"
solid_density = 2500.0
porosity = 0.4
youngs_modulus = 1.0e6
poisson_ratio = 0.3
friction_angle = 25.0

[[material]]
name = "layer"
model = "linear-elastic"
solid_density = 1800.0
porosity = 0.3
youngs_modulus = 2.0e7
poisson_ratio = 0.3

[[region]]
group = "slide"
material = "beads"

[[boundary]]
name = "glued"
group = "bed"
type = "fixed"

[[boundary]]
name = "rough"
group = "bed"
type = "contact"
friction = 0.4

[[stage]]
name = "gravity"
type = "quasi-static"
duration = 0.5
boundaries = ["glued"]

[[stage]]
name = "release"
type = "dynamic"
duration = 1.0
courant = 0.5
boundaries = ["rough"]

[post]
track_materials = ["beads"]
reference = "data/reference.csv"
)";

fs::path write_scene(const std::string& name, const std::string& text = kScene) {
  const fs::path folder = fs::temp_directory_path() / ("lituya_sweep_edit_" + name);
  fs::create_directories(folder / "data");
  std::ofstream(folder / "scene.toml") << text;
  return folder / "scene.toml";
}

using lituya::input_error_message;

// The line (1-based) of `text` that holds `needle`.
int line_with(const std::string& text, const std::string& needle) {
  const size_t at = text.find(needle);
  return at == std::string::npos
             ? 0
             : 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

TEST(SceneEdit, FindsMaterialsAndStagesByNameAndMeshKeys) {
  const SceneText scene(write_scene("find"));
  const KeyTarget phi = scene.locate("material.beads.friction_angle");
  EXPECT_TRUE(phi.present);
  EXPECT_EQ(phi.type, ValueType::kNumber);
  EXPECT_EQ(phi.current, "25.0");
  EXPECT_EQ(phi.line, line_with(kScene, "friction_angle"));
  EXPECT_NE(phi.where.find("\"beads\""), std::string::npos);

  const KeyTarget courant = scene.locate("stage.release.courant");
  EXPECT_TRUE(courant.present);
  EXPECT_EQ(courant.current, "0.5");

  const KeyTarget ppc = scene.locate("mesh.points_per_cell");
  EXPECT_EQ(ppc.type, ValueType::kInteger);
  EXPECT_EQ(ppc.current, "4");
  EXPECT_EQ(scene.locate("mesh.cell_size").current, "0.01");

  // Regions by group, boundaries by name (two share the group "bed"), arrays by index.
  EXPECT_EQ(scene.locate("region.slide.material").type, ValueType::kString);
  EXPECT_EQ(scene.locate("boundary.rough.friction").current, "0.4");
  EXPECT_EQ(scene.locate("gravity.1").current, "-9.81");
  EXPECT_EQ(scene.locate("material.1.porosity").current, "0.3");
}

TEST(SceneEdit, ReplacesOnlyTheValueAndMakesFilesAbsolute) {
  const fs::path file = write_scene("replace");
  const SceneText scene(file);
  const KeyTarget phi = scene.locate("material.beads.friction_angle");
  const std::vector<std::string> literals = scene.literals(phi, {"18", "22.5", " 1e1 "});
  EXPECT_EQ(literals, (std::vector<std::string>{"18.0", "22.5", "1e1"}));

  const std::string copy = scene.with_value(phi, literals[0], {"a note"});
  EXPECT_EQ(SceneText::value_in(copy, "material.beads.friction_angle"), "18.0");
  // The other material and everything else keep their values; the line numbers are kept.
  EXPECT_EQ(SceneText::value_in(copy, "material.layer.porosity"), "0.3");
  EXPECT_EQ(line_with(copy, "friction_angle"), line_with(kScene, "friction_angle"));
  EXPECT_NE(copy.find("cell_size = 0.01         # m"), std::string::npos);
  EXPECT_NE(copy.find("# a note\n"), std::string::npos);
  // The file references are absolute, so the copy runs from any folder.
  const std::string geometry = (file.parent_path() / "slide.geo").lexically_normal().string();
  EXPECT_EQ(SceneText::value_in(copy, "mesh.geometry"), "\"" + geometry + "\"");
  const std::string reference =
      (file.parent_path() / "data" / "reference.csv").lexically_normal().string();
  EXPECT_EQ(SceneText::value_in(copy, "post.reference"), "\"" + reference + "\"");

  // Integer keys take integers; string keys are quoted.
  const KeyTarget ppc = scene.locate("mesh.points_per_cell");
  EXPECT_EQ(scene.literals(ppc, {"1", "9", "16.0"}), (std::vector<std::string>{"1", "9", "16"}));
  EXPECT_EQ(SceneText::value_in(scene.with_value(ppc, "9", {}), "mesh.points_per_cell"), "9");
  const KeyTarget model = scene.locate("material.layer.model");
  EXPECT_EQ(scene.literals(model, {"mohr-coulomb"}),
            (std::vector<std::string>{"\"mohr-coulomb\""}));
}

TEST(SceneEdit, AddsAKeyTheSceneDoesNotSet) {
  const SceneText scene(write_scene("add"));
  // In an existing [[stage]] entry...
  const KeyTarget courant = scene.locate("stage.gravity.courant");
  EXPECT_FALSE(courant.present);
  const std::vector<std::string> literals = scene.literals(courant, {"0.25", "1"});
  EXPECT_EQ(literals, (std::vector<std::string>{"0.25", "1.0"}));  // numbers: one type for all
  const std::string copy = scene.with_value(courant, literals[0], {});
  EXPECT_EQ(SceneText::value_in(copy, "stage.gravity.courant"), "0.25");
  EXPECT_EQ(SceneText::value_in(copy, "stage.release.courant"), "0.5");
  // ... and in a top-level table the scene does not have.
  const KeyTarget flip = scene.locate("solver.flip_fraction");
  EXPECT_FALSE(flip.present);
  const std::string with_solver = scene.with_value(flip, "0.9", {});
  EXPECT_EQ(SceneText::value_in(with_solver, "solver.flip_fraction"), "0.9");
  EXPECT_EQ(SceneText::value_in(with_solver, "post.track_materials.0"), "\"beads\"");
}

// A sweep of several keys sets them all in one copy: values replaced in place, keys added to
// an existing table, and keys of a table the scene does not have under one new header (two
// [solver] headers would not parse).
TEST(SceneEdit, SetsSeveralKeysInOneCopy) {
  const SceneText scene(write_scene("several"));
  const KeyTarget cell = scene.locate("mesh.cell_size");
  const KeyTarget courant = scene.locate("stage.gravity.courant");
  const KeyTarget flip = scene.locate("solver.flip_fraction");
  const KeyTarget damping = scene.locate("solver.damping");
  const std::string copy = scene.with_values(
      {{cell, "0.02"}, {courant, "0.25"}, {flip, "0.9"}, {damping, "0.1"}}, {"a note"});
  EXPECT_EQ(SceneText::value_in(copy, "mesh.cell_size"), "0.02");
  EXPECT_EQ(SceneText::value_in(copy, "stage.gravity.courant"), "0.25");
  EXPECT_EQ(SceneText::value_in(copy, "solver.flip_fraction"), "0.9");
  EXPECT_EQ(SceneText::value_in(copy, "solver.damping"), "0.1");
  EXPECT_EQ(SceneText::value_in(copy, "stage.release.courant"), "0.5");
  const size_t header = copy.find("[solver]\nflip_fraction = 0.9\ndamping = 0.1\n");
  EXPECT_NE(header, std::string::npos) << copy;
  EXPECT_EQ(copy.find("[solver]", header + 1), std::string::npos) << copy;
  EXPECT_NE(copy.find("# a note\n"), std::string::npos);
  // One key alone gives the same text as with_value.
  EXPECT_EQ(scene.with_values({{cell, "0.02"}}, {}), scene.with_value(cell, "0.02", {}));
}

TEST(SceneEdit, UnknownPathsNameTheSceneAndWhatExists) {
  const fs::path file = write_scene("unknown");
  const SceneText scene(file);
  const std::string no_material =
      input_error_message([&] { scene.locate("material.beeds.friction_angle"); });
  EXPECT_NE(no_material.find(file.string()), std::string::npos) << no_material;
  EXPECT_NE(no_material.find("\"beeds\""), std::string::npos) << no_material;
  EXPECT_NE(no_material.find("\"beads\", \"layer\""), std::string::npos) << no_material;

  const std::string no_stage = input_error_message([&] { scene.locate("stage.relase.courant"); });
  EXPECT_NE(no_stage.find("\"gravity\", \"release\""), std::string::npos) << no_stage;

  const std::string no_table = input_error_message([&] { scene.locate("mesh.refinement.level"); });
  EXPECT_NE(no_table.find(file.string() + ":" + std::to_string(line_with(kScene, "[mesh]"))),
            std::string::npos)
      << no_table;
  EXPECT_NE(no_table.find("\"cell_size\""), std::string::npos) << no_table;

  // Two boundaries share the group "bed": selecting by it is ambiguous.
  const std::string ambiguous = input_error_message([&] { scene.locate("boundary.bed.friction"); });
  EXPECT_NE(ambiguous.find("\"glued\", \"rough\""), std::string::npos) << ambiguous;

  EXPECT_NE(input_error_message([&] { scene.locate("material.beads"); }).find("is a table"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] { scene.locate("gravity"); }).find("is an array"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] { scene.locate("gravity.2"); }).find("not an index"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] { scene.locate("mesh..cell_size"); }).find("not a key path"),
            std::string::npos);
}

TEST(SceneEdit, WrongValueTypesAreInputErrorsAtTheKeyLine) {
  const fs::path file = write_scene("types");
  const SceneText scene(file);
  const KeyTarget phi = scene.locate("material.beads.friction_angle");
  const std::string not_number = input_error_message([&] { scene.literals(phi, {"18", "steep"}); });
  EXPECT_NE(not_number.find(file.string() + ":" + std::to_string(phi.line) + ":"),
            std::string::npos)
      << not_number;
  EXPECT_NE(not_number.find("'steep' is not a number"), std::string::npos) << not_number;

  const KeyTarget ppc = scene.locate("mesh.points_per_cell");
  EXPECT_NE(
      input_error_message([&] { scene.literals(ppc, {"4.5"}); }).find("'4.5' is not an integer"),
      std::string::npos);
  const KeyTarget gravity = scene.locate("gravity.1");
  EXPECT_NE(input_error_message([&] { scene.literals(gravity, {"true"}); }).find("not a number"),
            std::string::npos);
}

}  // namespace
