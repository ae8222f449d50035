#include "lituya/solver/case_description.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lituya/common/input_error.hpp"

namespace {

using namespace lituya::solver;

std::string error_reading_material(const std::string& body) {
  auto path = std::filesystem::temp_directory_path() / "lituya_material_test.toml";
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
  auto path = std::filesystem::temp_directory_path() / "lituya_material_ok.toml";
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
  auto path = std::filesystem::temp_directory_path() / "lituya_stage_test.toml";
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
  auto path = std::filesystem::temp_directory_path() / "lituya_fixity_test.toml";
  std::ofstream(path)
      << "[[boundary]]\ngroup = \"gate\"\ntype = \"fixity\"\ndirections = [\"z\"]\n";
  lituya::TomlDocument doc(path);
  EXPECT_THROW(read_boundary(doc.root().tables("boundary").at(0), 2), lituya::InputError);
  EXPECT_NO_THROW(read_boundary(doc.root().tables("boundary").at(0), 3));
}

}  // namespace
