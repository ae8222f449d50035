#pragma once
// Meshing a .geo (or reading a .msh) with the gmsh SDK into a plain Mesh.
#include <filesystem>

#include "lituya/pre/mesh.hpp"

namespace lituya::pre {

struct MeshingOptions {
  int dimension = 2;        // 2: linear triangles, 3: linear tetrahedra
  double cell_size = 0.01;  // m, largest edge length gmsh may use
  bool verbose = false;     // let gmsh print its progress
};

// Opens `geometry` with gmsh, meshes it when it is a .geo, and returns every element of
// dimension `options.dimension` (nodes renumbered from 0, cells positively oriented) with the
// physical groups. Throws InputError naming the geometry file for anything gmsh rejects, for
// elements other than linear triangles / tetrahedra, and for inverted or degenerate cells.
// Not thread-safe: gmsh is one process-wide instance (opened and closed by each call).
Mesh read_gmsh_mesh(const std::filesystem::path& geometry, const MeshingOptions& options);

}  // namespace lituya::pre
