#pragma once
// scene.toml, the one file a user writes: what to mesh, which physical groups hold which
// material, boundaries, stages, solver and output settings, and what to post-process.
// Everything that can be checked without the mesh is checked by read_scene; the references to
// physical groups are checked against the mesh by check_scene_groups.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "lituya/pre/liquid_points.hpp"
#include "lituya/pre/mesh.hpp"
#include "lituya/solver/case_description.hpp"

namespace lituya::pre {

// How a region's points start:
//   kZero        stress-free solid points / liquid points at zero pressure (the quasi-static
//                stage settles them);
//   kK0          soil: geostatic effective stress (K0), and a hydrostatic pore pressure when
//                the region is saturated;
//   kHydrostatic free water: the pressure of the water column above each point.
enum class InitialStress { kZero, kK0, kHydrostatic };

// A physical group of dimension `dimension` filled with material points. Its `material` is
// either a soil (solid points, optionally saturated by `pore_water`) or water (free water:
// liquid points only, porosity 1).
struct Region {
  std::string group;
  std::size_t material = 0;  // index in Scene::materials
  // Saturated soil: index in Scene::materials of the water that fills the pores (liquid points
  // at the solid points' positions). Empty for dry soil and for free water.
  std::optional<std::size_t> pore_water;
  InitialStress initial_stress = InitialStress::kZero;
  double k0 = 0;       // lateral earth pressure coefficient at rest (k0 regions only)
  int group_line = 0;  // scene.toml line of `group`, for messages
};

// A data file named by a [post] key (`reference`, `gauge_reference`). It is copied into the
// case folder as `case_name` and the key in post.toml rewritten to that name, so a case
// folder holds everything `lituya post` reads.
struct PostDataFile {
  std::string key;
  std::filesystem::path source;  // resolved against the scene's folder
  std::string case_name;         // file name in the case folder
};

// The [post] table, forwarded to post.toml (`lituya post` validates its keys itself).
struct PostSettings {
  toml::table table;  // without the header keys
  std::vector<PostDataFile> data_files;
};

struct Scene {
  std::string file;  // scene.toml as given, for messages
  std::string title;
  std::filesystem::path geometry;  // resolved against the scene's folder
  int dimension = 2;
  double cell_size = 0;
  int cell_size_line = 0;  // scene.toml line of `cell_size`, for the memory check's refusal
  int points_per_cell = 0;
  bool crossed = false;  // [mesh] crossed: quadrangles cut into four (MeshingOptions::crossed)
  int mesh_seed = 0;     // [mesh] seed: gmsh's Mesh.RandomSeed (MeshingOptions::seed); 0: not given
  std::vector<double> gravity;  // `dimension` components
  std::vector<solver::Material> materials;
  std::vector<Region> regions;
  std::vector<solver::BoundaryCondition> boundaries;
  std::vector<int> boundary_group_lines;  // scene.toml line of each boundary's `group`
  std::vector<solver::Stage> stages;
  solver::SolverSettings solver;
  solver::OutputSettings output;
  std::vector<solver::Probe> probes;
  std::vector<int> probe_lines;         // scene.toml line of each probe's position or point id
  std::vector<solver::Sponge> sponges;  // damping_rate 0: the default, set by resolve_sponges
  std::vector<int> sponge_lines;        // scene.toml line of each sponge's x_start
  std::optional<PostSettings> post;

  // True when the region's material is water (free water, liquid points only).
  bool is_free_water(const Region& r) const { return materials[r.material].is_liquid(); }
  // The water material of a region's liquid points: its own material for free water, its
  // pore water for saturated soil; nullptr for dry soil.
  const solver::Material* water_of(const Region& r) const;
  // True when any region is seeded with liquid points (the case then has liquid_points.vtu).
  bool has_water() const;
};

// Reads and validates scene.toml; throws InputError naming scene.toml and the line.
Scene read_scene(const std::filesystem::path& scene_file);

// Checks that every region names a physical group of dimension `dimension`, every boundary
// one of dimension `dimension - 1`, and that no cell belongs to two regions. Throws
// InputError at the scene line, listing the groups the geometry has.
void check_scene_groups(const Scene& scene, const Mesh& mesh);

// Checks that every fixed probe lies in the mesh and every point probe names a point that
// exists (ids count from 0 in points.vtu / liquid_points.vtu). Throws InputError at the
// probe's line.
void check_probes(const Scene& scene, const Mesh& mesh, std::size_t solid_points,
                  std::size_t liquid_points);

// Checks that every [[sponge]] zone holds water, and gives a sponge without damping_rate the
// default kDefaultSpongeStrength sqrt(g / h), h the depth of the liquid points in the zone.
// Throws InputError at the sponge's line.
void resolve_sponges(Scene& scene, const LiquidPoints& liquid);

}  // namespace lituya::pre
