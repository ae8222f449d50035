#include "lituya/pre/preprocess.hpp"

#include "lituya/common/output_folder.hpp"
#include "lituya/pre/case_writer.hpp"
#include "lituya/pre/gmsh_mesh.hpp"
#include "lituya/pre/initial_stress.hpp"
#include "lituya/pre/scene.hpp"
#include "lituya/pre/seeding.hpp"

namespace lituya::pre {

namespace fs = std::filesystem;

namespace {

// Refuses a non-empty case folder before any work is done (meshing may take a while), with
// the message prepare_output_folder gives; the folder itself is created only once everything
// has been validated.
void refuse_occupied_folder(const fs::path& case_folder, bool overwrite) {
  if (fs::exists(case_folder) &&
      (!fs::is_directory(case_folder) || (!overwrite && !fs::is_empty(case_folder))))
    prepare_output_folder(case_folder, overwrite);  // throws
}

// Dry density of the material in each background cell, 0 where no region puts material.
std::vector<double> cell_dry_density(const Scene& scene, const Mesh& mesh) {
  std::vector<double> density(mesh.cell_count(), 0.0);
  for (const Region& region : scene.regions)
    for (std::size_t cell : mesh.group_cells[*mesh.find_group(region.group, mesh.dimension)])
      density[cell] = scene.materials[region.material].dry_density();
  return density;
}

}  // namespace

PreprocessSummary preprocess(const fs::path& scene_file, const fs::path& case_folder,
                             bool overwrite) {
  const Scene scene = read_scene(scene_file);
  refuse_occupied_folder(case_folder, overwrite);
  const Mesh mesh = read_gmsh_mesh(scene.geometry, {scene.dimension, scene.cell_size, false});
  check_scene_groups(scene, mesh);

  // Points region by region, so each region's points form one contiguous range.
  MaterialPoints points;
  std::vector<std::size_t> region_begin;
  for (const Region& region : scene.regions) {
    region_begin.push_back(points.size());
    const auto group = mesh.find_group(region.group, scene.dimension);
    seed_cells(mesh, mesh.group_cells[*group], scene.points_per_cell,
               scene.materials[region.material].dry_density(),
               static_cast<std::int32_t>(region.material), points);
  }
  region_begin.push_back(points.size());

  // The overburden counts the material of every region, also of those that start
  // stress-free.
  std::vector<double> overburden;
  for (std::size_t r = 0; r < scene.regions.size(); ++r) {
    if (scene.regions[r].initial_stress != InitialStress::kK0) continue;
    if (overburden.empty())
      overburden =
          overburden_pressure(mesh, cell_dry_density(scene, mesh), points, -scene.gravity[1]);
    set_k0_stress(points, overburden, region_begin[r], region_begin[r + 1], scene.regions[r].k0);
  }

  prepare_output_folder(case_folder, overwrite);
  write_geometry(mesh, region_group_of_cells(scene, mesh), case_folder / kGeometryFile);
  write_points(points, case_folder / kPointsFile);
  write_materials(scene, case_folder / kMaterialsFile);
  write_stages(scene, mesh, case_folder / kStagesFile);
  if (scene.post) write_post(*scene.post, case_folder);

  return {scene.dimension, mesh.node_count(), mesh.cell_count(), points.size()};
}

}  // namespace lituya::pre
