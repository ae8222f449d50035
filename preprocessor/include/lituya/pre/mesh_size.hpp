#pragma once
// How big a mesh a cell size asks for, estimated before gmsh meshes anything: a cell size
// typed a few orders of magnitude too small (1e-6 instead of 1e-2) would otherwise have gmsh
// grow until it takes all the machine's memory, which can take minutes and ends in a crash
// rather than an error message.
#include <cstddef>

namespace lituya::pre {

// Measured on the development machine (README, "Benchmark"; gmsh 4.8) and rounded up, so
// that a refused run would really not have fitted:
//  - gmsh's peak memory while meshing: 0.6-0.75 kB per triangle and 0.55 kB per tetrahedron
//    (the peak resident set of `gmsh -2/-3` and `lituya pre` at two cell sizes, differenced),
//    plus the preprocessor's own copy of the mesh; 1 kB per cell leaves a margin;
//  - the solver's storage per material point: 297 B in 2D and 453 B in 3D.
inline constexpr double kBytesPerCell = 1000;
inline constexpr double kBytesPerPoint2D = 300;
inline constexpr double kBytesPerPoint3D = 460;

struct MeshSizeEstimate {
  double cells = 0;
  double points = 0;  // an upper bound: every cell holding material points
  double bytes = 0;
};

// The cells and points of a model of total area (2D, m^2) or volume (3D, m^3) `measure`
// meshed at `cell_size`, and the memory they need. A cell is counted as an equilateral
// triangle (sqrt(3)/4 h^2) in 2D and as h^3 / 4.7 in 3D: gmsh's tetrahedra with edges of about
// h are on average 1.8 times as large as the regular tetrahedron (h^3 / (6 sqrt 2)), measured on
// the unit cube at h = 0.04 and 0.02 m. A crossed 2D mesh (MeshingOptions::crossed) cuts
// quadrangles of about h^2 into four triangles: h^2 / 4 a cell.
MeshSizeEstimate estimate_mesh_size(double measure, int dimension, double cell_size,
                                    int points_per_cell, bool crossed = false);

// The memory this process may use, in bytes: the smaller of the memory the system reports
// available (/proc/meminfo MemAvailable, else the physical memory) and a cgroup limit (a
// container's memory.max), when there is one.
double available_memory_bytes();

}  // namespace lituya::pre
