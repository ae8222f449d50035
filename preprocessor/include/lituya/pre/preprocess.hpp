#pragma once
// `lituya pre`: scene.toml + a gmsh geometry -> a case folder the solver reads.
#include <cstddef>
#include <filesystem>

namespace lituya::pre {

struct PreprocessSummary {
  int dimension = 0;
  std::size_t nodes = 0, cells = 0;
  std::size_t points = 0;         // solid points (points.vtu)
  std::size_t liquid_points = 0;  // liquid points (liquid_points.vtu; 0: a dry case)
};

// Reads the scene, meshes its geometry with gmsh, seeds points, writes the case folder
// (geometry.vtu, points.vtu, liquid_points.vtu if the scene has water, materials.toml,
// stages.toml, post.toml if the scene has [post]).
// Throws lituya::InputError (file + line + what was expected) for any bad input; never writes
// into a non-empty case folder unless overwrite is true (use prepare_output_folder), and
// validates everything BEFORE creating the folder. Refuses a cell size whose mesh would need
// more memory than the machine has (estimated before meshing) unless allow_large_mesh.
// `gmsh_messages`: let gmsh print its own messages (reading the geometry, meshing each
// dimension, its warnings) on standard output, as `lituya --verbose` asks.
PreprocessSummary preprocess(const std::filesystem::path& scene_file,
                             const std::filesystem::path& case_folder, bool overwrite,
                             bool allow_large_mesh = false, bool gmsh_messages = false);

}  // namespace lituya::pre
