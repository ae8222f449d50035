#include "lituya/solver/case_description.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lituya/common/input_error.hpp"

namespace {

using namespace lituya::solver;

// A file of the running test: ctest runs the tests of this file side by side, and with one
// shared folder a test read a file another had just rewritten (in CI, December 2026: a
// [solver] table gone, a segmentation fault). Each test writes into a folder of its own.
std::filesystem::path test_file(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / "lituya_case_description_tests" /
                      ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(folder);
  return folder / name;
}

// Writes `root` as the preprocessor does and reads it back as the solver does.
lituya::TomlDocument written_and_read(const toml::table& root, const std::string& name) {
  const auto path = test_file(name);
  std::ofstream(path) << root;
  return lituya::TomlDocument(path);
}

std::string error_reading_material(const std::string& body) {
  auto path = test_file("lituya_material_test.toml");
  std::ofstream(path) << body;
  lituya::TomlDocument doc(path);
  try {
    for (const auto& t : doc.root().tables("material")) read_material(t);
  } catch (const lituya::InputError& e) {
    return e.what();
  }
  return "";
}

const char* kSand = R"([[material]]
name = "sand"
model = "mohr-coulomb"
solid_density = 2650.0
porosity = 0.4
youngs_modulus = 1.0e7
poisson_ratio = 0.3
friction_angle = 30.0
)";

TEST(CaseDescription, ReadsMaterialWithDefaults) {
  auto path = test_file("lituya_material_ok.toml");
  std::ofstream(path) << kSand;
  lituya::TomlDocument doc(path);
  Material m = read_material(doc.root().tables("material").at(0));
  EXPECT_DOUBLE_EQ(m.dry_density(), 0.6 * 2650.0);
  EXPECT_DOUBLE_EQ(m.cohesion, 0.0);
  EXPECT_DOUBLE_EQ(m.tensile_strength, 0.0);  // apex of a cohesionless material
}

