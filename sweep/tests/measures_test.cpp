#include "lituya/sweep/measures.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lituya/common/error_message.hpp"
#include "lituya/common/input_error.hpp"

namespace {

namespace fs = std::filesystem;
using namespace lituya::sweep;

using lituya::input_error_message;

fs::path post_folder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / ("lituya_sweep_measures_" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

PostContent post_of(const std::string& post_table) {
  return post_content(toml::parse("[post]\n" + post_table));
}

TEST(Measures, ReadFromThePostTables) {
  const fs::path post = post_folder("tables");
  std::ofstream(post / "gauges.csv") << "time,G1,G2\n"
                                        "0,,0\n"
                                        "0.1,0.002,0.010\n"
                                        "0.2,0.012,0.030\n"
                                        "0.3,-0.001,0.020\n"
                                        "0.4,0.009,0.025\n"
                                        "0.5,0.015,0.024\n"
                                        "0.6,0.011,0.021\n"
                                        "0.7,0.010,0.022\n"
                                        "0.8,0.010,0.023\n";
  std::ofstream(post / "runout.csv")
      << "time,front_position,front_travel,mass_front_position,mass_front_travel\n"
         "0,0.2,0,0.19,0\n0.5,0.4,0.2,0.36,0.17\n1.0,0.45,0.25,0.4,0.21\n";
  std::ofstream(post / "leading_wave.csv") << "time,crest_x,crest_height,max_eta\n0,,,0.001\n"
                                              "0.5,1.2,0.031,0.04\n1.0,1.8,0.027,0.03\n";
  const PostContent content = post_of(
      "gauges = [1.0, 2.0]\ngauge_names = ['G1', 'G2']\ntrack_materials = ['beads']\n"
      "leading_wave = true\n");
  const std::vector<Measure> measures =
      parse_measures({"gauge_first_crest", "gauge_max:G2", "leading_wave_max", "front_travel_final",
                      "front_travel_max"},
                     content, "scene.toml");
  ASSERT_EQ(measures.size(), 6u);
  EXPECT_EQ(measures[0].name, "gauge_first_crest:G1");
  EXPECT_EQ(measures[1].name, "gauge_first_crest:G2");
  // G1's first wave ends at 0.3 s (below still water): its crest is 0.012, not the later 0.015.
  // G2 never falls below still water: its first wave is the whole record.
  EXPECT_DOUBLE_EQ(take_measure(measures[0], post), 0.012);
  EXPECT_DOUBLE_EQ(take_measure(measures[1], post), 0.030);
  EXPECT_DOUBLE_EQ(take_measure(measures[2], post), 0.030);
  EXPECT_DOUBLE_EQ(take_measure(measures[3], post), 0.031);
  EXPECT_DOUBLE_EQ(take_measure(measures[4], post), 0.25);
  EXPECT_DOUBLE_EQ(take_measure(measures[5], post), 0.25);
  // The mass front's travel is its own column, not the bin front's.
  const auto mass_front = parse_measures({"mass_front_travel_final"}, content, "scene.toml");
  ASSERT_EQ(mass_front.size(), 1u);
  EXPECT_DOUBLE_EQ(take_measure(mass_front[0], post), 0.21);

  // The area of G1's first wave: the trapezoid 0.1-0.2 s and the triangle out to its fall
  // through still water between 0.2 s (0.012) and 0.3 s (-0.001); the blank first row is no
  // water, not a crossing.
  const auto area = parse_measures({"gauge_first_wave_area:G1"}, content, "scene.toml");
  ASSERT_EQ(area.size(), 1u);
  EXPECT_NEAR(take_measure(area[0], post),
              0.5 * (0.002 + 0.012) * 0.1 + 0.5 * 0.012 * 0.1 * 0.012 / 0.013, 1e-15);
  EXPECT_EQ(measure_unit(area[0].name), "m s");
  EXPECT_EQ(measure_unit(measures[0].name), "m");

  // A table that was not written names its file.
  const auto wall = parse_measures({"wall_height_final"}, content, "scene.toml");
  EXPECT_NE(input_error_message([&] { take_measure(wall[0], post); }).find("wall_height.csv"),
            std::string::npos);
}

TEST(Measures, AreCheckedAgainstTheScenePostTable) {
  const PostContent gauges = post_of("gauges = [0.45, 0.75]\n");
  EXPECT_EQ(gauges.gauge_names, (std::vector<std::string>{"x=0.45", "x=0.75"}));
  EXPECT_EQ(default_measures(gauges).size(), 2u);
  EXPECT_EQ(default_measures(gauges)[1].name, "gauge_first_crest:x=0.75");
  EXPECT_EQ(default_measures(post_of("track_materials = ['a']\n"))[0].name, "front_travel_final");
  EXPECT_TRUE(default_measures(PostContent{}).empty());

  const std::string no_gauge =
      input_error_message([&] { parse_measures({"gauge_max:G9"}, gauges, "scene.toml"); });
  EXPECT_NE(no_gauge.find("scene.toml:1:"), std::string::npos) << no_gauge;
  EXPECT_NE(no_gauge.find("\"x=0.45\", \"x=0.75\""), std::string::npos) << no_gauge;
  EXPECT_NE(input_error_message([&] {
              parse_measures({"front_travel_final"}, gauges, "scene.toml");
            }).find("track_materials"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] {
              parse_measures({"gauge_max"}, PostContent{}, "scene.toml");
            }).find("no [post] table"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] {
              parse_measures({"runout"}, gauges, "scene.toml");
            }).find("--measure: unknown measure 'runout'"),
            std::string::npos);
}

