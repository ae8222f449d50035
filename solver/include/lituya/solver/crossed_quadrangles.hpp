#pragma once
// The quadrangles of a crossed mesh ([mesh] crossed = true: each quadrangle cut into four
// triangles where its diagonals cross) and the one pattern of water pressure over each of them
// that exerts no nodal force (scientific manual, section 3, "The free pressure pattern").
#include <array>
#include <vector>

#include "lituya/solver/mesh.hpp"

namespace lituya::solver {

struct CrossedQuadrangles {
  std::vector<std::array<int, 4>> cells;            // the four triangles of each quadrangle
  std::vector<std::array<double, 4>> free_pattern;  // unit c with sum_T c_T grad N_i|_T = 0
  std::vector<int> cell_quadrangle;                 // per cell: its quadrangle, or -1
  std::vector<int> cell_slot;                       // per cell: its place (0-3) in it
  bool empty() const { return cells.empty(); }
};

// Per-cell sums the removal reuses from step to step (no allocation per step). After a call,
// `change` holds each cell's pressure change (0 where nothing was removed).
struct FreePatternScratch {
  std::vector<double> sum, weight, change;
};

// The quadrangles of a 2D mesh: every node shared by exactly four cells whose four other nodes
// lie, two by two, on two straight lines through it (the crossing of a quadrangle's diagonals,
// where the four cells' volume constraints are dependent). A plain triangle mesh has none.
CrossedQuadrangles find_crossed_quadrangles(const Mesh<2>& mesh);

// Removes each quadrangle's free pattern from the pressure of the points in it: with S_T the
// sum over the points of cell T of scale_T p V (the cell's share of the pressure force),
// S <- S - (c . S) c, the change spread over the cell's points in proportion to scale_T V, so
// that every point of a cell moves by the same pressure. The nodal force of S is unchanged
// (the pattern exerts none); a quadrangle with a cell that holds no point is left alone, and
// a pressure that would fall below zero is clamped there (the water takes no tension).
// `point_cell`, `volume` and `pressure` are per point; `cell_scale` per cell. Returns the
// number of points changed. Serial: the same bits on any number of threads.
std::size_t remove_free_pressure_pattern(const CrossedQuadrangles& quadrangles,
                                         const std::vector<int>& point_cell,
                                         const std::vector<double>& cell_scale,
                                         const std::vector<double>& volume,
                                         std::vector<double>& pressure,
                                         FreePatternScratch& scratch);

}  // namespace lituya::solver
