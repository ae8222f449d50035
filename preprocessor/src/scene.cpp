#include "lituya/pre/scene.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <set>

#include "lituya/common/input_error.hpp"
#include "lituya/common/quoted_list.hpp"
#include "lituya/common/safe_name.hpp"
#include "lituya/common/toml_reader.hpp"
#include "lituya/post/postprocess.hpp"
#include "lituya/pre/case_writer.hpp"
#include "lituya/pre/gmsh_mesh.hpp"
#include "lituya/pre/seeding.hpp"
#include "lituya/solver/mohr_coulomb.hpp"

namespace lituya::pre {

namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

void read_mesh_table(const TomlTable& root, const fs::path& scene_file, Scene& scene) {
  const TomlTable mesh = root.table("mesh");
  const std::string geometry = mesh.string("geometry");
  std::string extension = fs::path(geometry).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".geo" && extension != ".msh")
    mesh.fail(
        "'mesh.geometry' = \"" + geometry + "\" must be a gmsh .geo script or a .msh mesh file",
        "geometry");
  // Relative to the scene file, so a scene folder can be moved or run from anywhere.
  scene.geometry = scene_file.parent_path() / geometry;
  std::error_code error;  // e.g. a symbolic link loop: reported, not thrown
  if (!fs::is_regular_file(scene.geometry, error))
    mesh.fail("geometry file \"" + geometry + "\" not found (looked for " +
                  scene.geometry.string() + "; the path is relative to the scene file)",
              "geometry");

  const long long dimension = mesh.integer("dimension");
  if (dimension != 2 && dimension != 3)
    mesh.fail("'mesh.dimension' must be 2 (plane strain) or 3", "dimension");
  scene.dimension = static_cast<int>(dimension);
  scene.cell_size = mesh.number("cell_size");
  scene.cell_size_line = mesh.line_of("cell_size");
  if (!(scene.cell_size > 0 && std::isfinite(scene.cell_size)))
    mesh.fail("'mesh.cell_size' must be a positive length in m", "cell_size");
  const long long points_per_cell = mesh.integer("points_per_cell");
  if (!is_supported_points_per_cell(scene.dimension, static_cast<int>(points_per_cell)))
    mesh.fail("'mesh.points_per_cell' = " + std::to_string(points_per_cell) +
                  " is not available in " + std::to_string(scene.dimension) +
                  "D; allowed values: " + supported_points_per_cell(scene.dimension),
              "points_per_cell");
  scene.points_per_cell = static_cast<int>(points_per_cell);
  scene.crossed = mesh.boolean_or("crossed", false);
  if (scene.crossed && scene.dimension != 2)
    mesh.fail(
        "'mesh.crossed' = true is available in 2D only (quadrangles cut into four "
        "triangles); 3D meshes are tetrahedra as gmsh makes them",
        "crossed");
  if (mesh.has("seed")) {
    const long long seed = mesh.integer("seed");
    if (seed < 1 || seed > kLargestMeshSeed)
      mesh.fail("'mesh.seed' must be a whole number from 1 to " + std::to_string(kLargestMeshSeed) +
                    " (got " + std::to_string(seed) + ")",
                "seed");
    scene.mesh_seed = static_cast<int>(seed);
  }

  // `gravity` belongs to the scene root; a line written under [mesh] (as a reader of the
  // format example may do) is accepted too, but not both.
  if (root.has("gravity") && mesh.has("gravity"))
    mesh.fail("'gravity' is given both at the top of the file and in [mesh]; keep one", "gravity");
  const TomlTable& owner = mesh.has("gravity") ? mesh : root;
  scene.gravity = owner.numbers("gravity");
  if (static_cast<int>(scene.gravity.size()) != scene.dimension)
    owner.fail("'gravity' must have " + std::to_string(scene.dimension) +
                   " components (one per axis, m/s2)",
               "gravity");
  mesh.finish();
}

void read_materials(const TomlTable& root, Scene& scene) {
  for (const TomlTable& t : root.tables("material")) {
    solver::Material m = solver::read_material(t);
    for (const auto& other : scene.materials)
      if (other.name == m.name)
        t.fail("two [[material]] entries are named '" + m.name + "'", "name");
    scene.materials.push_back(m);
  }
  if (scene.materials.empty())
    root.fail("no [[material]] given: at least one region needs a material");
}