// The kinetic energies come from the solver's history of the stage post reads ([post] stage,
// else the last [[stage]]), which every solve writes: no [post] key is needed, not even a table.
TEST(Measures, KineticEnergyFromTheStageHistory) {
  const fs::path post = post_folder("history") / "post";
  fs::create_directories(post.parent_path() / "output");
  std::ofstream(post.parent_path() / "output" / "release_history.csv")
      << "time,stage,stage_time,step,time_step,kinetic_energy_solid,kinetic_energy_liquid,"
         "kinetic_energy,max_speed_solid,max_speed_liquid\n"
         "0.2,release,0.0,10,1e-5,0.5,0.0,0.5,0.1,0.0\n"
         "0.3,release,0.1,20,1e-5,2.5,0.25,2.75,0.9,0.3\n"
         "0.4,release,0.2,30,1e-5,1.5,0.75,2.25,0.6,0.5\n";
  const PostContent without_post =
      post_content(toml::parse("[[stage]]\nname = 'gravity'\n[[stage]]\nname = 'release'\n"));
  EXPECT_FALSE(without_post.present);
  EXPECT_EQ(without_post.stage, "release");
  const std::vector<Measure> measures = parse_measures(
      {"kinetic_energy_solid_max", "kinetic_energy_liquid_max"}, without_post, "scene.toml");
  ASSERT_EQ(measures.size(), 2u);
  EXPECT_DOUBLE_EQ(take_measure(measures[0], post), 2.5);  // the folder post/ need not exist
  EXPECT_DOUBLE_EQ(take_measure(measures[1], post), 0.75);
  EXPECT_EQ(measure_unit(measures[0].name), "J, per m in 2D");

  // The fastest point of each phase: the largest max_speed_* over the rows (the solid's 0.9 m/s
  // at 0.3 s, not its last row's 0.6).
  const std::vector<Measure> speeds =
      parse_measures({"speed_solid_max", "speed_liquid_max"}, without_post, "scene.toml");
  EXPECT_DOUBLE_EQ(take_measure(speeds[0], post), 0.9);
  EXPECT_DOUBLE_EQ(take_measure(speeds[1], post), 0.5);
  EXPECT_EQ(measure_unit(speeds[0].name), "m/s");

  // [post] stage wins over the last stage; a missing history names the file.
  const PostContent gravity = post_content(toml::parse(
      "[[stage]]\nname = 'gravity'\n[[stage]]\nname = 'release'\n[post]\nstage = 'gravity'\n"));
  const Measure from_gravity =
      parse_measures({"kinetic_energy_solid_max"}, gravity, "scene.toml").front();
  EXPECT_NE(
      input_error_message([&] { take_measure(from_gravity, post); }).find("gravity_history.csv"),
      std::string::npos);
}

}  // namespace
