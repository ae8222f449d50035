#pragma once
// Filling cells with material points in fixed, equal-volume patterns.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lituya/pre/liquid_points.hpp"
#include "lituya/pre/material_points.hpp"
#include "lituya/pre/mesh.hpp"

namespace lituya::pre {

// True when `points_per_cell` is one of the patterns below for this dimension.
bool is_supported_points_per_cell(int dimension, int points_per_cell);
// "1, 3, 4, 9, 16" (2D) or "1, 4, 8" (3D), for messages.
std::string supported_points_per_cell(int dimension);

// Barycentric coordinates (dimension + 1 used, the rest 0) of the points of one cell, each
// standing for an equal share of the cell's volume:
//   2D: 1 centroid; 3 the degree-2 Gauss points; 4, 9, 16 the centroids of the k^2 triangles
//       of a uniform k-subdivision (k = 2, 3, 4);
//   3D: 1 centroid; 4 the degree-2 Gauss points; 8 the centroids of the 8 children of the
//       midpoint (red) refinement.
// Throws std::invalid_argument for an unsupported count.
std::vector<std::array<double, 4>> seed_pattern(int dimension, int points_per_cell);

// Appends `points_per_cell` solid points to each of `cells`, with volume = cell volume / N and
// mass = dry_density * volume.
void seed_cells(const Mesh& mesh, const std::vector<std::size_t>& cells, int points_per_cell,
                double dry_density, std::int32_t material_id, MaterialPoints& points);

// Appends `points_per_cell` liquid points to each of `cells`, at the positions seed_cells
// uses, so the water of saturated soil sits on its solid points. A point stands for the water
// in the mixture volume V = cell volume / N: volume = porosity * V and mass = liquid_density *
// porosity * V (the apparent density n rho_w of eq. (2)). Free water has porosity 1.
void seed_liquid_cells(const Mesh& mesh, const std::vector<std::size_t>& cells, int points_per_cell,
                       double porosity, double liquid_density, std::int32_t material_id,
                       LiquidPoints& points);

}  // namespace lituya::pre