// K0 from the material when the region does not give it: Jaky's 1 - sin(phi) for a frictional
// soil, the laterally confined elastic ratio nu / (1 - nu) otherwise.
double default_k0(const solver::Material& m) {
  if (m.model == solver::MaterialModel::kMohrCoulomb)
    return 1.0 - std::sin(m.friction_angle * kPi / 180.0);
  return m.poisson_ratio / (1.0 - m.poisson_ratio);
}

// The overburden integrals behind the K0 stress and the hydrostatic water pressure run along
// y: they only make sense for gravity along -y.
// `what` names the setting in the message, e.g. initial_stress = "k0".
void require_gravity_along_minus_y(const TomlTable& t, const Scene& scene,
                                   const std::string& what) {
  const auto& g = scene.gravity;
  const double lateral = std::abs(g[0]) + (scene.dimension == 3 ? std::abs(g[2]) : 0.0);
  if (!(g[1] < 0) || lateral > 1e-12 * std::abs(g[1]))
    t.fail(what + " needs gravity along -y (e.g. gravity = [0.0, -9.81" +
               std::string(scene.dimension == 3 ? ", 0.0" : "") +
               "]); with other gravity use initial_stress = \"zero\"",
           "initial_stress");
}

std::string model_name(const solver::Material& m) {
  switch (m.model) {
    case solver::MaterialModel::kMohrCoulomb:
      return "mohr-coulomb";
    case solver::MaterialModel::kLinearElastic:
      return "linear-elastic";
    case solver::MaterialModel::kWater:
      return "water";
  }
  return "?";
}

// A region whose material is water: free water, seeded with liquid points only. It has no
// effective stress, so no K0; it starts at the hydrostatic pressure unless told otherwise.
void read_free_water_region(const TomlTable& t, const Scene& scene, Region& r) {
  const solver::Material& water = scene.materials[r.material];
  if (t.has("water"))
    t.fail("'water' fills the pores of a soil region; region '" + r.group +
               "' is free water already (its material '" + water.name + "' is water)",
           "water");
  const std::string initial =
      t.choice_or("initial_stress", {"hydrostatic", "zero", "k0"}, "hydrostatic");
  if (initial == "k0")
    t.fail("initial_stress = \"k0\" is the geostatic stress of soil; region '" + r.group +
               "' is water (material '" + water.name +
               "'): use \"hydrostatic\" (the default) or \"zero\"",
           "initial_stress");
  if (t.has("k0"))
    t.fail("'k0' applies to soil regions; region '" + r.group + "' is water (material '" +
               water.name + "'), which carries no effective stress",
           "k0");
  r.initial_stress = initial == "zero" ? InitialStress::kZero : InitialStress::kHydrostatic;
  if (r.initial_stress == InitialStress::kHydrostatic)
    require_gravity_along_minus_y(t, scene,
                                  t.has("initial_stress")
                                      ? "initial_stress = \"hydrostatic\""
                                      : "initial_stress = \"hydrostatic\" (the default for water)");
}

