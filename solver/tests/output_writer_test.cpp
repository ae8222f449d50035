// The output series of a run: time that runs on across stages (TimeValue in every file and
// the run-wide .pvd), the fields chosen in [output] and nothing else, output/README.txt naming
// every field written, and the [output] keys refused with file, line and the known fields.
#include "lituya/solver/output_writer.hpp"

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "lituya/common/input_error.hpp"
#include "lituya/solver/box_scene.hpp"

namespace {

using namespace lituya::solver;
namespace fs = std::filesystem;

std::string contents(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Stage stage(const std::string& name, double duration, double interval) {
  Stage s;
  s.name = name;
  s.type = StageType::kDynamic;
  s.duration = duration;
  s.output_interval = interval;
  s.courant = 0.5;
  return s;
}

// A 2D box of dry sand with a pool of water beside it, so that every file (solid, liquid,
// grid) is written.
BoxScene<2> sand_and_water() {
  BoxScene<2> s;
  s.domain_size = {1.0, 0.5};
  s.cells = {10, 5};
  s.block_min = {0.0, 0.0};
  s.block_max = {0.3, 0.3};
  s.material.name = "sand";
  s.material.model = MaterialModel::kLinearElastic;
  s.material.porosity = 0.4;
  s.material.solid_density = 2650;
  s.material.youngs_modulus = 1e6;
  s.material.poisson_ratio = 0.3;
  s.material.grain_diameter = 0.002;
  s.gravity = {0.0, -9.81};
  s.with_water = true;
  s.water = paper_water();
  s.water_min = {0.5, 0.0};
  s.water_max = {1.0, 0.2};
  for (const char* side : {"x-", "x+", "y-"})
    s.boundaries.push_back({side, box_condition(BoundaryType::kRoller)});
  return s;
}

struct Vtu {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  explicit Vtu(const fs::path& file) {
    reader->SetFileName(file.c_str());
    reader->Update();
  }
  vtkUnstructuredGrid* grid() { return reader->GetOutput(); }
  double field(const char* name) {
    vtkDataArray* a = grid()->GetFieldData()->GetArray(name);
    return a ? a->GetTuple1(0) : -1.0;
  }
  std::set<std::string> point_arrays() {
    std::set<std::string> names;
    for (int i = 0; i < grid()->GetPointData()->GetNumberOfArrays(); ++i)
      names.insert(grid()->GetPointData()->GetArrayName(i));
    return names;
  }
};

// The .pvd's (time, file) entries, in order.
std::vector<std::pair<double, std::string>> pvd_entries(const fs::path& pvd) {
  std::vector<std::pair<double, std::string>> entries;
  const std::string text = contents(pvd);
  for (std::size_t at = text.find("<DataSet"); at != std::string::npos;
       at = text.find("<DataSet", at + 1)) {
    const std::size_t t = text.find("timestep=\"", at) + 10;
    const std::size_t f = text.find("file=\"", at) + 6;
    entries.emplace_back(std::stod(text.substr(t, text.find('"', t) - t)),
                         text.substr(f, text.find('"', f) - f));
  }
  return entries;
}

class OutputSeries : public ::testing::Test {
 protected:
  // One folder per test: ctest runs tests side by side.
  fs::path folder_ = fs::temp_directory_path() /
                     ("lituya_output_writer_" +
                      std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  void SetUp() override { fs::remove_all(folder_); }

  // Two stages of 0.01 s with outputs every 0.005 s.
  void run(const OutputSettings& settings) {
    Simulation<2> simulation = make_box_simulation<2>(sand_and_water());
    OutputWriter<2> writer(folder_, settings);
    auto on_output = [&](const Stage& s, double t, int index) {
      writer.write(simulation, s, t, index);
    };
    simulation.run_stage(stage("gravity", 0.01, 0.005), on_output);
    simulation.run_stage(stage("release", 0.01, 0.005), on_output);
  }
};

TEST_F(OutputSeries, TimeRunsOnAcrossStages) {
  run(OutputSettings{});
  // Each stage's own series keeps the stage clock (what [post] profile_times use).
  const auto release = pvd_entries(folder_ / "release_points.pvd");
  ASSERT_EQ(release.size(), 3u);
  EXPECT_DOUBLE_EQ(release[0].first, 0.0);
  EXPECT_DOUBLE_EQ(release[2].first, 0.01);
  // The run's series: the release starts at the gravity stage's end, 0.01 s, and its first
  // frame replaces the gravity stage's last one at that instant.
  for (const char* set : {"points", "liquid", "grid"}) {
    const auto run = pvd_entries(folder_ / (std::string(set) + ".pvd"));
    ASSERT_EQ(run.size(), 5u) << set;
    const double times[] = {0.0, 0.005, 0.01, 0.015, 0.02};
    for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(run[i].first, times[i], 1e-12) << set;
    EXPECT_EQ(run[2].second, "release_" + std::string(set) + "_0000.vtu");
    EXPECT_EQ(run[4].second, "release_" + std::string(set) + "_0002.vtu");
  }
  // Every file carries its run time as TimeValue, and its stage time.
  Vtu first(folder_ / "gravity_points_0001.vtu");
  EXPECT_NEAR(first.field("TimeValue"), 0.005, 1e-12);
  EXPECT_NEAR(first.field("stage_time"), 0.005, 1e-12);
  for (const char* file :
       {"release_points_0002.vtu", "release_liquid_0002.vtu", "release_grid_0002.vtu"}) {
    Vtu last(folder_ / file);
    EXPECT_NEAR(last.field("TimeValue"), 0.02, 1e-12) << file;
    EXPECT_NEAR(last.field("stage_time"), 0.01, 1e-12) << file;
  }
}

// A run resumed from a checkpoint (the writer's series restored) must write the same bytes as
// one never interrupted: the same run times in the files and in the run's series.
TEST_F(OutputSeries, ARestoredWriterGoesOnWithTheSameClock) {
  Simulation<2> simulation = make_box_simulation<2>(sand_and_water());
  OutputWriter<2> whole(folder_ / "whole", OutputSettings{});
  std::vector<SeriesRecord> checkpoint;
  auto on_output = [&](const Stage& s, double t, int index) {
    whole.write(simulation, s, t, index);
    if (s.name == "release" && index == 1) checkpoint = whole.series();
  };
  simulation.run_stage(stage("gravity", 0.01, 0.005), on_output);
  const Stage release = stage("release", 0.01, 0.005);
  simulation.run_stage(release, on_output);
  ASSERT_FALSE(checkpoint.empty());

  OutputWriter<2> resumed(folder_ / "resumed", OutputSettings{});
  resumed.restore_series(checkpoint);
  resumed.write(simulation, release, 0.01, 2);  // the state of the last frame, written again
  for (const char* file : {"release_points_0002.vtu", "release_grid_0002.vtu", "points.pvd",
                           "liquid.pvd", "grid.pvd", "release_points.pvd", "README.txt"})
    EXPECT_EQ(contents(folder_ / "resumed" / file), contents(folder_ / "whole" / file)) << file;
}

TEST_F(OutputSeries, WritesTheChosenFieldsOnly) {
  OutputSettings settings;
  settings.point_fields = {"stress", "material"};
  settings.liquid_fields = {"pressure"};
  settings.grid_fields = {"mass", "liquid_pressure"};
  settings.compress = false;
  run(settings);
  EXPECT_EQ(Vtu(folder_ / "release_points_0001.vtu").point_arrays(),
            (std::set<std::string>{"id", "stress", "material"}));
  EXPECT_EQ(Vtu(folder_ / "release_liquid_0001.vtu").point_arrays(),
            (std::set<std::string>{"id", "pressure"}));
  EXPECT_EQ(Vtu(folder_ / "release_grid_0001.vtu").point_arrays(),
            (std::set<std::string>{"mass", "liquid_pressure"}));
  EXPECT_EQ(contents(folder_ / "release_grid_0001.vtu").find("compressor="), std::string::npos);
  const std::string readme = contents(folder_ / "README.txt");
  EXPECT_NE(readme.find("Not written (left out of [output] point_fields): displacement, "
                        "velocity, plastic_strain, mass, volume, porosity"),
            std::string::npos)
      << readme;
  EXPECT_NE(readme.find("not compressed"), std::string::npos);
}

// README.txt names every array of every file written, with its unit; the stress and pressure
// lines say which sign is positive.
TEST_F(OutputSeries, ReadmeNamesEveryFieldWritten) {
  run(OutputSettings{});
  const std::string readme = contents(folder_ / "README.txt");
  for (const char* file :
       {"release_points_0001.vtu", "release_liquid_0001.vtu", "release_grid_0001.vtu"}) {
    Vtu vtu(folder_ / file);
    const std::string prefix = std::string(file).substr(8, 6);  // points, liquid, grid_0
    const std::set<std::string> arrays = vtu.point_arrays();
    EXPECT_GE(arrays.size(), 6u) << file;
    for (const std::string& name : arrays)
      EXPECT_NE(readme.find("\n  " + name + " "), std::string::npos) << name << " of " << prefix;
  }
  for (const char* text :
       {"TimeValue", "stage_time", "TENSION POSITIVE", "COMPRESSION POSITIVE",
        "xx, yy, zz, xy, yz, xz", "points.pvd, liquid.pvd, grid.pvd", "kg/m", "zlib-compressed"})
    EXPECT_NE(readme.find(text), std::string::npos) << text << "\n" << readme;
  EXPECT_EQ(readme.find("Not written"), std::string::npos);
}

// Every field a scene can select has a line in the README (a field added to the lists without
// a description fails here).
TEST(OutputReadme, DescribesEveryKnownField) {
  const std::string readme = output_readme(OutputSettings{}, 3, true);
  const std::size_t solid = readme.find("\nSolid points");
  const std::size_t liquid = readme.find("\nLiquid points");
  const std::size_t grid = readme.find("\nBackground grid");
  ASSERT_LT(solid, liquid);
  ASSERT_LT(liquid, grid);
  const std::pair<std::string, const std::vector<std::string>*> sections[] = {
      {readme.substr(solid, liquid - solid), &kSolidPointFields},
      {readme.substr(liquid, grid - liquid), &kLiquidPointFields},
      {readme.substr(grid), &kGridFields}};
  for (const auto& [section, fields] : sections)
    for (const std::string& f : *fields)
      EXPECT_NE(section.find("\n  " + f + " "), std::string::npos) << f << " in\n" << section;
  EXPECT_NE(readme.find("m^3"), std::string::npos);  // 3D units
  // A dry case without a grid lists neither liquid nor grid files.
  OutputSettings no_grid;
  no_grid.grid = false;
  const std::string dry = output_readme(no_grid, 2, false);
  EXPECT_EQ(dry.find("liquid"), std::string::npos) << dry;
  EXPECT_EQ(dry.find("grid.pvd"), std::string::npos) << dry;
}

std::string output_error(const std::string& body) {
  const fs::path path = fs::temp_directory_path() / "lituya_output_settings_test.toml";
  std::ofstream(path) << "[output]\n" << body;
  lituya::TomlDocument doc(path);
  try {
    read_output_settings(doc.root().table("output"));
  } catch (const lituya::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputSettingsReader, RefusesUnknownFieldsWithLineAndKnownFields) {
  std::string msg = output_error("grid = true\nliquid_fields = [\"velocity\", \"presure\"]\n");
  EXPECT_NE(msg.find("lituya_output_settings_test.toml:3"), std::string::npos) << msg;
  EXPECT_NE(
      msg.find("unknown liquid point field \"presure\" in 'liquid_fields' (known: "
               "velocity, pressure, porosity, mass, volume, material, in_flight; the point 'id' "
               "is "
               "always written)"),
      std::string::npos)
      << msg;
  msg = output_error("grid_fields = [\"stress\"]\n");
  EXPECT_NE(msg.find(":2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown grid field \"stress\" in 'grid_fields' (known: mass, velocity, "
                     "liquid_mass, liquid_velocity, porosity, liquid_pressure)"),
            std::string::npos)
      << msg;
  msg = output_error("point_fields = [\"id\"]\n");
  EXPECT_NE(msg.find("unknown solid point field \"id\""), std::string::npos) << msg;
  msg = output_error("point_fields = [\"mass\", \"mass\"]\n");
  EXPECT_NE(msg.find("'point_fields' lists \"mass\" twice"), std::string::npos) << msg;
  msg = output_error("compression = \"gzip\"\n");
  EXPECT_NE(msg.find(":2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("zlib"), std::string::npos) << msg;
}

TEST(OutputSettingsReader, DefaultsWriteEverythingCompressedAndRoundTrip) {
  const fs::path path = fs::temp_directory_path() / "lituya_output_settings_round_trip.toml";
  { std::ofstream(path) << "[output]\nliquid_fields = [\"pressure\"]\ncompression = \"none\"\n"; }
  lituya::TomlDocument doc(path);
  const OutputSettings read = read_output_settings(doc.root().table("output"));
  EXPECT_EQ(read.point_fields, kSolidPointFields);
  EXPECT_EQ(read.grid_fields, kGridFields);
  EXPECT_EQ(read.liquid_fields, std::vector<std::string>{"pressure"});
  EXPECT_FALSE(read.compress);
  // stages.toml gets what the scene said, and the solver reads the same settings back.
  const fs::path again = fs::temp_directory_path() / "lituya_output_settings_written.toml";
  { std::ofstream(again) << toml::table{{"output", to_toml(read)}}; }
  lituya::TomlDocument written(again);
  const OutputSettings back = read_output_settings(written.root().table("output"));
  EXPECT_EQ(back.liquid_fields, read.liquid_fields);
  EXPECT_EQ(back.point_fields, read.point_fields);
  EXPECT_FALSE(back.compress);
  EXPECT_TRUE(OutputSettings{}.compress);
}

}  // namespace
