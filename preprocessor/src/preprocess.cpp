#include "lituya/pre/preprocess.hpp"

#include "lituya/common/output_folder.hpp"
#include "lituya/pre/case_writer.hpp"
#include "lituya/pre/gmsh_mesh.hpp"
#include "lituya/pre/initial_state.hpp"
#include "lituya/pre/scene.hpp"

namespace lituya::pre {

namespace fs = std::filesystem;

namespace {

// Refuses a non-empty case folder before any work is done (meshing may take a while), with
// the message prepare_output_folder gives; the folder itself is created only once everything
// has been validated.
void refuse_occupied_folder(const fs::path& case_folder, bool overwrite) {
  std::error_code error;  // e.g. a symbolic link loop: prepare_output_folder reports it
  const fs::file_status status = fs::status(case_folder, error);
  if ((error && status.type() != fs::file_type::not_found) ||
      (fs::exists(status) &&
       (!fs::is_directory(status) || (!overwrite && !fs::is_empty(case_folder)))))
    prepare_output_folder(case_folder, overwrite);  // throws
}

}  // namespace

PreprocessSummary preprocess(const fs::path& scene_file, const fs::path& case_folder,
                             bool overwrite, bool allow_large_mesh, bool gmsh_messages) {
  Scene scene = read_scene(scene_file);
  refuse_occupied_folder(case_folder, overwrite);
  MeshingOptions meshing{scene.dimension, scene.cell_size, gmsh_messages, scene.crossed};
  meshing.seed = scene.mesh_seed;
  meshing.size_check = {!allow_large_mesh, scene.points_per_cell, scene.file, scene.cell_size_line};
  const Mesh mesh = read_gmsh_mesh(scene.geometry, meshing);
  check_scene_groups(scene, mesh);

  const InitialState state = make_initial_state(scene, mesh);
  const bool has_liquid_points = state.liquid.size() > 0;
  check_probes(scene, mesh, state.solid.size(), state.liquid.size());
  resolve_sponges(scene, state.liquid);

  prepare_output_folder(case_folder, overwrite);
  write_geometry(mesh, region_group_of_cells(scene, mesh), case_folder / kGeometryFile);
  write_points(state.solid, case_folder / kPointsFile);
  if (has_liquid_points) write_liquid_points(state.liquid, case_folder / kLiquidPointsFile);
  write_materials(scene, case_folder / kMaterialsFile);
  write_stages(scene, mesh, has_liquid_points, case_folder / kStagesFile);
  if (scene.post) write_post(*scene.post, case_folder);

  return {scene.dimension, mesh.node_count(), mesh.cell_count(), state.solid.size(),
          state.liquid.size()};
}

}  // namespace lituya::pre
