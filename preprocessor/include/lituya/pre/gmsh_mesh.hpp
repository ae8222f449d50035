#pragma once
// Meshing a .geo (or reading a .msh) with the gmsh SDK into a plain Mesh.
#include <filesystem>
#include <string>

#include "lituya/pre/mesh.hpp"
#include "lituya/pre/mesh_size.hpp"

namespace lituya::pre {

// The memory check made before a .geo is meshed (a .msh is already meshed: nothing to check).
struct MeshSizeCheck {
  bool enabled = false;  // false: mesh whatever the size (`--allow-large-mesh`)
  int points_per_cell = 0;
  std::string scene_file;  // where cell_size is written, for the refusal (else the geometry)
  int cell_size_line = 0;
  double available_bytes = 0;  // 0: available_memory_bytes()
};

// The largest [mesh] seed a scene may give (gmsh's seed is a C int).
inline constexpr long long kLargestMeshSeed = 2147483647;

struct MeshingOptions {
  int dimension = 2;        // 2: linear triangles, 3: linear tetrahedra
  double cell_size = 0.01;  // m, largest edge length gmsh may use
  bool verbose = false;     // let gmsh print its progress
  // 2D only. gmsh recombines its triangles into quadrangles (Mesh.RecombineAll) and each
  // quadrangle is cut into four triangles where its diagonals cross ("crossed" or
  // criss-cross cells). Linear triangles in pairs lock under a volume constraint
  // (incompressible flow, a Coulomb flow at zero dilation): a mesh of them has about as many
  // such constraints as velocity unknowns. In a crossed quadrangle one of the four
  // constraints follows from the other three, so the mesh can deform at constant volume
  // (scientific manual, section 3).
  bool crossed = false;
  // The seed of gmsh's pseudo-random numbers (Mesh.RandomSeed; 0: gmsh's own, 1, or the
  // .geo's). gmsh perturbs the points it inserts by tiny random amounts, so another seed gives
  // another triangulation of the same geometry at the same size, often with most interior
  // nodes elsewhere (Case B's flume at 0.015 m: 819 of 3779 nodes stay), but not always (two
  // unit squares at 0.05 m mesh the same with seeds 1 and 2).
  // Runs on meshes of several seeds measure how much a result depends on the particular
  // triangulation (`lituya sweep --repeats N --repeat-by mesh`).
  int seed = 0;
  MeshSizeCheck size_check = {};
};

// Opens `geometry` with gmsh (without meshing it) and estimates the mesh `options` would give
// from the area (2D) or volume (3D) of its surfaces / volumes: the OpenCASCADE kernel's exact
// mass, else (built-in kernel) each entity's bounding box, an upper bound. Local refinement
// (sizes given to points, size fields) is not counted.
MeshSizeEstimate estimate_gmsh_mesh(const std::filesystem::path& geometry,
                                    const MeshingOptions& options);

// Opens `geometry` with gmsh, meshes it when it is a .geo, and returns every element of
// dimension `options.dimension` (nodes renumbered from 0, cells positively oriented) with the
// physical groups. Throws InputError naming the geometry file for anything gmsh rejects, for
// elements other than linear triangles / tetrahedra (with `crossed`, also quadrangles, each
// cut into four triangles around a new node where its diagonals cross), and for inverted or
// degenerate cells.
// With options.size_check enabled, refuses (InputError at the scene's cell_size line) a .geo
// whose estimated mesh needs more memory than is available, before meshing it.
// Not thread-safe: gmsh is one process-wide instance (opened and closed by each call).
Mesh read_gmsh_mesh(const std::filesystem::path& geometry, const MeshingOptions& options);

}  // namespace lituya::pre