// A soil region: solid points, and with `water` also the pore water (saturated soil).
void read_soil_region(const TomlTable& t, const Scene& scene, Region& r) {
  const solver::Material& soil = scene.materials[r.material];
  const std::string initial = t.choice_or("initial_stress", {"zero", "k0", "hydrostatic"}, "zero");
  if (initial == "hydrostatic")
    t.fail("initial_stress = \"hydrostatic\" applies to free water; region '" + r.group +
               "' is soil (material '" + soil.name +
               "'): use \"k0\" (a saturated soil then also starts at a hydrostatic pore "
               "pressure) or \"zero\"",
           "initial_stress");
  r.initial_stress = initial == "k0" ? InitialStress::kK0 : InitialStress::kZero;
  if (r.initial_stress == InitialStress::kK0) {
    require_gravity_along_minus_y(t, scene, "initial_stress = \"k0\"");
    r.k0 = t.has("k0") ? t.number_in("k0", 0.0, 10.0) : default_k0(soil);
  } else if (t.has("k0")) {
    t.fail("'k0' applies only to initial_stress = \"k0\"", "k0");
  }

  if (!t.has("water")) return;
  const std::string name = t.string("water");
  std::vector<std::string> water_names;
  for (const auto& m : scene.materials)
    if (m.is_liquid()) water_names.push_back(m.name);
  std::size_t index = 0;
  while (index < scene.materials.size() && scene.materials[index].name != name) ++index;
  if (index == scene.materials.size())
    t.fail("region '" + r.group + "' is saturated with '" + name +
               "', which no [[material]] defines (water materials: " + quoted_list(water_names) +
               ")",
           "water");
  const solver::Material& water = scene.materials[index];
  if (!water.is_liquid())
    t.fail("'water' of region '" + r.group + "' names material '" + name + "', which is " +
               model_name(water) + ", not water (a material with model = \"water\")",
           "water");
  // The drag between the skeleton and its pore water, eq. (23), needs the permeability of
  // eq. (24), and that needs the grain diameter.
  if (!(soil.grain_diameter > 0))
    t.fail("region '" + r.group + "' is saturated, but its soil '" + soil.name +
               "' has no 'grain_diameter': the drag between soil and pore water (eq. (23)) "
               "needs the mean grain diameter D_p for the Kozeny-Carman permeability (eq. (24))",
           "water");
  r.pore_water = index;
}

void read_regions(const TomlTable& root, Scene& scene) {
  std::vector<std::string> material_names;
  for (const auto& m : scene.materials) material_names.push_back(m.name);
  std::set<std::string> groups;
  const std::vector<TomlTable> region_tables = root.tables("region");
  for (const TomlTable& t : region_tables) {
    Region r;
    r.group = t.string("group");
    r.group_line = t.line_of("group");
    if (!groups.insert(r.group).second)
      t.fail("two [[region]] entries fill group '" + r.group + "'", "group");
    const std::string material = t.string("material");
    auto it = std::find(material_names.begin(), material_names.end(), material);
    if (it == material_names.end())
      t.fail("region '" + r.group + "' uses material '" + material +
                 "', which no [[material]] defines (defined: " + quoted_list(material_names) + ")",
             "material");
    r.material = static_cast<std::size_t>(it - material_names.begin());
    // Solid points come only from soils, liquid points only from water.
    if (scene.materials[r.material].is_liquid())
      read_free_water_region(t, scene, r);
    else
      read_soil_region(t, scene, r);
    t.finish();
    scene.regions.push_back(r);
  }
  if (scene.regions.empty())
    root.fail("no [[region]] given: name at least one physical group to fill with material");
  // With water anywhere in the scene, a dry soil may meet it too (a slide entering a lake):
  // the drag of eq. (23) then needs every soil's grain diameter, eq. (24).
  bool has_water = false;
  for (const Region& r : scene.regions)
    has_water = has_water || scene.materials[r.material].is_liquid() || r.pore_water;
  for (std::size_t k = 0; k < scene.regions.size() && has_water; ++k) {
    const solver::Material& m = scene.materials[scene.regions[k].material];
    if (!m.is_liquid() && !(m.grain_diameter > 0))
      region_tables[k].fail("region '" + scene.regions[k].group + "' is soil '" + m.name +
                                "' without 'grain_diameter', and the scene has water: the drag "
                                "between soil and water (eq. (23)) needs the mean grain "
                                "diameter D_p for the Kozeny-Carman permeability (eq. (24))",
                            "material");
  }
}

// A `contact` wall with `rough = "<soil>"`: its friction is the soil's own stress ratio on a
// velocity discontinuity (solver::rough_wall_friction, Davis 1968), so a sweep of the soil's
// angles carries the wall along. Written to the case as the number.
void resolve_rough_wall(const TomlTable& t, const Scene& scene, solver::BoundaryCondition& b) {
  if (b.rough.empty()) return;
  const auto m = std::find_if(scene.materials.begin(), scene.materials.end(),
                              [&](const solver::Material& x) { return x.name == b.rough; });
  if (m == scene.materials.end()) {
    std::vector<std::string> names;
    for (const auto& x : scene.materials) names.push_back(x.name);
    t.fail("'rough' names no [[material]] \"" + b.rough +
               "\" (the scene has: " + quoted_list(names) + ")",
           "rough");
  }
  if (m->model != solver::MaterialModel::kMohrCoulomb)
    t.fail("'rough' = \"" + b.rough +
               "\" is not a mohr-coulomb soil: a rough wall takes its friction from the soil's "
               "friction and dilatancy angles (give 'friction' instead)",
           "rough");
  b.friction = solver::rough_wall_friction(m->friction_angle, m->dilatancy_angle);
}

