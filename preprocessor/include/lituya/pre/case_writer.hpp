#pragma once
// The files of a case folder (see manuals/file-formats.md).
#include <cstdint>
#include <filesystem>
#include <vector>

#include "lituya/pre/liquid_points.hpp"
#include "lituya/pre/material_points.hpp"
#include "lituya/pre/mesh.hpp"
#include "lituya/pre/scene.hpp"

namespace lituya::pre {

// File names inside the case folder.
inline constexpr const char* kGeometryFile = "geometry.vtu";
inline constexpr const char* kPointsFile = "points.vtu";
inline constexpr const char* kLiquidPointsFile = "liquid_points.vtu";
inline constexpr const char* kMaterialsFile = "materials.toml";
inline constexpr const char* kStagesFile = "stages.toml";
inline constexpr const char* kPostFile = "post.toml";

// Cell data `group` of each background cell: the id of the region group that holds it, -1
// for cells outside every region.
std::vector<std::int32_t> region_group_of_cells(const Scene& scene, const Mesh& mesh);

// geometry.vtu: nodes, background cells, then the facets of every group of dimension - 1.
void write_geometry(const Mesh& mesh, const std::vector<std::int32_t>& cell_group,
                    const std::filesystem::path& file);
// points.vtu: one vertex cell per solid point (none in a water-only scene).
void write_points(const MaterialPoints& points, const std::filesystem::path& file);
// liquid_points.vtu: one vertex cell per liquid point.
void write_liquid_points(const LiquidPoints& points, const std::filesystem::path& file);
// materials.toml
void write_materials(const Scene& scene, const std::filesystem::path& file);
// stages.toml; names liquid_points.vtu when `has_liquid_points` (a dry case has no such key,
// and the solver allocates no liquid phase).
void write_stages(const Scene& scene, const Mesh& mesh, bool has_liquid_points,
                  const std::filesystem::path& file);
// post.toml, and copies of the data files it names (PostSettings::data_files) next to it.
void write_post(const PostSettings& post, const std::filesystem::path& case_folder);

}  // namespace lituya::pre
