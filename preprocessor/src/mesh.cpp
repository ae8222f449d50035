#include "lituya/pre/mesh.hpp"

#include <Eigen/Dense>

namespace lituya::pre {

std::optional<std::size_t> Mesh::find_group(const std::string& name, int group_dimension) const {
  for (std::size_t g = 0; g < groups.size(); ++g)
    if (groups[g].name == name && groups[g].dimension == group_dimension) return g;
  return std::nullopt;
}

std::string Mesh::group_names(int group_dimension) const {
  std::string list;
  for (const PhysicalGroup& g : groups)
    if (g.dimension == group_dimension) {
      if (!list.empty()) list += ", ";
      list += "\"" + g.name + "\"";
    }
  return list.empty() ? "none" : list;
}

namespace {
Eigen::Vector3d node_position(const Mesh& mesh, std::int64_t node) {
  return Eigen::Vector3d::Map(&mesh.node_xyz[3 * static_cast<std::size_t>(node)]);
}
}  // namespace

double signed_cell_measure(const Mesh& mesh, std::size_t cell) {
  const std::int64_t* nodes = &mesh.cell_nodes[cell * mesh.nodes_per_cell()];
  const Eigen::Vector3d a = node_position(mesh, nodes[0]);
  const Eigen::Vector3d e1 = node_position(mesh, nodes[1]) - a;
  const Eigen::Vector3d e2 = node_position(mesh, nodes[2]) - a;
  if (mesh.dimension == 2) return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
  const Eigen::Vector3d e3 = node_position(mesh, nodes[3]) - a;
  return e1.cross(e2).dot(e3) / 6.0;
}

std::vector<double> cell_centroid(const Mesh& mesh, std::size_t cell) {
  const int n = mesh.nodes_per_cell();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) sum += node_position(mesh, mesh.cell_nodes[cell * n + i]);
  sum /= n;
  return {sum.x(), sum.y(), sum.z()};
}

}  // namespace lituya::pre