void read_boundaries_and_stages(const TomlTable& root, Scene& scene) {
  std::set<std::string> names;
  for (const TomlTable& t : root.tables("boundary")) {
    scene.boundaries.push_back(solver::read_boundary(t, scene.dimension));
    resolve_rough_wall(t, scene, scene.boundaries.back());
    scene.boundary_group_lines.push_back(t.line_of("group"));
    if (!names.insert(scene.boundaries.back().name).second)
      t.fail("two [[boundary]] entries are named '" + scene.boundaries.back().name +
                 "' (give one a different 'name')",
             t.has("name") ? "name" : "group");
  }
  const std::vector<TomlTable> stage_tables = root.tables("stage");
  for (const TomlTable& t : stage_tables) scene.stages.push_back(solver::read_stage(t));
  if (scene.stages.empty()) root.fail("no [[stage]] given: nothing to run");
  solver::check_stage_boundaries(scene.stages, scene.boundaries, stage_tables);
  if (auto s = root.optional_table("solver")) scene.solver = solver::read_solver_settings(*s);
  if (auto o = root.optional_table("output")) scene.output = solver::read_output_settings(*o);
}

// [[probe]]: read here with the regions known, so that a water field in a dry scene is refused
// at its line; whether a position lies in the mesh or a point id exists is checked once the
// mesh and points are made (check_probes).
void read_probes(const TomlTable& root, Scene& scene) {
  const std::vector<TomlTable> tables = root.tables("probe");
  for (const TomlTable& t : tables) {
    scene.probes.push_back(solver::read_probe(t, scene.dimension, scene.has_water()));
    const solver::Probe& p = scene.probes.back();
    scene.probe_lines.push_back(
        t.line_of(p.follows == solver::Probe::Follows::kPosition     ? "position"
                  : p.follows == solver::Probe::Follows::kSolidPoint ? "solid_point"
                                                                     : "liquid_point"));
  }
  solver::check_probe_names(scene.probes, tables);
}

// [[sponge]]: the zone and rate are checked here; that the zone holds water, and the default
// rate from its depth, once the liquid points are seeded (resolve_sponges).
void read_sponges(const TomlTable& root, Scene& scene) {
  for (const TomlTable& t : root.tables("sponge")) {
    if (!scene.has_water())
      t.fail(
          "a [[sponge]] damps the water at a tank end, and the scene has no water (no region "
          "of a water material, no saturated soil)");
    scene.sponges.push_back(solver::read_sponge(t, false));
    scene.sponge_lines.push_back(t.line_of("x_start"));
  }
}

// The [post] keys that name a data file for `lituya post`. The sweep rewrites the same keys
// (scene_edit.cpp) to absolute paths.
constexpr const char* kPostDataKeys[] = {"reference", "gauge_reference"};

// Names a case folder holds besides the copied data files (see case_writer.hpp).
bool is_case_file_name(const std::string& name) {
  for (const char* taken : {kGeometryFile, kPointsFile, kLiquidPointsFile, kMaterialsFile,
                            kStagesFile, kPostFile, "output", "post"})
    if (name == taken) return true;
  return false;
}

