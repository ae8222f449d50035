#pragma once
// Minimal writer of VTK XML unstructured grids (.vtu) with appended raw binary data, and of
// .pvd collections, so that ParaView opens every geometry and output file Lituya writes.
// Files are written to a temporary name and renamed (write_file_atomically), so a crash or a
// full disk never leaves a torn file and the last good output of a run stays readable; a failed
// write throws WriteError naming the file and the system's reason.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace lituya {

// VTK cell type codes used by Lituya.
enum class VtkCellType : std::uint8_t { kVertex = 1, kLine = 3, kTriangle = 5, kTetra = 10 };

class VtuWriter {
 public:
  // xyz: 3 coordinates per point (z = 0 in 2D).
  void set_points(std::span<const double> xyz);
  // One vertex cell per point (for point clouds).
  void set_vertex_cells();
  // connectivity: node indices of all cells; offsets: end of each cell in connectivity.
  void set_cells(std::vector<std::int64_t> connectivity, std::vector<std::int64_t> offsets,
                 std::vector<std::uint8_t> types);
  void add_point_data(const std::string& name, int components, std::span<const double> values);
  void add_point_data(const std::string& name, std::span<const std::int32_t> values);
  void add_cell_data(const std::string& name, int components, std::span<const double> values);
  void add_cell_data(const std::string& name, std::span<const std::int32_t> values);
  // Writes atomically (temporary file + rename).
  void write(const std::filesystem::path& file) const;

  std::size_t point_count() const { return points_.size() / 3; }
  std::size_t cell_count() const { return types_.size(); }

 private:
  struct Array {
    std::string name;
    int components;
    bool is_int;
    std::vector<double> real;
    std::vector<std::int32_t> integer;
  };
  std::vector<double> points_;
  std::vector<std::int64_t> connectivity_, offsets_;
  std::vector<std::uint8_t> types_;
  std::vector<Array> point_data_, cell_data_;
};

// A .pvd collection: the list of (time, file) of one output series. Rewritten (atomically)
// after every entry so ParaView can play the series while the run goes on or after it stops.
class PvdWriter {
 public:
  explicit PvdWriter(std::filesystem::path file) : file_(std::move(file)) {}
  // `dataset` is relative to the .pvd's folder.
  void add(double time, const std::string& dataset);
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace lituya
