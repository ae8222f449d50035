#include "lituya/pre/case_writer.hpp"

#include <fstream>

#include <toml++/toml.h>

#include "lituya/common/vtu_writer.hpp"

namespace lituya::pre {

namespace fs = std::filesystem;

namespace {

// TOML files start with the two header keys, then the tables as toml++ prints them. Written
// to a temporary name and renamed, like the VTU files, so no reader ever sees half a file.
class TomlFile {
 public:
  TomlFile(fs::path file, const std::string& format) : file_(std::move(file)) {
    temporary_ = file_;
    temporary_ += ".tmp";
    out_.open(temporary_);
    if (!out_) throw std::runtime_error("cannot write " + temporary_.string());
    out_ << "format = \"" << format << "\"\nversion = 1\n";
  }
  // A table's keys at the top level of the file (plain keys, then sub-tables).
  void add(const toml::table& table) {
    if (!table.empty()) out_ << "\n" << table << "\n";
  }
  void close() {
    out_.close();
    if (!out_) throw std::runtime_error("error while writing " + temporary_.string());
    fs::rename(temporary_, file_);
  }

 private:
  fs::path file_, temporary_;
  std::ofstream out_;
};

toml::array array_of(const std::vector<toml::table>& tables) {
  toml::array a;
  for (const auto& t : tables) a.push_back(t);
  return a;
}

}  // namespace

std::vector<std::int32_t> region_group_of_cells(const Scene& scene, const Mesh& mesh) {
  std::vector<std::int32_t> group(mesh.cell_count(), -1);
  for (const Region& region : scene.regions) {
    const auto g = mesh.find_group(region.group, mesh.dimension);
    if (!g) continue;  // check_scene_groups reports it
    for (std::size_t cell : mesh.group_cells[*g]) group[cell] = static_cast<std::int32_t>(*g);
  }
  return group;
}

void write_geometry(const Mesh& mesh, const std::vector<std::int32_t>& cell_group,
                    const fs::path& file) {
  std::vector<std::int64_t> connectivity(mesh.cell_nodes.begin(), mesh.cell_nodes.end());
  std::vector<std::int64_t> offsets;
  std::vector<std::uint8_t> types;
  std::vector<std::int32_t> group = cell_group;
  const int corners = mesh.nodes_per_cell();
  const auto cell_type =
      static_cast<std::uint8_t>(mesh.dimension == 2 ? VtkCellType::kTriangle : VtkCellType::kTetra);
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    offsets.push_back(static_cast<std::int64_t>((c + 1) * corners));
    types.push_back(cell_type);
  }
  // Boundary facets after the cells; a facet on two groups appears once per group.
  const auto facet_type =
      static_cast<std::uint8_t>(mesh.dimension == 2 ? VtkCellType::kLine : VtkCellType::kTriangle);
  for (std::size_t g = 0; g < mesh.groups.size(); ++g) {
    const auto& facets = mesh.group_facets[g];
    for (std::size_t k = 0; k < facets.size(); k += mesh.dimension) {
      connectivity.insert(connectivity.end(), facets.begin() + k,
                          facets.begin() + k + mesh.dimension);
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      types.push_back(facet_type);
      group.push_back(static_cast<std::int32_t>(g));
    }
  }
  VtuWriter vtu;
  vtu.set_points(mesh.node_xyz);
  vtu.set_cells(std::move(connectivity), std::move(offsets), std::move(types));
  vtu.add_cell_data("group", group);
  vtu.write(file);
}

namespace {
// The arrays both point files share; the caller adds its own (stress or pressure) and writes.
template <class Points>
VtuWriter point_set_writer(const Points& points) {
  VtuWriter vtu;
  vtu.set_points(points.position);
  vtu.set_vertex_cells();
  vtu.add_point_data("material", points.material);
  vtu.add_point_data("volume", 1, points.volume);
  vtu.add_point_data("mass", 1, points.mass);
  vtu.add_point_data("velocity", 3, points.velocity);
  vtu.add_point_data("cell", points.cell);
  return vtu;
}
}  // namespace

void write_points(const MaterialPoints& points, const fs::path& file) {
  VtuWriter vtu = point_set_writer(points);
  vtu.add_point_data("stress", 6, points.stress);
  vtu.write(file);
}

void write_liquid_points(const LiquidPoints& points, const fs::path& file) {
  VtuWriter vtu = point_set_writer(points);
  vtu.add_point_data("pressure", 1, points.pressure);
  vtu.write(file);
}

void write_materials(const Scene& scene, const fs::path& file) {
  std::vector<toml::table> materials;
  for (const auto& m : scene.materials) materials.push_back(solver::to_toml(m));
  TomlFile out(file, "lituya-materials");
  out.add(toml::table{{"material", array_of(materials)}});
  out.close();
}

void write_stages(const Scene& scene, const Mesh& mesh, bool has_liquid_points,
                  const fs::path& file) {
  toml::array gravity;
  for (double g : scene.gravity) gravity.push_back(g);
  std::vector<toml::table> groups, boundaries, stages;
  for (const PhysicalGroup& g : mesh.groups)
    groups.push_back(toml::table{{"name", g.name}, {"dimension", g.dimension}});
  for (const auto& b : scene.boundaries) boundaries.push_back(solver::to_toml(b));
  for (const auto& s : scene.stages) stages.push_back(solver::to_toml(s));

  // Section by section, so the file reads in the order of the format description.
  TomlFile out(file, "lituya-stages");
  toml::table files{{"dimension", scene.dimension},
                    {"gravity", gravity},
                    {"geometry", kGeometryFile},
                    {"points", kPointsFile}};
  if (has_liquid_points) files.insert("liquid_points", kLiquidPointsFile);
  files.insert("materials", kMaterialsFile);
  out.add(files);
  out.add(toml::table{{"group", array_of(groups)}});
  out.add(toml::table{{"solver", solver::to_toml(scene.solver)}});
  out.add(toml::table{{"output", solver::to_toml(scene.output)}});
  if (!boundaries.empty()) out.add(toml::table{{"boundary", array_of(boundaries)}});
  out.add(toml::table{{"stage", array_of(stages)}});
  std::vector<toml::table> probes;
  for (const auto& p : scene.probes) probes.push_back(solver::to_toml(p));
  if (!probes.empty()) out.add(toml::table{{"probe", array_of(probes)}});
  std::vector<toml::table> sponges;
  for (const auto& z : scene.sponges) sponges.push_back(solver::to_toml(z));
  if (!sponges.empty()) out.add(toml::table{{"sponge", array_of(sponges)}});
  out.close();
}

void write_post(const PostSettings& post, const fs::path& case_folder) {
  TomlFile out(case_folder / kPostFile, "lituya-post");
  out.add(post.table);
  out.close();
  // post.toml names each copy relative to itself, which is how `lituya post` resolves it.
  for (const PostDataFile& data : post.data_files)
    fs::copy_file(data.source, case_folder / data.case_name, fs::copy_options::overwrite_existing);
}

}  // namespace lituya::pre