// Checks the file `key` names (relative to the scene file), so a missing or unreadable one
// stops `lituya pre` instead of `lituya post` after the solve, and records it for copying.
void add_post_data_file(const TomlTable& post, const fs::path& scene_file, const char* key,
                        PostSettings& settings) {
  const std::string name = post.string(key);
  const std::string where = std::string("'post.") + key + "' = \"" + name + "\"";
  if (name.empty()) post.fail(where + " is empty: name a CSV file or remove the key", key);
  const fs::path file = scene_file.parent_path() / name;
  const std::string looked_for =
      " (looked for " + file.string() + "; the path is relative to the scene file)";
  std::error_code error;  // e.g. a symbolic link loop: reported, not thrown
  if (!fs::exists(file, error)) post.fail(where + ": file not found" + looked_for, key);
  if (!fs::is_regular_file(file, error))
    post.fail(where + " is not a regular file" + looked_for, key);
  if (!std::ifstream(file)) post.fail(where + ": the file cannot be read" + looked_for, key);

  // The copy keeps the file's name, unless that name is taken by a case file or by another
  // data file: then the key makes it unique.
  PostDataFile data{key, file, file.filename().string()};
  for (const PostDataFile& other : settings.data_files) {
    std::error_code ignored;
    if (fs::equivalent(other.source, file, ignored)) {
      data.case_name = other.case_name;  // one file named twice is copied once
      break;
    }
    if (other.case_name == data.case_name) data.case_name = std::string(key) + "_" + data.case_name;
  }
  if (is_case_file_name(data.case_name)) data.case_name = std::string(key) + "_" + data.case_name;
  settings.table.insert_or_assign(key, data.case_name);
  settings.data_files.push_back(std::move(data));
}

// [post] is forwarded as written: `lituya post` owns its keys. The preprocessor checks only
// what it knows better (stage and material names, that the data files exist and can be read),
// so such mistakes surface before any solve.
void read_post(const TomlTable& root, const fs::path& scene_file, Scene& scene) {
  const std::optional<TomlTable> post = root.optional_table("post");
  if (!post) return;
  for (const char* header : {"format", "version"})
    if (post->has(header))
      post->fail(std::string("'") + header + "' is written by lituya pre; remove it from [post]",
                 header);
  PostSettings settings;
  // TomlTable validates but does not expose the table, so take the copy from a second parse
  // (the file parsed once already, so it parses again).
  const toml::table whole = toml::parse_file(scene_file.string());
  settings.table = *whole["post"].as_table();
  // Both keys name the output series `lituya post` opens (<stage>_points.pvd,
  // <liquid_stage>_liquid.pvd), so they must be stage names, which are safe in file names.
  for (const char* key : {"stage", "liquid_stage"}) {
    if (!post->has(key)) continue;
    const std::string stage = post->string(key);
    bool found = false;
    for (const auto& s : scene.stages) found = found || s.name == stage;
    if (!found)
      post->fail(std::string("'post.") + key + "' = " + quoted_for_message(stage) +
                     " is not a [[stage]] name",
                 key);
  }
  if (post->has("track_materials")) {
    for (const std::string& name : post->strings("track_materials")) {
      bool found = false;
      for (const auto& m : scene.materials) found = found || m.name == name;
      if (!found)
        post->fail("'post.track_materials' names \"" + name + "\", which is not a [[material]]",
                   "track_materials");
    }
  }
  for (const char* key : kPostDataKeys)
    if (post->has(key)) add_post_data_file(*post, scene_file, key, settings);
  // Everything else `lituya post` will ask of this table (a slope frame for a slide, a still
  // water level for gauges, unknown keys), checked now at the scene's lines: found only at
  // the post step, such an error came after the whole solve (or, in a sweep, after every run).
  post::read_post_table(*post, scene_file);
  scene.post = std::move(settings);
}

// `lituya post` reads some fields of the output: a field selection in [output] that leaves one
// of them out would let the whole solve run for nothing. Refused here, at the [output] key.
void check_output_serves_post(const TomlTable& root, const Scene& scene) {
  const std::optional<TomlTable> output = root.optional_table("output");
  if (!output || !scene.post) return;
  const toml::table& post = scene.post->table;
  const solver::OutputSettings& o = scene.output;
  auto refuse = [&](const char* key, const std::string& field, const std::string& why) {
    output->fail(std::string("'") + key + "' leaves out \"" + field + "\", which `lituya post` " +
                     why + ": add it, or remove the [post] key that asks for it",
                 key);
  };
  const toml::array* tracked = post["track_materials"].as_array();
  if (tracked && !tracked->empty() && scene.materials.size() > 1 &&
      !o.writes(o.point_fields, "material"))
    refuse("point_fields", "material",
           "needs to tell the materials of [post] track_materials apart");
  const toml::array* gauges = post["gauges"].as_array();
  const bool measures_water = (gauges && !gauges->empty()) || post["leading_wave"].value_or(false);
  if (!measures_water) return;
  if (!o.writes(o.liquid_fields, "volume"))
    refuse("liquid_fields", "volume",
           "needs to place the water surface ([post] gauges, leading_wave)");
  if (post["surface_min_porosity"].value_or(0.9) > 0 && !o.writes(o.liquid_fields, "porosity"))
    refuse("liquid_fields", "porosity",
           "needs to tell pore water from free water at the surface ([post] gauges, leading_wave; "
           "surface_min_porosity = 0 counts all water)");
}

}  // namespace

