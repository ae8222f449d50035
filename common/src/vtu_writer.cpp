#include "lituya/common/vtu_writer.hpp"

#include <iomanip>
#include <sstream>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/xml_escape.hpp"

namespace lituya {

namespace {
// Appended raw data blocks are preceded by their byte count (header_type="UInt64").
struct Block {
  const void* data;
  std::uint64_t bytes;
};

void write_vtu(const std::filesystem::path& file, const std::string& head,
               const std::vector<Block>& blocks, const std::string& tail) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << head;
    for (const Block& b : blocks) {
      out.write(reinterpret_cast<const char*>(&b.bytes), sizeof(b.bytes));
      out.write(static_cast<const char*>(b.data), static_cast<std::streamsize>(b.bytes));
    }
    out << tail;
  });
}
}  // namespace

void VtuWriter::set_points(std::span<const double> xyz) {
  points_.assign(xyz.begin(), xyz.end());
}

void VtuWriter::set_vertex_cells() {
  const std::size_t n = point_count();
  connectivity_.resize(n);
  offsets_.resize(n);
  types_.assign(n, static_cast<std::uint8_t>(VtkCellType::kVertex));
  for (std::size_t i = 0; i < n; ++i) {
    connectivity_[i] = static_cast<std::int64_t>(i);
    offsets_[i] = static_cast<std::int64_t>(i + 1);
  }
}

void VtuWriter::set_cells(std::vector<std::int64_t> connectivity, std::vector<std::int64_t> offsets,
                          std::vector<std::uint8_t> types) {
  connectivity_ = std::move(connectivity);
  offsets_ = std::move(offsets);
  types_ = std::move(types);
}

void VtuWriter::add_point_data(const std::string& name, int components,
                               std::span<const double> values) {
  point_data_.push_back({name, components, false, {values.begin(), values.end()}, {}});
}
void VtuWriter::add_point_data(const std::string& name, std::span<const std::int32_t> values) {
  point_data_.push_back({name, 1, true, {}, {values.begin(), values.end()}});
}
void VtuWriter::add_cell_data(const std::string& name, int components,
                              std::span<const double> values) {
  cell_data_.push_back({name, components, false, {values.begin(), values.end()}, {}});
}
void VtuWriter::add_cell_data(const std::string& name, std::span<const std::int32_t> values) {
  cell_data_.push_back({name, 1, true, {}, {values.begin(), values.end()}});
}

void VtuWriter::write(const std::filesystem::path& file) const {
  std::ostringstream head;
  std::vector<Block> blocks;
  std::uint64_t offset = 0;
  auto declare = [&](const std::string& type, const std::string& name, int comps, const void* data,
                     std::uint64_t bytes) {
    head << "        <DataArray type=\"" << type << "\"";
    if (!name.empty()) head << " Name=\"" << xml_escaped(name) << "\"";
    head << " NumberOfComponents=\"" << comps << "\" format=\"appended\" offset=\"" << offset
         << "\"/>\n";
    blocks.push_back({data, bytes});
    offset += sizeof(std::uint64_t) + bytes;
  };
  auto declare_arrays = [&](const std::vector<Array>& arrays) {
    for (const Array& a : arrays) {
      if (a.is_int)
        declare("Int32", a.name, 1, a.integer.data(), a.integer.size() * sizeof(std::int32_t));
      else
        declare("Float64", a.name, a.components, a.real.data(), a.real.size() * sizeof(double));
    }
  };
  head << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
          "header_type=\"UInt64\">\n"
       << "  <UnstructuredGrid>\n"
       << "    <Piece NumberOfPoints=\"" << point_count() << "\" NumberOfCells=\"" << cell_count()
       << "\">\n";
  head << "      <PointData>\n";
  declare_arrays(point_data_);
  head << "      </PointData>\n      <CellData>\n";
  declare_arrays(cell_data_);
  head << "      </CellData>\n      <Points>\n";
  declare("Float64", "", 3, points_.data(), points_.size() * sizeof(double));
  head << "      </Points>\n      <Cells>\n";
  declare("Int64", "connectivity", 1, connectivity_.data(),
          connectivity_.size() * sizeof(std::int64_t));
  declare("Int64", "offsets", 1, offsets_.data(), offsets_.size() * sizeof(std::int64_t));
  declare("UInt8", "types", 1, types_.data(), types_.size());
  head << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
       << "  <AppendedData encoding=\"raw\">\n   _";
  write_vtu(file, head.str(), blocks, "\n  </AppendedData>\n</VTKFile>\n");
}

void PvdWriter::add(double time, const std::string& dataset) {
  entries_.emplace_back(time, dataset);
  std::ostringstream s;
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
    << "  <Collection>\n";
  s << std::setprecision(10);
  for (const auto& [t, f] : entries_)
    s << "    <DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << xml_escaped(f) << "\"/>\n";
  s << "  </Collection>\n</VTKFile>\n";
  // A failed write leaves the previous collection, which lists every frame up to the last
  // one written whole: the series stays playable. The entry is dropped so that the writer
  // lists what the file lists.
  try {
    write_file_atomically(file_, s.str());
  } catch (...) {
    entries_.pop_back();
    throw;
  }
}

}  // namespace lituya
