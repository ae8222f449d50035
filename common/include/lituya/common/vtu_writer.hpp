#pragma once
// Minimal writer of VTK XML unstructured grids (.vtu) with appended raw binary data, and of
// .pvd collections, so that ParaView opens every geometry and output file Lituya writes.
// The appended arrays are zlib-compressed by default (VTK's "vtkZLibDataCompressor" layout,
// which every VTK reader and ParaView decode): the solver's output series shrinks to less than
// half, and the grid, whose coordinates and cells repeat in every file, to about a quarter.
// Files are written to a temporary name and renamed (write_file_atomically), so a crash or a
// full disk never leaves a torn file and the last good output of a run stays readable; a failed
// write throws WriteError naming the file and the system's reason.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace lituya {

// VTK cell type codes used by Lituya.
enum class VtkCellType : std::uint8_t { kVertex = 1, kLine = 3, kTriangle = 5, kTetra = 10 };

// How the appended arrays are stored. kNone keeps the plain layout (one UInt64 byte count,
// then the bytes), for tools that parse VTU files themselves and know no zlib.
enum class VtuCompression { kNone, kZlib };

// Compressed arrays are cut into blocks of this many uncompressed bytes, each compressed on
// its own: VTK's default block size, so a reader can inflate one block at a time.
inline constexpr std::size_t kVtuCompressedBlockBytes = 1 << 15;

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
  // A data-set-wide array (FieldData), for example "TimeValue", the time ParaView shows when
  // the files are opened as a file series without their .pvd.
  void add_field_data(const std::string& name, std::span<const double> values);
  void set_compression(VtuCompression compression) { compression_ = compression; }
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
  std::vector<Array> point_data_, cell_data_, field_data_;
  VtuCompression compression_ = VtuCompression::kZlib;
};

// A .pvd collection: the list of (time, file) of one output series. Rewritten (atomically)
// after every entry so ParaView can play the series while the run goes on or after it stops.
class PvdWriter {
 public:
  using Entry = std::pair<double, std::string>;  // (time, dataset)
  explicit PvdWriter(std::filesystem::path file) : file_(std::move(file)) {}
  // A series that goes on from `entries` (a run resumed from a checkpoint): the next add()
  // rewrites the file with them and the new entry.
  PvdWriter(std::filesystem::path file, std::vector<Entry> entries)
      : file_(std::move(file)), entries_(std::move(entries)) {}
  // `dataset` is relative to the .pvd's folder.
  void add(double time, const std::string& dataset);
  // As add, but an entry at the same time as the last one replaces it: a series that runs on
  // across stages holds one frame per time (the next stage's first frame, not the previous
  // stage's last one at the same instant, which ParaView could not tell apart).
  void add_or_replace_last(double time, const std::string& dataset);
  const std::filesystem::path& file() const { return file_; }
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  // Rewrites the file; on failure restores the last entry (`replaced`) or drops it (none).
  void write_or_undo(const std::optional<Entry>& replaced);

  std::filesystem::path file_;
  std::vector<Entry> entries_;
};

}  // namespace lituya