const solver::Material* Scene::water_of(const Region& r) const {
  if (is_free_water(r)) return &materials[r.material];
  return r.pore_water ? &materials[*r.pore_water] : nullptr;
}

bool Scene::has_water() const {
  for (const Region& r : regions)
    if (water_of(r)) return true;
  return false;
}

Scene read_scene(const fs::path& scene_file) {
  const TomlDocument document(scene_file);
  const TomlTable root = document.root();
  TomlDocument::check_header(root, "lituya-scene", 1);
  Scene scene;
  scene.file = document.file();
  scene.title = root.string_or("title", "");
  read_mesh_table(root, scene_file, scene);
  read_materials(root, scene);
  read_regions(root, scene);
  read_boundaries_and_stages(root, scene);
  read_probes(root, scene);
  read_sponges(root, scene);
  read_post(root, scene_file, scene);
  check_output_serves_post(root, scene);
  root.finish();
  return scene;
}

namespace {
[[noreturn]] void missing_group(const Scene& scene, const Mesh& mesh, const std::string& what,
                                const std::string& group, int group_dim, int line) {
  std::string message = what + " group '" + group + "' is not a physical group of dimension " +
                        std::to_string(group_dim) + " in " + scene.geometry.filename().string();
  for (int other = 0; other <= 3; ++other)
    if (other != group_dim && mesh.find_group(group, other))
      message += " (it is a group of dimension " + std::to_string(other) + ")";
  message += "; the geometry's groups of dimension " + std::to_string(group_dim) +
             " are: " + mesh.group_names(group_dim);
  throw InputError(scene.file, line, message);
}
}  // namespace

void check_scene_groups(const Scene& scene, const Mesh& mesh) {
  const int dim = scene.dimension;
  const std::string geometry = scene.geometry.filename().string();

  std::vector<int> owner(mesh.cell_count(), -1);  // region filling each cell
  for (std::size_t r = 0; r < scene.regions.size(); ++r) {
    const Region& region = scene.regions[r];
    const auto group = mesh.find_group(region.group, dim);
    if (!group) missing_group(scene, mesh, "region", region.group, dim, region.group_line);
    if (mesh.group_cells[*group].empty())
      throw InputError(scene.file, region.group_line,
                       "region group '" + region.group + "' has no cells in " + geometry);
    for (std::size_t cell : mesh.group_cells[*group]) {
      if (owner[cell] >= 0)
        throw InputError(scene.file, region.group_line,
                         "regions '" + scene.regions[owner[cell]].group + "' and '" + region.group +
                             "' overlap (cell of element " +
                             std::to_string(mesh.cell_element_tags[cell]) +
                             "); each cell may hold one material");
      owner[cell] = static_cast<int>(r);
    }
  }
  for (std::size_t b = 0; b < scene.boundaries.size(); ++b) {
    const auto& boundary = scene.boundaries[b];
    if (!mesh.find_group(boundary.group, dim - 1))
      missing_group(scene, mesh, "boundary", boundary.group, dim - 1,
                    scene.boundary_group_lines[b]);
  }
}