TEST(CaseDescription, MaterialErrorsNameFileAndLine) {
  std::string msg = error_reading_material(std::string(kSand) + "frction = 3\n");
  EXPECT_NE(msg.find("lituya_material_test.toml:9"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown key 'frction'"), std::string::npos) << msg;

  std::string missing = kSand;
  missing.replace(missing.find("porosity = 0.4\n"), 15, "");
  msg = error_reading_material(missing);
  EXPECT_NE(msg.find("porosity"), std::string::npos) << msg;

  std::string bad_porosity = kSand;
  bad_porosity.replace(bad_porosity.find("0.4"), 3, "1.2");
  msg = error_reading_material(bad_porosity);
  EXPECT_NE(msg.find(":5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(0, 1)"), std::string::npos) << msg;

  std::string wrong_type = kSand;
  wrong_type.replace(wrong_type.find("1.0e7"), 5, "\"stiff\"");
  msg = error_reading_material(wrong_type);
  EXPECT_NE(msg.find(":6"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must be a number"), std::string::npos) << msg;
}

TEST(CaseDescription, StageReferencingUnknownBoundaryIsAnError) {
  auto path = test_file("lituya_stage_test.toml");
  std::ofstream(path) << "[[boundary]]\ngroup = \"bed\"\ntype = \"fixed\"\n\n[[stage]]\n"
                         "name = \"go\"\ntype = \"dynamic\"\nduration = 1.0\n"
                         "boundaries = [\"bed\", \"gate\"]\n";
  lituya::TomlDocument doc(path);
  auto root = doc.root();
  std::vector<BoundaryCondition> b;
  for (const auto& t : root.tables("boundary")) b.push_back(read_boundary(t, 2));
  std::vector<Stage> s;
  auto tables = root.tables("stage");
  for (const auto& t : tables) s.push_back(read_stage(t));
  try {
    check_stage_boundaries(s, b, tables);
    FAIL();
  } catch (const lituya::InputError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find(":9"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'gate'"), std::string::npos) << msg;
  }
}

TEST(CaseDescription, FixityDirectionMustExistInDimension) {
  auto path = test_file("lituya_fixity_test.toml");
  std::ofstream(path)
      << "[[boundary]]\ngroup = \"gate\"\ntype = \"fixity\"\ndirections = [\"z\"]\n";
  lituya::TomlDocument doc(path);
  EXPECT_THROW(read_boundary(doc.root().tables("boundary").at(0), 2), lituya::InputError);
  EXPECT_NO_THROW(read_boundary(doc.root().tables("boundary").at(0), 3));
}

}  // namespace

namespace {

const char* kWater = R"([[material]]
name = "water"
model = "water"
density = 1000.0
bulk_modulus = 2.15e7
viscosity = 1.0e-3
)";

TEST(CaseDescription, ReadsWaterAndMaxPorosity) {
  auto path = test_file("lituya_water_ok.toml");
  std::ofstream(path) << kWater << "\n" << kSand << "max_porosity = 0.5\n";
  lituya::TomlDocument doc(path);
  auto tables = doc.root().tables("material");
  Material water = read_material(tables.at(0));
  EXPECT_TRUE(water.is_liquid());
  EXPECT_DOUBLE_EQ(water.bulk_modulus, 2.15e7);
  EXPECT_DOUBLE_EQ(water.viscosity, 1.0e-3);
  EXPECT_DOUBLE_EQ(water.liquid_density, 1000.0);
  Material sand = read_material(tables.at(1));
  EXPECT_DOUBLE_EQ(sand.max_porosity, 0.5);
  // Written and read back: the same values (materials.toml is written with to_toml).
  toml::table root;
  toml::array list;
  list.push_back(to_toml(water));
  list.push_back(to_toml(sand));
  root.insert("material", list);
  const lituya::TomlDocument doc2 = written_and_read(root, "lituya_water_back.toml");
  auto again = doc2.root().tables("material");
  EXPECT_DOUBLE_EQ(read_material(again.at(0)).bulk_modulus, 2.15e7);
  EXPECT_DOUBLE_EQ(read_material(again.at(1)).max_porosity, 0.5);
}

TEST(CaseDescription, WaterErrorsNameFileAndLine) {
  // A liquid without bulk modulus: named, with what is expected.
  std::string no_bulk = kWater;
  no_bulk.replace(no_bulk.find("bulk_modulus = 2.15e7\n"), 22, "");
  std::string msg = error_reading_material(no_bulk);
  EXPECT_NE(msg.find("missing 'bulk_modulus'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lituya_material_test.toml"), std::string::npos) << msg;
  std::string no_viscosity = kWater;
  no_viscosity.replace(no_viscosity.find("viscosity = 1.0e-3\n"), 19, "");
  msg = error_reading_material(no_viscosity);
  EXPECT_NE(msg.find("missing 'viscosity'"), std::string::npos) << msg;
  // A soil key on water, and a water key on soil, are errors at their line.
  msg = error_reading_material(std::string(kWater) + "porosity = 0.4\n");
  EXPECT_NE(msg.find(":7"), std::string::npos) << msg;
  EXPECT_NE(msg.find("soil parameter"), std::string::npos) << msg;
  msg = error_reading_material(std::string(kSand) + "density = 1000.0\n");
  EXPECT_NE(msg.find(":9"), std::string::npos) << msg;
  // n_max below the initial porosity (0.4).
  msg = error_reading_material(std::string(kSand) + "max_porosity = 0.35\n");
  EXPECT_NE(msg.find(":9"), std::string::npos) << msg;
  EXPECT_NE(msg.find("max_porosity"), std::string::npos) << msg;
  // Negative bulk modulus: out of range at its line.
  std::string negative = kWater;
  negative.replace(negative.find("2.15e7"), 6, "-1.0");
  msg = error_reading_material(negative);
  EXPECT_NE(msg.find(":5"), std::string::npos) << msg;
}

}  // namespace

namespace {

std::string error_reading_boundary(const std::string& body, int dimension) {
  auto path = test_file("lituya_boundary_test.toml");
  std::ofstream(path) << body;
  lituya::TomlDocument doc(path);
  try {
    read_boundary(doc.root().tables("boundary").at(0), dimension);
  } catch (const lituya::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CaseDescription, TractionAndPhaseBoundaries) {
  auto path = test_file("lituya_traction_ok.toml");
  std::ofstream(path) << "[[boundary]]\ngroup = \"top\"\ntype = \"traction\"\n"
                         "traction = [0.0, -1.0e4]\n\n"
                         "[[boundary]]\ngroup = \"plate\"\ntype = \"fixed\"\nphase = \"solid\"\n";
  lituya::TomlDocument doc(path);
  auto tables = doc.root().tables("boundary");
  BoundaryCondition load = read_boundary(tables.at(0), 2);
  EXPECT_EQ(load.type, BoundaryType::kTraction);
  EXPECT_EQ(load.phase, BoundaryPhase::kSolid);  // a load acts on the skeleton by default
  EXPECT_DOUBLE_EQ(load.traction.at(1), -1.0e4);
  BoundaryCondition plate = read_boundary(tables.at(1), 2);
  EXPECT_EQ(plate.phase, BoundaryPhase::kSolid);
  // Written and read back.
  toml::table root;
  toml::array list;
  list.push_back(to_toml(load));
  list.push_back(to_toml(plate));
  root.insert("boundary", list);
  const lituya::TomlDocument doc2 = written_and_read(root, "lituya_traction_back.toml");
  EXPECT_DOUBLE_EQ(read_boundary(doc2.root().tables("boundary").at(0), 2).traction.at(1), -1.0e4);
  EXPECT_EQ(read_boundary(doc2.root().tables("boundary").at(1), 2).phase, BoundaryPhase::kSolid);
}

TEST(CaseDescription, TractionErrorsNameTheLine) {
  // Three components in 2D.
  std::string msg = error_reading_boundary(
      "[[boundary]]\ngroup = \"top\"\ntype = \"traction\"\ntraction = [0.0, 1.0, 2.0]\n", 2);
  EXPECT_NE(msg.find(":4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("2 components"), std::string::npos) << msg;
  // A traction on a fixed boundary, and "both" on a traction.
  msg = error_reading_boundary(
      "[[boundary]]\ngroup = \"b\"\ntype = \"fixed\"\ntraction = [0.0, 1.0]\n", 2);
  EXPECT_NE(msg.find(":4"), std::string::npos) << msg;
  msg = error_reading_boundary(
      "[[boundary]]\ngroup = \"b\"\ntype = \"traction\"\ntraction = [0.0, 1.0]\n"
      "phase = \"both\"\n",
      2);
  EXPECT_NE(msg.find(":5"), std::string::npos) << msg;
  // A load ramp on a velocity boundary.
  msg = error_reading_boundary("[[boundary]]\ngroup = \"b\"\ntype = \"roller\"\nramp_time = 0.5\n",
                               2);
  EXPECT_NE(msg.find(":4"), std::string::npos) << msg;
  // A traction without its vector.
  msg = error_reading_boundary("[[boundary]]\ngroup = \"b\"\ntype = \"traction\"\n", 2);
  EXPECT_NE(msg.find("traction"), std::string::npos) << msg;
}

}  // namespace

namespace {

// Reads a [solver] table that must be rejected; returns the error message.
std::string error_reading_solver_settings(const std::string& text) {
  auto path = test_file("lituya_solver_settings.toml");
  std::ofstream(path) << text;
  lituya::TomlDocument doc(path);
  const std::optional<lituya::TomlTable> solver = doc.root().optional_table("solver");
  if (!solver) return "no [solver] table in " + path.string();
  try {
    read_solver_settings(*solver);
  } catch (const lituya::InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(CaseDescription, DampingTimesExcludeFlipFraction) {
  // The error names the line of the second setting and the key.
  std::string msg =
      error_reading_solver_settings("[solver]\nflip_fraction = 0.99\npic_damping_time = 0.01\n");
  EXPECT_NE(msg.find(":3"), std::string::npos) << msg;
  msg = error_reading_solver_settings(
      "[solver]\nflip_fraction = 0.99\n\nliquid_pic_damping_time = 0.01\n");
  EXPECT_NE(msg.find(":4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("liquid_pic_damping_time"), std::string::npos) << msg;
}

TEST(CaseDescription, GivenDampingTimesAreWrittenBackAlone) {
  // Written back, a damping time comes without flip_fraction, and reads again.
  SolverSettings s;
  s.pic_damping_time = 0.01;
  toml::table root;
  root.insert("solver", to_toml(s));
  const lituya::TomlDocument doc2 = written_and_read(root, "lituya_solver_back.toml");
  const SolverSettings read_back = read_solver_settings(*doc2.root().optional_table("solver"));
  ASSERT_TRUE(read_back.pic_damping_time.has_value());
  EXPECT_DOUBLE_EQ(*read_back.pic_damping_time, 0.01);
  EXPECT_FALSE(read_back.flip_fraction.has_value());
  EXPECT_FALSE(read_back.liquid_pic_damping_time.has_value());
}

TEST(CaseDescription, PressureProjectionIsCountedInStepsOrInTimeNotBoth) {
  // Both given: the error names the line of the time and the key.
  const std::string msg = error_reading_solver_settings(
      "[solver]\npressure_projection_interval = 10\npressure_projection_time = 0.001\n");
  EXPECT_NE(msg.find(":3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("pressure_projection_time"), std::string::npos) << msg;
  EXPECT_NE(error_reading_solver_settings("[solver]\npressure_projection_time = 0\n"), "accepted");
  // Neither is written back when neither was given (the default, by time, stays a default);
  // a given one is written back alone and reads again.
  SolverSettings s;
  toml::table root;
  root.insert("solver", to_toml(s));
  const SolverSettings none = read_solver_settings(
      *written_and_read(root, "lituya_projection_none.toml").root().optional_table("solver"));
  EXPECT_FALSE(none.pressure_projection_interval.has_value());
  EXPECT_FALSE(none.pressure_projection_time.has_value());
  s.pressure_projection_time = 0.002;
  root.insert_or_assign("solver", to_toml(s));
  const SolverSettings timed = read_solver_settings(
      *written_and_read(root, "lituya_projection_time.toml").root().optional_table("solver"));
  ASSERT_TRUE(timed.pressure_projection_time.has_value());
  EXPECT_DOUBLE_EQ(*timed.pressure_projection_time, 0.002);
  EXPECT_FALSE(timed.pressure_projection_interval.has_value());
}

TEST(CaseDescription, LiquidXpicOrderIsAnIntegerFromOneToEight) {
  // Out of range: the error names the line and the key.
  for (const char* wrong : {"0", "9", "2.5"}) {
    const std::string msg =
        error_reading_solver_settings(std::string("[solver]\nliquid_xpic_order = ") + wrong + "\n");
    EXPECT_NE(msg.find(":2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("liquid_xpic_order"), std::string::npos) << msg;
  }
  // The default (1, the plain blend) is not written; a given order is, and reads back.
  SolverSettings s;
  toml::table root;
  root.insert("solver", to_toml(s));
  EXPECT_EQ(read_solver_settings(
                *written_and_read(root, "lituya_xpic_none.toml").root().optional_table("solver"))
                .liquid_xpic_order,
            1);
  s.liquid_xpic_order = 3;
  root.insert_or_assign("solver", to_toml(s));
  EXPECT_EQ(read_solver_settings(
                *written_and_read(root, "lituya_xpic_three.toml").root().optional_table("solver"))
                .liquid_xpic_order,
            3);
}

// The [solver] choice keys: a scene whose line 2 sets `key` to `wrong` must fail at that
// line, naming the key; `settings` (a non-default choice) must survive being written to a
// case file and read back.
SolverSettings check_solver_choice(const std::string& key, const std::string& wrong,
                                   const SolverSettings& settings) {
  const std::string msg =
      error_reading_solver_settings("[solver]\n" + key + " = \"" + wrong + "\"\n");
  EXPECT_NE(msg.find(":2"), std::string::npos) << msg;
  EXPECT_NE(msg.find(key), std::string::npos) << msg;
  toml::table root;
  root.insert("solver", to_toml(settings));
  return read_solver_settings(
      *written_and_read(root, "lituya_" + key + ".toml").root().optional_table("solver"));
}

TEST(CaseDescription, PorePressureCellMeasureIsSoilOrWater) {
  EXPECT_EQ(SolverSettings{}.pore_pressure_cell_measure, PorePressureMeasure::kSoil);
  SolverSettings s;
  s.pore_pressure_cell_measure = PorePressureMeasure::kWater;
  EXPECT_EQ(
      check_solver_choice("pore_pressure_cell_measure", "grains", s).pore_pressure_cell_measure,
      PorePressureMeasure::kWater);
}

// A boolean [solver] key that is on unless set: `false` survives the written case, and a value
// that is not a boolean is an error naming its line and the key.
void expect_switch_on_by_default(const std::string& key, bool SolverSettings::*member) {
  EXPECT_TRUE(SolverSettings{}.*member);
  SolverSettings s;
  s.*member = false;
  toml::table root;
  root.insert("solver", to_toml(s));
  EXPECT_FALSE(
      read_solver_settings(
          *written_and_read(root, "lituya_" + key + ".toml").root().optional_table("solver")).*
      member);
  const std::string msg = error_reading_solver_settings("[solver]\n" + key + " = \"yes\"\n");
  EXPECT_NE(msg.find(":2"), std::string::npos) << msg;
  EXPECT_NE(msg.find(key), std::string::npos) << msg;
}

TEST(CaseDescription, FreeWaterCellVolumeIsOnUnlessSetAndSurvivesTheWrittenCase) {
  expect_switch_on_by_default("free_water_cell_volume", &SolverSettings::free_water_cell_volume);
}

TEST(CaseDescription, CrossedPressureFilterIsOnUnlessSetAndSurvivesTheWrittenCase) {
  expect_switch_on_by_default("crossed_pressure_filter", &SolverSettings::crossed_pressure_filter);
}

// Two choices of the water's treatment: each default, and the other value written into a case
// and read back (a wrong word names its line and key).
TEST(CaseDescription, LiquidAdvectionIsVelocityOrFluxAndLandingIsMergeOrKeepVelocity) {
  EXPECT_EQ(SolverSettings{}.liquid_advection, LiquidAdvection::kVelocity);
  EXPECT_EQ(SolverSettings{}.liquid_landing, LiquidLanding::kMerge);
  SolverSettings s;
  s.liquid_advection = LiquidAdvection::kFlux;
  s.liquid_landing = LiquidLanding::kKeepVelocity;
  EXPECT_EQ(check_solver_choice("liquid_advection", "darcy", s).liquid_advection,
            LiquidAdvection::kFlux);
  EXPECT_EQ(check_solver_choice("liquid_landing", "bounce", s).liquid_landing,
            LiquidLanding::kKeepVelocity);
}

// stages.toml and materials.toml can be edited by hand between `lituya pre` and `lituya
// solve`: the case loader applies the same checks as the scene reader, so a stage name that
// cannot make a file name or a non-finite gravity stops at its line, before any output.
TEST(CaseDescription, HandEditedCaseRefusesUnsafeNamesAndNonFiniteGravity) {
  const auto folder = std::filesystem::temp_directory_path() / "lituya_hand_edited_case";
  std::filesystem::create_directories(folder);
  const std::string head = "format = \"lituya-stages\"\nversion = 1\ndimension = 2\n";  // lines 1-3
  const std::string files =
      "geometry = \"geometry.vtu\"\npoints = \"points.vtu\"\nmaterials = \"materials.toml\"\n";
  auto error_in = [&](const std::string& gravity, const std::string& stage_name) {
    std::ofstream(folder / "stages.toml") << head << "gravity = " << gravity << "\n"
                                          << files << "\n[[stage]]\nname = " << stage_name
                                          << "\ntype = \"dynamic\"\nduration = 1.0\n";
    try {
      read_case(folder.string());
    } catch (const lituya::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  std::string msg = error_in("[0.0, -9.81]", "'grav/ity'");
  EXPECT_NE(msg.find("stages.toml:10:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'/'"), std::string::npos) << msg;
  msg = error_in("[0.0, -9.81]", "'a&b'");
  EXPECT_NE(msg.find("stages.toml:10:"), std::string::npos) << msg;
  msg = error_in("[0.0, -inf]", "'release'");
  EXPECT_NE(msg.find("stages.toml:4:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not a finite number"), std::string::npos) << msg;

  std::string bad_material = kSand;
  bad_material.replace(bad_material.find("\"sand\""), 6, "\"..\"");
  msg = error_reading_material(bad_material);
  EXPECT_NE(msg.find("lituya_material_test.toml:2:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("starts with '.'"), std::string::npos) << msg;
  std::filesystem::remove_all(folder);
}

// A rough wall names a material of the scene; pre resolves it to the number. A hand-edited
// stages.toml that keeps `rough` would otherwise run with friction 0.
TEST(CaseDescription, RoughWallIsResolvedByThePreprocessor) {
  const auto folder = std::filesystem::temp_directory_path() / "lituya_rough_in_case";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "stages.toml")
      << "format = \"lituya-stages\"\nversion = 1\ndimension = 2\ngravity = [0.0, -9.81]\n"
         "geometry = \"geometry.vtu\"\npoints = \"points.vtu\"\nmaterials = \"materials.toml\"\n"
         "\n[[group]]\nname = \"bed\"\ndimension = 1\n"
         "\n[[boundary]]\ngroup = \"bed\"\ntype = \"contact\"\nrough = \"sand\"\n"  // line 16
         "\n[[stage]]\nname = \"go\"\ntype = \"dynamic\"\nduration = 1.0\n";
  std::string msg = "accepted";
  try {
    read_case(folder.string());
  } catch (const lituya::InputError& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("stages.toml:16:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("belongs in scene.toml"), std::string::npos) << msg;
  std::filesystem::remove_all(folder);
}

}  // namespace
