#pragma once
// Synthetic solver output for the postprocessor tests: blocks of points laid out in the slope
// frame (where their front and height are known exactly), water columns under a known
// surface, written with the same writers the solver uses.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lituya/common/input_error.hpp"
#include "lituya/common/vtu_writer.hpp"
#include "lituya/post/postprocess.hpp"

namespace lituya::post::synthetic {

// A rectangle s in [s0, s1], t in [t0, t1] of the slope frame filled with points at the
// centres of squares of side h (cubes in 3D, `layers` of them across the flume width).
inline void add_block(PointCloud& cloud, const SlopeFrame& frame, double s0, double s1, double t0,
                      double t1, double h, int material, int layers = 0) {
  const int ns = static_cast<int>(std::lround((s1 - s0) / h));
  const int nt = static_cast<int>(std::lround((t1 - t0) / h));
  const int nz = layers > 0 ? layers : 1;
  for (int i = 0; i < ns; ++i)
    for (int j = 0; j < nt; ++j)
      for (int k = 0; k < nz; ++k) {
        const double z = layers > 0 ? (k + 0.5) * h : 0.0;
        cloud.position.push_back(frame.point(s0 + (i + 0.5) * h, t0 + (j + 0.5) * h, z));
        cloud.material.push_back(material);
        cloud.volume.push_back(layers > 0 ? h * h * h : h * h);
        cloud.id.push_back(static_cast<int>(cloud.id.size()));
      }
}

inline void write_cloud(const PointCloud& cloud, const std::filesystem::path& file) {
  std::vector<double> xyz;
  for (const auto& p : cloud.position) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  lituya::VtuWriter writer;
  writer.set_points(xyz);
  writer.set_vertex_cells();
  if (!cloud.material.empty()) {
    std::vector<std::int32_t> material(cloud.material.begin(), cloud.material.end());
    writer.add_point_data("material", material);
  }
  if (!cloud.volume.empty()) writer.add_point_data("volume", 1, cloud.volume);
  if (!cloud.mass.empty()) writer.add_point_data("mass", 1, cloud.mass);
  if (!cloud.id.empty()) {
    std::vector<std::int32_t> id(cloud.id.begin(), cloud.id.end());
    writer.add_point_data("id", id);
  }
  writer.write(file);
}

// Water in columns of side-h squares (cubes in 3D, `layers` of them across the flume width)
// whose centres are at x0 + (i + 1/2) h, for x up to x1. Each column is filled from its top
// down to `bottom`: the top point's centre is h/2 below surface(x) of the column centre, so
// the column's true surface, top point plus half a spacing, is surface(x) exactly.
template <typename Surface>
inline void add_water(PointCloud& cloud, double x0, double x1, double bottom, double h,
                      Surface surface, int layers = 0, int material = 0) {
  const int nx = static_cast<int>(std::lround((x1 - x0) / h));
  const int nz = layers > 0 ? layers : 1;
  if (layers > 0) cloud.dimension = 3;
  for (int i = 0; i < nx; ++i) {
    const double x = x0 + (i + 0.5) * h;
    for (double y = surface(x) - 0.5 * h; y - 0.5 * h >= bottom - 1e-12; y -= h)
      for (int k = 0; k < nz; ++k) {
        const double z = layers > 0 ? (k + 0.5) * h : 0.0;
        cloud.position.emplace_back(x, y, z);
        cloud.material.push_back(material);
        cloud.volume.push_back(layers > 0 ? h * h * h : h * h);
        cloud.id.push_back(static_cast<int>(cloud.id.size()));
      }
  }
}

// Liquid points with every array the solver writes into <stage>_liquid_NNNN.vtu.
inline void write_liquid_cloud(const PointCloud& cloud, const std::filesystem::path& file) {
  const size_t n = cloud.position.size();
  std::vector<double> xyz, velocity(3 * n, 0.0), pressure, mass;
  // Free water unless the cloud says otherwise.
  const std::vector<double> porosity =
      cloud.porosity.empty() ? std::vector<double>(n, 1.0) : cloud.porosity;
  for (size_t i = 0; i < n; ++i) {
    const auto& p = cloud.position[i];
    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    velocity[3 * i] = 0.1 * p.y();  // anything: the surface must not depend on it
    pressure.push_back(1000.0 * 9.81 * std::max(0.0, 0.15 - p.y()));
    mass.push_back(1000.0 * cloud.volume[i]);
  }
  lituya::VtuWriter writer;
  writer.set_points(xyz);
  writer.set_vertex_cells();
  writer.add_point_data("velocity", 3, velocity);
  writer.add_point_data("pressure", 1, pressure);
  writer.add_point_data("porosity", 1, porosity);
  writer.add_point_data("mass", 1, mass);
  writer.add_point_data("volume", 1, cloud.volume);
  std::vector<std::int32_t> material(cloud.material.begin(), cloud.material.end());
  writer.add_point_data("material", material);
  std::vector<std::int32_t> id(cloud.id.begin(), cloud.id.end());
  writer.add_point_data("id", id);
  writer.write(file);
}

inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Rows of a CSV file after its header line, as numbers (a blank field becomes NaN).
inline std::vector<std::vector<double>> read_csv_rows(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    size_t start = 0;
    while (true) {
      size_t comma = line.find(',', start);
      std::string field = line.substr(start, comma - start);
      row.push_back(field.empty() ? NAN : std::stod(field));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    rows.push_back(row);
  }
  return rows;
}

// A fresh folder per test, removed afterwards.
class TempFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = std::filesystem::temp_directory_path() /
              ("lituya_post_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
               std::to_string(::getpid()));
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }
  std::filesystem::path folder_;
};

// A case folder inside the temporary folder, and the check that a wrong post.toml stops
// `lituya post` with an error at the given line that mentions `mention`, writing nothing.
class CaseFolderTest : public TempFolderTest {
 protected:
  void SetUp() override {
    TempFolderTest::SetUp();
    case_ = folder_ / "case";
  }

  void expect_input_error(const std::string& post_toml, int line, const std::string& mention) {
    write_text(case_ / "post.toml", post_toml);
    try {
      postprocess(case_, case_ / "post", false);
      ADD_FAILURE() << "no InputError; expected one at line " << line;
    } catch (const InputError& e) {
      EXPECT_EQ(std::filesystem::path(e.file()).filename(), "post.toml") << e.what();
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
    }
    // Nothing is written when the input is wrong.
    EXPECT_FALSE(std::filesystem::exists(case_ / "post"));
  }

  std::filesystem::path case_;
};

}  // namespace lituya::post::synthetic
