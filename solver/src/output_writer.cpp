#include "lituya/solver/output_writer.hpp"

#include <algorithm>
#include <cstdio>

namespace lituya::solver {

namespace {
// Pads vectors to 3 components, as VTK expects.
template <int dim>
std::vector<double> as_xyz(const std::vector<Eigen::Matrix<double, dim, 1>>& v) {
  std::vector<double> out(3 * v.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int d = 0; d < dim; ++d) out[3 * i + d] = v[i](d);
  return out;
}

bool wants(const OutputSettings& s, const std::string& field) {
  return std::find(s.point_fields.begin(), s.point_fields.end(), field) != s.point_fields.end();
}
}  // namespace

template <int dim>
OutputWriter<dim>::OutputWriter(std::filesystem::path folder, OutputSettings settings)
    : folder_(std::move(folder)), settings_(std::move(settings)) {
  std::filesystem::create_directories(folder_);
}

template <int dim>
void OutputWriter<dim>::write(Simulation<dim>& simulation, const Stage& stage, double time,
                              int index) {
  char number[16];
  std::snprintf(number, sizeof number, "%04d", index);
  const std::string points_name = stage.name + "_points_" + number + ".vtu";
  write_points(simulation, folder_ / points_name);
  auto& points_series = series_[stage.name + "_points"];
  if (!points_series)
    points_series = std::make_unique<PvdWriter>(folder_ / (stage.name + "_points.pvd"));
  points_series->add(time, points_name);
  if (simulation.has_liquid()) {
    const std::string liquid_name = stage.name + "_liquid_" + number + ".vtu";
    write_liquid(simulation, folder_ / liquid_name);
    auto& liquid_series = series_[stage.name + "_liquid"];
    if (!liquid_series)
      liquid_series = std::make_unique<PvdWriter>(folder_ / (stage.name + "_liquid.pvd"));
    liquid_series->add(time, liquid_name);
  }
  if (settings_.grid) {
    const std::string grid_name = stage.name + "_grid_" + number + ".vtu";
    write_grid(simulation, folder_ / grid_name);
    auto& grid_series = series_[stage.name + "_grid"];
    if (!grid_series)
      grid_series = std::make_unique<PvdWriter>(folder_ / (stage.name + "_grid.pvd"));
    grid_series->add(time, grid_name);
  }
}

template <int dim>
void OutputWriter<dim>::write_points(const Simulation<dim>& simulation,
                                     const std::filesystem::path& file) const {
  const MaterialPoints<dim>& p = simulation.points();
  VtuWriter w;
  w.set_points(as_xyz<dim>(p.position));
  w.set_vertex_cells();
  w.add_point_data("id", p.id);
  if (wants(settings_, "displacement"))
    w.add_point_data("displacement", 3, as_xyz<dim>(p.displacement));
  if (wants(settings_, "velocity")) w.add_point_data("velocity", 3, as_xyz<dim>(p.velocity));
  if (wants(settings_, "stress")) {
    std::vector<double> s(6 * p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      for (int k = 0; k < 6; ++k) s[6 * i + k] = p.stress[i](k);
    w.add_point_data("stress", 6, s);
  }
  if (wants(settings_, "plastic_strain")) w.add_point_data("plastic_strain", 1, p.plastic_strain);
  if (wants(settings_, "material")) w.add_point_data("material", p.material);
  if (wants(settings_, "mass")) w.add_point_data("mass", 1, p.mass);
  if (wants(settings_, "volume")) w.add_point_data("volume", 1, p.volume);
  if (wants(settings_, "porosity")) {
    std::vector<double> n(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) n[i] = simulation.porosity(i);
    w.add_point_data("porosity", 1, n);
  }
  w.write(file);
}

template <int dim>
void OutputWriter<dim>::write_liquid(const Simulation<dim>& simulation,
                                     const std::filesystem::path& file) const {
  const LiquidPoints<dim>& q = simulation.liquid();
  VtuWriter w;
  w.set_points(as_xyz<dim>(q.position));
  w.set_vertex_cells();
  w.add_point_data("id", q.id);
  w.add_point_data("velocity", 3, as_xyz<dim>(q.velocity));
  w.add_point_data("pressure", 1, q.pressure);
  w.add_point_data("porosity", 1, q.porosity);
  w.add_point_data("mass", 1, q.mass);
  w.add_point_data("volume", 1, q.volume);
  w.add_point_data("material", q.material);
  w.write(file);
}

template <int dim>
void OutputWriter<dim>::write_grid(Simulation<dim>& simulation,
                                   const std::filesystem::path& file) const {
  simulation.map_to_grid();
  const Mesh<dim>& mesh = simulation.mesh();
  VtuWriter w;
  w.set_points(as_xyz<dim>(mesh.node_position));
  std::vector<std::int64_t> connectivity, offsets;
  connectivity.reserve(mesh.cell_count() * (dim + 1));
  for (const auto& cell : mesh.cell_nodes) {
    for (int n : cell) connectivity.push_back(n);
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  w.set_cells(std::move(connectivity), std::move(offsets),
              std::vector<std::uint8_t>(mesh.cell_count(),
                                        static_cast<std::uint8_t>(dim == 2 ? VtkCellType::kTriangle
                                                                           : VtkCellType::kTetra)));
  w.add_point_data("mass", 1, simulation.node_mass());
  w.add_point_data("velocity", 3, as_xyz<dim>(simulation.node_velocity()));
  if (simulation.has_liquid()) {
    w.add_point_data("liquid_mass", 1, simulation.node_liquid_mass());
    w.add_point_data("liquid_velocity", 3, as_xyz<dim>(simulation.node_liquid_velocity()));
    w.add_point_data("porosity", 1, simulation.node_porosity());
    w.add_point_data("liquid_pressure", 1, simulation.node_pressure());
  }
  w.write(file);
}

template class OutputWriter<2>;
template class OutputWriter<3>;

}  // namespace lituya::solver
