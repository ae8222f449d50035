#pragma once
// The background mesh as the preprocessor sees it: plain arrays, no gmsh types, so that
// seeding, the initial stress and the writers can be tested without gmsh.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lituya::pre {

// A gmsh physical group. Its position in Mesh::groups is its id in stages.toml's [[group]].
struct PhysicalGroup {
  std::string name;  // the gmsh physical name, or the group's tag when it has no name
  int dimension = 0;
  int tag = 0;  // gmsh physical tag, for messages
};

struct Mesh {
  int dimension = 2;
  std::vector<double> node_xyz;                // 3 coordinates per node (z = 0 in 2D)
  std::vector<std::int64_t> cell_nodes;        // dimension + 1 nodes per cell, positive
  std::vector<std::size_t> cell_element_tags;  // gmsh element tag of each cell (messages)
  std::vector<PhysicalGroup> groups;
  // Per group: the cells of a group of dimension `dimension` (empty for other groups).
  std::vector<std::vector<std::size_t>> group_cells;
  // Per group: the facets of a group of dimension `dimension - 1`, `dimension` nodes each
  // (empty for other groups).
  std::vector<std::vector<std::int64_t>> group_facets;

  int nodes_per_cell() const { return dimension + 1; }
  std::size_t node_count() const { return node_xyz.size() / 3; }
  std::size_t cell_count() const { return cell_nodes.size() / nodes_per_cell(); }
  // Index of the group called `name` with dimension `dimension`, if any.
  std::optional<std::size_t> find_group(const std::string& name, int dimension) const;
  // "bed", "wall", ... : the names of the groups of one dimension, for error messages.
  std::string group_names(int dimension) const;
};

// Signed area (2D, counter-clockwise positive) or volume (3D, right-handed positive) of a
// cell, from its node coordinates.
double signed_cell_measure(const Mesh& mesh, std::size_t cell);
// Centroid of a cell (3 components).
std::vector<double> cell_centroid(const Mesh& mesh, std::size_t cell);

}  // namespace lituya::pre
