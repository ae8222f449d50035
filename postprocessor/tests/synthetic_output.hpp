#pragma once
// Synthetic solver output for the postprocessor tests: blocks of points laid out in the slope
// frame (where their front and height are known exactly) and written with the same writers
// the solver uses.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

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
  if (!cloud.id.empty()) {
    std::vector<std::int32_t> id(cloud.id.begin(), cloud.id.end());
    writer.add_point_data("id", id);
  }
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

}  // namespace lituya::post::synthetic
