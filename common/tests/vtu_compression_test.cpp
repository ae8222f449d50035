// The compressed VTU layout is checked twice: by a small parser written here from the format's
// description (header words, then zlib blocks), which must give back every array bit for bit,
// and by VTK's own reader (what ParaView uses), which must give the same values.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "lituya/common/vtu_writer.hpp"

namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string attribute(const std::string& tag, const std::string& name) {
  const std::size_t at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return "";
  const std::size_t begin = at + name.size() + 3;
  return tag.substr(begin, tag.find('"', begin) - begin);
}

std::uint64_t word(const std::string& data, std::size_t at) {
  std::uint64_t w;
  std::memcpy(&w, data.data() + at, sizeof w);
  return w;
}

// The uncompressed bytes of every appended array of `file`, by name ("" for the points).
// Fails the test on any departure from the layout.
std::map<std::string, std::string> appended_arrays(const fs::path& file, bool compressed) {
  const std::string text = contents(file);
  const std::size_t underscore = text.find('_', text.find("<AppendedData"));
  EXPECT_NE(underscore, std::string::npos);
  const std::string appended = text.substr(underscore + 1);
  std::map<std::string, std::string> arrays;
  for (std::size_t at = text.find("<DataArray"); at < underscore;
       at = text.find("<DataArray", at + 1)) {
    const std::string tag = text.substr(at, text.find('>', at) - at);
    std::size_t p = std::stoull(attribute(tag, "offset"));
    std::string bytes;
    if (!compressed) {
      const std::uint64_t n = word(appended, p);
      bytes = appended.substr(p + 8, n);
    } else {
      const std::uint64_t blocks = word(appended, p);
      const std::uint64_t block_size = word(appended, p + 8);
      const std::uint64_t last_size = word(appended, p + 16);
      EXPECT_EQ(block_size, lituya::kVtuCompressedBlockBytes);
      std::size_t data = p + 24 + 8 * blocks;
      for (std::uint64_t b = 0; b < blocks; ++b) {
        const std::uint64_t compressed_size = word(appended, p + 24 + 8 * b);
        uLongf size = (b + 1 == blocks && last_size != 0) ? last_size : block_size;
        const uLongf expected = size;
        std::string block(size, '\0');
        EXPECT_EQ(
            uncompress(reinterpret_cast<Bytef*>(block.data()), &size,
                       reinterpret_cast<const Bytef*>(appended.data() + data), compressed_size),
            Z_OK);
        EXPECT_EQ(size, expected);
        bytes += block;
        data += compressed_size;
      }
    }
    arrays[attribute(tag, "Name")] = bytes;
  }
  return arrays;
}

template <class T>
std::string bytes_of(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

fs::path test_file(const std::string& name) {
  return fs::temp_directory_path() / ("lituya_vtu_compression_" + name + ".vtu");
}

// A point cloud whose arrays span no block, part of one, exactly two and several: every case
// of the last-block word (0 when the last block is full).
struct Cloud {
  std::vector<double> xyz, smooth, exact_blocks, noisy;
  std::vector<std::int32_t> id;
  std::vector<double> time = {1.25};

  explicit Cloud(std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      xyz.insert(xyz.end(), {0.001 * i, std::sin(0.01 * i), 0.0});
      smooth.push_back(1000.0 * i);
      noisy.push_back(std::sin(1e3 * i) * 1e5 + 1.0 / (i + 3.0));
      id.push_back(static_cast<std::int32_t>(n - i));
    }
    // 2 blocks of doubles exactly: the last-block word must be 0.
    exact_blocks.resize(2 * lituya::kVtuCompressedBlockBytes / sizeof(double));
    for (std::size_t i = 0; i < exact_blocks.size(); ++i) exact_blocks[i] = 0.5 * i;
  }

  lituya::VtuWriter writer(lituya::VtuCompression compression) const {
    lituya::VtuWriter w;
    w.set_compression(compression);
    w.set_points(xyz);
    w.set_vertex_cells();
    w.add_point_data("id", id);
    w.add_point_data("smooth", 1, smooth);
    w.add_point_data("noisy", 1, noisy);
    w.add_field_data("TimeValue", time);
    return w;
  }
};

TEST(VtuCompression, ArraysDecompressBitForBit) {
  const Cloud cloud(10000);  // 80 000 bytes per scalar array: 2 full blocks and a partial one
  const fs::path file = test_file("bits");
  cloud.writer(lituya::VtuCompression::kZlib).write(file);
  const std::string text = contents(file);
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);

  auto arrays = appended_arrays(file, true);
  EXPECT_EQ(arrays["id"], bytes_of(cloud.id));
  EXPECT_EQ(arrays["smooth"], bytes_of(cloud.smooth));
  EXPECT_EQ(arrays["noisy"], bytes_of(cloud.noisy));
  EXPECT_EQ(arrays["TimeValue"], bytes_of(cloud.time));
  EXPECT_EQ(arrays[""], bytes_of(cloud.xyz));
  std::vector<std::int64_t> offsets(10000);
  for (std::size_t i = 0; i < offsets.size(); ++i) offsets[i] = static_cast<std::int64_t>(i + 1);
  EXPECT_EQ(arrays["offsets"], bytes_of(offsets));
  EXPECT_EQ(arrays["types"], std::string(10000, '\1'));
}