namespace {
// True when x lies in one of the mesh's simplices (barycentric coordinates all >= -1e-9), so a
// probe on a cell face or at a node counts as inside.
bool inside_mesh(const Mesh& mesh, const std::vector<double>& x) {
  const int dim = mesh.dimension;
  const int corners = mesh.nodes_per_cell();
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    const std::int64_t* nodes = &mesh.cell_nodes[c * corners];
    auto at = [&](int k, int d) { return mesh.node_xyz[3 * nodes[k] + d]; };
    // Columns of the Jacobian: edges from corner 0; solve J lambda = x - x0 by Cramer's rule.
    double j[3][3] = {}, r[3] = {};
    for (int d = 0; d < dim; ++d) {
      r[d] = x[d] - at(0, d);
      for (int k = 1; k <= dim; ++k) j[d][k - 1] = at(k, d) - at(0, d);
    }
    auto det = [&](const double(&m)[3][3]) {
      if (dim == 2) return m[0][0] * m[1][1] - m[0][1] * m[1][0];
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double volume = det(j);
    if (volume == 0) continue;
    double sum = 0;
    bool inside = true;
    for (int k = 0; k < dim && inside; ++k) {
      double m[3][3];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) m[a][b] = b == k ? r[a] : j[a][b];
      const double lambda = det(m) / volume;
      inside = lambda >= -1e-9;
      sum += lambda;
    }
    if (inside && 1.0 - sum >= -1e-9) return true;
  }
  return false;
}
}  // namespace

void check_probes(const Scene& scene, const Mesh& mesh, std::size_t solid_points,
                  std::size_t liquid_points) {
  for (std::size_t i = 0; i < scene.probes.size(); ++i) {
    const solver::Probe& p = scene.probes[i];
    const int line = scene.probe_lines[i];
    if (p.follows == solver::Probe::Follows::kPosition) {
      if (!inside_mesh(mesh, p.position)) {
        std::string where;
        for (double x : p.position) where += (where.empty() ? "" : ", ") + std::to_string(x);
        throw InputError(scene.file, line,
                         "probe '" + p.name + "' at (" + where + ") lies outside the mesh of " +
                             scene.geometry.filename().string());
      }
      continue;
    }
    const bool solid = p.follows == solver::Probe::Follows::kSolidPoint;
    const std::size_t count = solid ? solid_points : liquid_points;
    if (static_cast<std::size_t>(p.point_id) >= count)
      throw InputError(scene.file, line,
                       "probe '" + p.name + "' rides on " + (solid ? "solid" : "liquid") +
                           " point " + std::to_string(p.point_id) + ", but the scene has " +
                           std::to_string(count) + " " + (solid ? "solid" : "liquid") +
                           " points (ids 0 to " + std::to_string(count) + " - 1)");
  }
}

void resolve_sponges(Scene& scene, const LiquidPoints& liquid) {
  const double g = std::sqrt(
      std::inner_product(scene.gravity.begin(), scene.gravity.end(), scene.gravity.begin(), 0.0));
  const double exponent = 1.0 / scene.dimension;
  for (std::size_t k = 0; k < scene.sponges.size(); ++k) {
    solver::Sponge& sponge = scene.sponges[k];
    const double lo = std::min(sponge.x_start, sponge.x_end);
    const double hi = std::max(sponge.x_start, sponge.x_end);
    // Depth: the span of the liquid points in the zone along y, each point counted with half
    // its spacing above and below (a point's volume is its spacing to the power dimension).
    double bottom = 1e300, top = -1e300;
    for (std::size_t p = 0; p < liquid.volume.size(); ++p) {
      const double x = liquid.position[3 * p], y = liquid.position[3 * p + 1];
      if (x < lo || x > hi) continue;
      const double half = 0.5 * std::pow(liquid.volume[p], exponent);
      bottom = std::min(bottom, y - half);
      top = std::max(top, y + half);
    }
    if (!(top > bottom))
      throw InputError(scene.file, scene.sponge_lines[k],
                       "the [[sponge]] from x = " + std::to_string(sponge.x_start) + " to " +
                           std::to_string(sponge.x_end) +
                           " m holds no water: place it over the water at a tank end");
    if (sponge.damping_rate == 0 && g > 0)
      sponge.damping_rate = solver::kDefaultSpongeStrength * std::sqrt(g / (top - bottom));
    if (sponge.damping_rate == 0)
      throw InputError(scene.file, scene.sponge_lines[k],
                       "the scene has no gravity, so the [[sponge]] needs a 'damping_rate' (1/s)");
  }
}

}  // namespace lituya::pre
