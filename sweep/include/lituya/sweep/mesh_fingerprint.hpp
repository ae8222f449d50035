#pragma once
// A fingerprint of a case's mesh that does not depend on how the nodes and cells are numbered.
//
// Why: the mesh repeats of a sweep (repeats.hpp) ask gmsh for another triangulation with another
// seed, and the report must say when a seed gave the same mesh again. Comparing the files does
// not do: on examples/case_b_2d at 0.02 m seeds 1 and 2 give the same 4248 triangles, with the
// nodes numbered in another order and a third of them moved by rounding (1e-14 m), so
// geometry.vtu differs while the mesh does not (the crests differ by at most 0.3 %, the
// Courant repeats' chaotic scatter, the kinetic energy by 2e-6).
//
// How: each coordinate is rounded to a step of 1e-7 of the mesh's largest extent (far below
// any cell, far above rounding), each cell becomes its physical group and its nodes' rounded
// coordinates, the nodes of a cell in sorted order; the cells are sorted; the list is hashed
// with FNV-1a 64 (content_hash.hpp). Two meshes with the same cells in any numbering give the
// same fingerprint; a node moved by more than the step or a flipped edge gives another. A
// coordinate within rounding of a step's edge can still round two ways (odds about 1e-3 for a
// mesh of thousands of nodes at 1e-14 jitter): then two equal meshes read as different, and
// the report stays silent, as it was before it compared meshes.
#include <cstdint>
#include <filesystem>
#include <optional>

namespace lituya::sweep {

// The fingerprint of the mesh in `geometry_vtu` (a case's geometry.vtu); nullopt when the file
// is missing or cannot be read, or holds a cell of more than four nodes (Lituya writes
// triangles and tetrahedra only).
std::optional<std::uint64_t> mesh_fingerprint(const std::filesystem::path& geometry_vtu);

}  // namespace lituya::sweep