TEST(VtuCompression, ArrayOfWholeBlocksAndEmptyArrays) {
  Cloud cloud(0);
  lituya::VtuWriter w;
  const std::size_t n = cloud.exact_blocks.size();
  std::vector<double> xyz(3 * n, 0.0);
  w.set_points(xyz);
  w.set_vertex_cells();
  w.add_point_data("exact", 1, cloud.exact_blocks);
  const fs::path file = test_file("whole_blocks");
  w.write(file);
  auto arrays = appended_arrays(file, true);
  EXPECT_EQ(arrays["exact"], bytes_of(cloud.exact_blocks));

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkDataArray* exact = reader->GetOutput()->GetPointData()->GetArray("exact");
  ASSERT_NE(exact, nullptr);
  ASSERT_EQ(exact->GetNumberOfTuples(), static_cast<vtkIdType>(n));
  EXPECT_EQ(exact->GetTuple1(static_cast<vtkIdType>(n - 1)), cloud.exact_blocks.back());

  // No points at all (a stage whose water has all left the mesh): still a readable file.
  const Cloud none(0);
  const fs::path empty = test_file("empty");
  none.writer(lituya::VtuCompression::kZlib).write(empty);
  vtkNew<vtkXMLUnstructuredGridReader> empty_reader;
  empty_reader->SetFileName(empty.c_str());
  empty_reader->Update();
  EXPECT_EQ(empty_reader->GetErrorCode(), 0);
  EXPECT_EQ(empty_reader->GetOutput()->GetNumberOfPoints(), 0);
}

// What ParaView sees: VTK's reader decodes the compressed file to the same values, and the
// field data TimeValue is there.
TEST(VtuCompression, VtkReadsTheSameValues) {
  const Cloud cloud(5000);
  for (auto compression : {lituya::VtuCompression::kZlib, lituya::VtuCompression::kNone}) {
    const bool zlib = compression == lituya::VtuCompression::kZlib;
    const fs::path file = test_file(zlib ? "vtk_zlib" : "vtk_none");
    cloud.writer(compression).write(file);
    EXPECT_EQ(contents(file).find("compressor=") != std::string::npos, zlib);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    ASSERT_EQ(reader->GetErrorCode(), 0);
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_EQ(grid->GetNumberOfPoints(), 5000);
    ASSERT_EQ(grid->GetNumberOfCells(), 5000);
    vtkDataArray* noisy = grid->GetPointData()->GetArray("noisy");
    vtkDataArray* id = grid->GetPointData()->GetArray("id");
    ASSERT_NE(noisy, nullptr);
    ASSERT_NE(id, nullptr);
    for (vtkIdType i = 0; i < 5000; ++i) {
      double p[3];
      grid->GetPoint(i, p);
      ASSERT_EQ(p[1], cloud.xyz[3 * i + 1]) << i;
      ASSERT_EQ(noisy->GetTuple1(i), cloud.noisy[i]) << i;
      ASSERT_EQ(id->GetTuple1(i), cloud.id[i]) << i;
    }
    vtkDataArray* time = grid->GetFieldData()->GetArray("TimeValue");
    ASSERT_NE(time, nullptr);
    EXPECT_EQ(time->GetNumberOfTuples(), 1);
    EXPECT_EQ(time->GetTuple1(0), 1.25);
  }
}

// The point of compressing: smooth data (a grid's coordinates and cells, vertex cells) shrinks
// a lot, noise barely; the file as a whole must be well under the uncompressed one.
TEST(VtuCompression, SmoothDataShrinks) {
  const Cloud cloud(20000);
  const fs::path zlib = test_file("size_zlib");
  const fs::path none = test_file("size_none");
  cloud.writer(lituya::VtuCompression::kZlib).write(zlib);
  cloud.writer(lituya::VtuCompression::kNone).write(none);
  EXPECT_LT(fs::file_size(zlib), fs::file_size(none) / 2);
}

TEST(PvdWriter, AnEntryAtTheLastTimeReplacesIt) {
  const fs::path file = fs::temp_directory_path() / "lituya_pvd_replace_test.pvd";
  lituya::PvdWriter pvd(file);
  pvd.add_or_replace_last(0.0, "gravity_0000.vtu");
  pvd.add_or_replace_last(0.2, "gravity_0001.vtu");
  pvd.add_or_replace_last(0.2, "release_0000.vtu");  // the next stage starts at 0.2
  pvd.add_or_replace_last(0.3, "release_0001.vtu");
  ASSERT_EQ(pvd.entries().size(), 3u);
  EXPECT_EQ(pvd.entries()[1].second, "release_0000.vtu");
  const std::string text = contents(file);
  EXPECT_EQ(text.find("gravity_0001.vtu"), std::string::npos);
  EXPECT_NE(text.find("timestep=\"0.2\" part=\"0\" file=\"release_0000.vtu\""), std::string::npos);
}

}  // namespace
