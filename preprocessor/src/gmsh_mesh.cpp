#include "lituya/pre/gmsh_mesh.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>
#include <vector>

#include <gmsh.h>

#include "lituya/common/input_error.hpp"

namespace lituya::pre {

namespace {

// gmsh is a global singleton: every read opens one session and always closes it, also when
// an error leaves this function, so the next read (or a test) starts from a clean state.
class GmshSession {
 public:
  explicit GmshSession(bool verbose) {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    // Without --verbose gmsh stays silent: its errors reach the user as InputErrors with the
    // file and line, and its progress would bury Lituya's own lines. With it, gmsh prints up
    // to its info level (5: what it reads, each meshing step and its time, warnings), stated
    // so that it does not depend on the version's default.
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
    if (verbose) gmsh::option::setNumber("General.Verbosity", 5);
    // Make every gmsh error an exception (the API default, stated so it does not depend on
    // the version), which read_gmsh_mesh turns into an InputError.
    gmsh::option::setNumber("General.AbortOnError", 2);
  }
  ~GmshSession() {
    try {
      gmsh::finalize();
    } catch (...) {
      // Nothing sensible to do while unwinding; the process keeps going without gmsh.
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

// gmsh's messages look like "'path/case.geo', line 12: syntax error (;)". The line becomes
// the InputError's line when the message is about the file the user gave (not an included
// one), so the error reads like every other Lituya error: file:line: what.
InputError gmsh_error(const std::filesystem::path& geometry, const std::string& message) {
  static const std::regex located(R"(^'([^']*)', line (\d+)\s*:\s*(.*)$)");
  std::smatch m;
  if (std::regex_search(message, m, located) &&
      std::filesystem::path(m[1].str()).filename() == geometry.filename())
    return InputError(geometry.string(), std::stoi(m[2].str()), "gmsh: " + m[3].str());
  return InputError(geometry.string(), 0, "gmsh: " + message);
}

// The geometry's lines with comments blanked out (strings kept), so that a search for a
// statement finds its line and not a commented-out copy.
std::vector<std::string> uncommented_lines(const std::filesystem::path& geometry) {
  std::ifstream in(geometry);
  std::vector<std::string> lines;
  bool in_block = false;
  for (std::string line; std::getline(in, line);) {
    bool in_string = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (in_block) {
        if (line.compare(i, 2, "*/") == 0) {
          in_block = false;
          line[i] = line[i + 1] = ' ';
          ++i;
        } else {
          line[i] = ' ';
        }
      } else if (line[i] == '"') {
        in_string = !in_string;
      } else if (!in_string && line.compare(i, 2, "//") == 0) {
        line.erase(i);
      } else if (!in_string && line.compare(i, 2, "/*") == 0) {
        in_block = true;
        line[i] = line[i + 1] = ' ';
        ++i;
      }
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

// 1-based line of the last statement of the geometry (the file itself, not what it includes)
// that matches `statement`; 0 when there is none (e.g. it comes from an included file).
int line_matching(const std::filesystem::path& geometry, const std::regex& statement) {
  const std::vector<std::string> lines = uncommented_lines(geometry);
  for (std::size_t k = lines.size(); k-- > 0;)
    if (std::regex_search(lines[k], statement)) return static_cast<int>(k) + 1;
  return 0;
}

// gmsh logs "Meshing surface 2 (Plane, Frontal-Delaunay)" before it meshes an entity, and its
// meshing errors rarely say which entity they are about: the last such line before the error
// does. Returns e.g. {"surface", 2}, or an empty kind.
std::pair<std::string, int> entity_being_meshed(const std::vector<std::string>& log,
                                                std::size_t error) {
  static const std::regex meshing(R"(^Info: Meshing (curve|surface|volume) (\d+))");
  std::smatch m;
  for (std::size_t k = error; k-- > 0;)
    if (std::regex_search(log[k], m, meshing)) return {m[1].str(), std::stoi(m[2].str())};
  return {"", 0};
}

// Line of the statement that defines entity `tag` in the geometry (built-in kernel names and
// the common OpenCASCADE shapes), or 0.
int definition_line(const std::filesystem::path& geometry, const std::string& kind, int tag) {
  const std::string shapes = kind == "curve"     ? "Line|Circle|Ellipse|Spline|BSpline|Bezier|Curve"
                             : kind == "surface" ? "Plane Surface|Surface|Rectangle|Disk"
                                                 : "Volume|Box|Sphere|Cylinder|Cone|Wedge|Torus";
  return line_matching(geometry, std::regex(R"(^\s*(?:)" + shapes + R"()\s*\(\s*)" +
                                            std::to_string(tag) + R"(\s*\)\s*=)"));
}

// Runs `gmsh_call` (opening or meshing the model) with gmsh's errors logged rather than
// thrown, then throws the first logged error as an InputError. Two reasons not to let gmsh
// throw here: a throw from inside its .geo parser leaves the lexer reading the closed file,
// and every later parse in this process fails; and gmsh meshes inside OpenMP parallel
// regions, from which an exception cannot escape: the process terminates (abort, exit 134),
// whatever the number of threads.
template <class GmshCall>
void call_without_throwing(const std::filesystem::path& geometry, GmshCall gmsh_call) {
  struct LoggedErrors {
    LoggedErrors() {
      gmsh::logger::start();
      gmsh::option::setNumber("General.AbortOnError", 0);
    }
    ~LoggedErrors() {
      try {
        gmsh::option::setNumber("General.AbortOnError", 2);
        gmsh::logger::stop();
      } catch (...) {
        // Only reached while another error unwinds; the session is closed right after.
      }
    }
  } logged;
  gmsh_call();
  std::vector<std::string> log;
  gmsh::logger::get(log);
  for (std::size_t k = 0; k < log.size(); ++k) {
    if (log[k].rfind("Error: ", 0) != 0) continue;
    const std::string message = log[k].substr(7);
    const auto [kind, tag] = entity_being_meshed(log, k);
    // A parse error names its own file and line; a meshing error gets the entity.
    if (kind.empty() || message.rfind("'", 0) == 0) throw gmsh_error(geometry, message);
    throw InputError(
        geometry.string(), definition_line(geometry, kind, tag),
        "gmsh: " + message + " (while meshing " + kind + " " + std::to_string(tag) + ")");
  }
}

// gmsh 4.8's algorithms for quadrangles and hexahedra need a cross field (frame field) that
// it never builds when driven through its API: Mesh.Algorithm = 8 (Frontal-Delaunay for
// quads; also per surface with MeshAlgorithm Surface {...} = 8) and Mesh.Algorithm3D = 9
// (R-tree) crash the process (segmentation fault) on any geometry, so no error handling can
// catch them. Lituya needs triangles and tetrahedra anyway, so they are refused before
// meshing instead of replaced: the .geo then meshes the same in Lituya as in gmsh's GUI.
void refuse_crashing_algorithms(const std::filesystem::path& geometry, int dimension) {
  std::string version;
  gmsh::option::getString("General.Version", version);
  std::string advice = ": it is meant for quadrangle/hexahedral meshes and crashes the gmsh ";
  advice += "library Lituya uses (gmsh " + version + "), while Lituya needs linear triangles ";
  advice += "(2D) or tetrahedra (3D). Remove the option, or choose a triangle algorithm, e.g. ";
  // The global options gmsh can read back, each with the value that crashes and the fix.
  struct Crashing {
    const char* option;
    double value;
    int dimension;  // 2: checked in 2D and 3D; 3: only in 3D
    const char* what;
    const char* instead;
  };
  static const Crashing options[] = {
      {"Mesh.Algorithm", 8, 2, "Frontal-Delaunay for quads",
       "Mesh.Algorithm = 6 (Frontal-Delaunay, gmsh's default)"},
      {"Mesh.Algorithm3D", 9, 3, "R-tree", "Mesh.Algorithm3D = 1 (Delaunay, gmsh's default)"},
  };
  for (const Crashing& c : options) {
    if (c.dimension > dimension) continue;
    double value = 0;
    gmsh::option::getNumber(c.option, value);
    if (value != c.value) continue;
    const std::string name = c.option;
    const std::string pattern =
        "\\b" + std::regex_replace(name, std::regex("\\."), "\\.") + "\\s*=";
    throw InputError(geometry.string(), line_matching(geometry, std::regex(pattern)),
                     name + " = " + std::to_string(static_cast<int>(c.value)) + " (" + c.what +
                         ") is not supported" + advice + c.instead);
  }
  // The value of a per-surface algorithm cannot be read back through gmsh's API, so only a
  // literal 8 in the file itself is found.
  const int per_surface =
      line_matching(geometry, std::regex(R"(\bMeshAlgorithm\s+Surface\s*\{[^}]*\}\s*=\s*8\s*;)"));
  if (per_surface > 0)
    throw InputError(geometry.string(), per_surface,
                     "MeshAlgorithm Surface {...} = 8 (Frontal-Delaunay for quads) is not "
                     "supported" +
                         advice + "6 (Frontal-Delaunay, gmsh's default)");
}

// The total area (2D) or volume (3D) of the open model's entities of dimension `dim`, before
// it is meshed. The OpenCASCADE kernel knows the exact mass of its shapes; gmsh's built-in
// kernel has no such query, so its entities count with their bounding boxes, which can only
// overestimate (exact for the rectangles and boxes most flume scenes are made of).
double model_measure(int dim) {
  std::set<int> occ_tags;
  try {
    gmsh::vectorpair occ;
    gmsh::model::occ::getEntities(occ, dim);
    for (const auto& dim_tag : occ) occ_tags.insert(dim_tag.second);
  } catch (...) {
    // A gmsh built without OpenCASCADE: every entity is measured by its bounding box.
  }
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dim);
  double sum = 0;
  for (const auto& [entity_dim, tag] : entities) {
    if (occ_tags.count(tag) != 0) {
      double mass = 0;
      gmsh::model::occ::getMass(entity_dim, tag, mass);
      sum += std::abs(mass);
      continue;
    }
    double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
    gmsh::model::getBoundingBox(entity_dim, tag, x0, y0, z0, x1, y1, z1);
    sum += (x1 - x0) * (y1 - y0) * (dim == 3 ? z1 - z0 : 1.0);
  }
  return sum;
}

MeshSizeEstimate estimate_open_model(const MeshingOptions& options) {
  return estimate_mesh_size(model_measure(options.dimension), options.dimension, options.cell_size,
                            options.size_check.points_per_cell, options.crossed);
}

// "63208" for a count a reader can take in at a glance, "4.6e+12" beyond.
std::string about(double count) {
  std::ostringstream s;
  if (count < 1e7)
    s << std::llround(count);
  else
    s << std::setprecision(2) << count;
  return s.str();
}

std::string gigabytes(double bytes) {
  std::ostringstream s;
  s << std::setprecision(bytes < 1e9 ? 2 : 3) << bytes / 1e9;
  return s.str();
}

// Refuses, before gmsh allocates anything, a cell size that would need more memory than this
// machine has: gmsh would otherwise grow for minutes and end in bad_alloc or the kernel's
// out-of-memory killer, and take the machine's memory from everything else meanwhile.
void refuse_too_large_mesh(const std::filesystem::path& geometry, const MeshingOptions& options) {
  const MeshSizeCheck& check = options.size_check;
  if (!check.enabled) return;
  const MeshSizeEstimate e = estimate_open_model(options);
  const double available =
      check.available_bytes > 0 ? check.available_bytes : available_memory_bytes();
  if (e.bytes <= available) return;
  std::ostringstream m;
  m << "cell_size = " << options.cell_size << " would give about " << about(e.cells)
    << " cells and " << about(e.points) << " points, needing about " << gigabytes(e.bytes)
    << " GB; this machine has " << gigabytes(available)
    << " GB available (use --allow-large-mesh to try anyway)";
  const bool in_scene = !check.scene_file.empty();
  throw InputError(in_scene ? check.scene_file : geometry.string(),
                   in_scene ? check.cell_size_line : 0, m.str());
}

std::string element_name(int type) {
  std::string name;
  int dim = 0, order = 0, nodes = 0, primary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, nodes, local, primary);
  return name + " (gmsh type " + std::to_string(type) + ")";
}

// "surface 3", "volume 1": how gmsh's GUI and .geo files name geometric entities.
std::string entity_words(int dim, int tag) {
  static const char* kinds[] = {"point", "curve", "surface", "volume"};
  return std::string(kinds[std::clamp(dim, 0, 3)]) + " " + std::to_string(tag);
}

struct GmshElements {
  std::vector<std::size_t> tags;
  std::vector<std::size_t> node_tags;
};

// gmsh's elements of one geometric entity, in blocks of one element type each.
struct ElementBlocks {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, node_tags;

  ElementBlocks(int dim, int entity) {
    gmsh::model::mesh::getElements(types, tags, node_tags, dim, entity);
  }
  // Block `b` appended to `out` as it is.
  void append(std::size_t b, GmshElements& out) const {
    out.tags.insert(out.tags.end(), tags[b].begin(), tags[b].end());
    out.node_tags.insert(out.node_tags.end(), node_tags[b].begin(), node_tags[b].end());
  }
  InputError wrong_type(const std::filesystem::path& geometry, int dim, int entity, std::size_t b,
                        const std::string& what_is_expected) const {
    return InputError(geometry.string(), 0,
                      entity_words(dim, entity) + " has " + std::to_string(tags[b].size()) +
                          " elements of type " + element_name(types[b]) + "; Lituya needs " +
                          what_is_expected);
  }
};

// The elements of one geometric entity, all of `expected_type`.
GmshElements entity_elements(const std::filesystem::path& geometry, int dim, int entity,
                             int expected_type, const std::string& what_is_expected) {
  const ElementBlocks blocks(dim, entity);
  GmshElements out;
  for (std::size_t b = 0; b < blocks.types.size(); ++b) {
    if (blocks.tags[b].empty()) continue;
    if (blocks.types[b] != expected_type)
      throw blocks.wrong_type(geometry, dim, entity, b, what_is_expected);
    blocks.append(b, out);
  }
  return out;
}

std::string node_list(const std::vector<std::size_t>& gmsh_tags) {
  std::string s;
  for (std::size_t t : gmsh_tags) {
    if (!s.empty()) s += ' ';
    s += std::to_string(t);
  }
  return s;
}

// Checks the cells of one geometric entity [begin, end) and orients them positively. A 2D
// surface whose normal points to -z comes out of gmsh entirely clockwise: that is only a
// convention, so its triangles are reordered. A mix of orientations within one entity, a
// negative tetrahedron, or a cell of (almost) no size is a broken mesh.
void orient_cells(Mesh& mesh, std::size_t begin, std::size_t end, double cell_size,
                  const std::vector<std::size_t>& gmsh_node_tag,
                  const std::filesystem::path& geometry, int entity) {
  const double tiny = 1e-10 * std::pow(cell_size, mesh.dimension);
  const int corners = mesh.nodes_per_cell();
  std::size_t negative = 0, first_negative = end, first_positive = end;
  auto fail = [&](std::size_t cell, double measure, const std::string& why) {
    std::vector<std::size_t> nodes;
    for (int c = 0; c < corners; ++c)
      nodes.push_back(gmsh_node_tag[static_cast<std::size_t>(mesh.cell_nodes[cell * corners + c])]);
    std::ostringstream m;
    m << "inverted or degenerate element " << mesh.cell_element_tags[cell] << " (nodes "
      << node_list(nodes) << ") in " << entity_words(mesh.dimension, entity) << ": signed "
      << (mesh.dimension == 2 ? "area " : "volume ") << measure << ", " << why;
    throw InputError(geometry.string(), 0, m.str());
  };
  for (std::size_t cell = begin; cell < end; ++cell) {
    const double measure = signed_cell_measure(mesh, cell);
    if (std::abs(measure) <= tiny)
      fail(cell, measure, "which is (almost) zero: the cell has collapsed");
    if (measure < 0) {
      ++negative;
      if (first_negative == end) first_negative = cell;
    } else if (first_positive == end) {
      first_positive = cell;
    }
  }
  if (negative == 0) return;
  if (mesh.dimension == 3)
    fail(first_negative, signed_cell_measure(mesh, first_negative),
         "tetrahedra must have positive volume (node order right-handed)");
  if (negative != end - begin) {
    // Name a cell of the minority orientation: that is the one most likely inverted.
    const bool negatives_are_fewer = 2 * negative <= end - begin;
    const std::size_t cell = negatives_are_fewer ? first_negative : first_positive;
    fail(cell, signed_cell_measure(mesh, cell),
         "while " + std::to_string(negatives_are_fewer ? end - begin - negative : negative) +
             " of the " + std::to_string(end - begin) +
             " triangles of this surface have the opposite orientation");
  }
  for (std::size_t cell = begin; cell < end; ++cell)
    std::swap(mesh.cell_nodes[cell * corners + 1], mesh.cell_nodes[cell * corners + 2]);
}

// Node coordinates by gmsh tag. A crossed mesh adds one node at the centre of each
// quadrangle, tagged above every gmsh tag (`next_tag`), so the cells are assembled with tags
// as gmsh's are and renumbered once.
struct NodesByTag {
  std::unordered_map<std::size_t, std::array<double, 3>> xyz;
  std::size_t next_tag = 0;
};

// The point where a quadrangle's diagonals cross, or nothing when they do not (a
// non-convex or degenerate quadrangle). Why there and not at the mean of the corners: the
// four triangles' volume constraints are dependent only when the edges meeting at the centre
// lie on two straight lines (the centre is a "singular vertex"); around any other point the
// four constraints are independent and the mesh locks like any other triangle mesh.
std::optional<std::array<double, 3>> diagonals_crossing(const std::array<double, 3>& a,
                                                        const std::array<double, 3>& b,
                                                        const std::array<double, 3>& c,
                                                        const std::array<double, 3>& d) {
  // a + s (c - a) = b + t (d - b), solved by Cramer's rule in the x-y plane.
  const double ac_x = c[0] - a[0], ac_y = c[1] - a[1];
  const double bd_x = d[0] - b[0], bd_y = d[1] - b[1];
  const double ab_x = b[0] - a[0], ab_y = b[1] - a[1];
  const double det = ac_x * -bd_y - ac_y * -bd_x;
  if (det == 0) return std::nullopt;
  const double s = (ab_x * -bd_y - ab_y * -bd_x) / det;
  const double t = (ac_x * ab_y - ac_y * ab_x) / det;
  if (!(s > 0 && s < 1 && t > 0 && t < 1)) return std::nullopt;
  return std::array<double, 3>{a[0] + s * ac_x, a[1] + s * ac_y, a[2] + s * (c[2] - a[2])};
}

// The cells of one entity of a crossed mesh as linear triangles: gmsh's triangles (blossom
// recombination may leave a few) as they are, each quadrangle (corners a b c d) as the four
// triangles (a b o) (b c o) (c d o) (d a o) around the point o where its diagonals cross.
// The four keep the quadrangle's element tag, so an error about one names what gmsh wrote.
GmshElements crossed_entity_elements(const std::filesystem::path& geometry, int dim, int entity,
                                     NodesByTag& nodes) {
  const ElementBlocks blocks(dim, entity);
  const auto& tags = blocks.tags;
  const auto& node_tags = blocks.node_tags;
  GmshElements out;
  for (std::size_t t = 0; t < blocks.types.size(); ++t) {
    if (tags[t].empty()) continue;
    if (blocks.types[t] == 2) {  // 3-node triangle
      blocks.append(t, out);
      continue;
    }
    if (blocks.types[t] != 3)  // 4-node quadrangle
      throw blocks.wrong_type(geometry, dim, entity, t,
                              "linear quadrangles (gmsh type 3) or triangles (gmsh type 2) for a "
                              "crossed mesh");
    for (std::size_t q = 0; q < tags[t].size(); ++q) {
      const std::size_t* corner = &node_tags[t][4 * q];
      std::array<std::array<double, 3>, 4> x;
      for (int k = 0; k < 4; ++k) {
        const auto found = nodes.xyz.find(corner[k]);
        if (found == nodes.xyz.end())
          throw InputError(geometry.string(), 0,
                           "element " + std::to_string(tags[t][q]) + " uses node " +
                               std::to_string(corner[k]) + ", which the file does not define");
        x[k] = found->second;
      }
      const auto centre = diagonals_crossing(x[0], x[1], x[2], x[3]);
      if (!centre)
        throw InputError(geometry.string(), 0,
                         "quadrangle " + std::to_string(tags[t][q]) + " (nodes " +
                             node_list({corner, corner + 4}) + ") in " + entity_words(dim, entity) +
                             " is not convex: its diagonals do not cross, so it cannot be "
                             "cut into four triangles");
      const std::size_t centre_tag = nodes.next_tag++;
      nodes.xyz[centre_tag] = *centre;
      for (int k = 0; k < 4; ++k) {
        out.tags.push_back(tags[t][q]);
        out.node_tags.insert(out.node_tags.end(), {corner[k], corner[(k + 1) % 4], centre_tag});
      }
    }
  }
  return out;
}

Mesh read_current_model(const std::filesystem::path& geometry, const MeshingOptions& options) {
  const int dim = options.dimension;
  const int cell_type = dim == 2 ? 2 : 4;   // 3-node triangle, 4-node tetrahedron
  const int facet_type = dim == 2 ? 1 : 2;  // 2-node line, 3-node triangle
  const std::string cell_words =
      dim == 2 ? "linear triangles (gmsh type 2) in 2D (quadrangles with [mesh] crossed = true)"
               : "linear tetrahedra (gmsh type 4) in 3D";
  const std::string facet_words = dim == 2 ? "linear lines (gmsh type 1) on 2D boundaries"
                                           : "linear triangles (gmsh type 2) on 3D boundaries";
  Mesh mesh;
  mesh.dimension = dim;

  std::vector<std::size_t> all_tags;
  std::vector<double> all_xyz, parametric;
  gmsh::model::mesh::getNodes(all_tags, all_xyz, parametric, -1, -1, false, false);
  NodesByTag nodes;
  for (std::size_t i = 0; i < all_tags.size(); ++i) {
    nodes.xyz[all_tags[i]] = {all_xyz[3 * i], all_xyz[3 * i + 1], all_xyz[3 * i + 2]};
    nodes.next_tag = std::max(nodes.next_tag, all_tags[i] + 1);
  }

  // Cells, entity by entity (orientation is a per-entity matter), still with gmsh node tags.
  std::vector<std::pair<int, std::pair<std::size_t, std::size_t>>> entity_cells;
  std::vector<std::size_t> cell_gmsh_nodes;
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dim);
  for (const auto& [entity_dim, entity] : entities) {
    GmshElements e = options.crossed
                         ? crossed_entity_elements(geometry, entity_dim, entity, nodes)
                         : entity_elements(geometry, entity_dim, entity, cell_type, cell_words);
    const std::size_t begin = mesh.cell_element_tags.size();
    mesh.cell_element_tags.insert(mesh.cell_element_tags.end(), e.tags.begin(), e.tags.end());
    cell_gmsh_nodes.insert(cell_gmsh_nodes.end(), e.node_tags.begin(), e.node_tags.end());
    entity_cells.push_back({entity, {begin, mesh.cell_element_tags.size()}});
  }
  if (mesh.cell_element_tags.empty())
    throw InputError(geometry.string(), 0,
                     "the model has no elements of dimension " + std::to_string(dim) +
                         " (does it define " + (dim == 2 ? "surfaces" : "volumes") +
                         ", and is [mesh] dimension right?)");

  // Compact 0-based node numbering, in gmsh tag order, of the nodes the cells use.
  std::vector<std::size_t> gmsh_node_tag = cell_gmsh_nodes;
  std::sort(gmsh_node_tag.begin(), gmsh_node_tag.end());
  gmsh_node_tag.erase(std::unique(gmsh_node_tag.begin(), gmsh_node_tag.end()), gmsh_node_tag.end());
  std::unordered_map<std::size_t, std::int64_t> node_index;
  for (std::size_t i = 0; i < gmsh_node_tag.size(); ++i)
    node_index[gmsh_node_tag[i]] = static_cast<std::int64_t>(i);
  mesh.cell_nodes.reserve(cell_gmsh_nodes.size());
  for (std::size_t tag : cell_gmsh_nodes) mesh.cell_nodes.push_back(node_index.at(tag));

  mesh.node_xyz.assign(3 * gmsh_node_tag.size(), 0.0);
  for (std::size_t n = 0; n < gmsh_node_tag.size(); ++n) {
    const auto found = nodes.xyz.find(gmsh_node_tag[n]);
    if (found == nodes.xyz.end())
      throw InputError(geometry.string(), 0,
                       "an element uses node " + std::to_string(gmsh_node_tag[n]) +
                           ", which the file does not define");
    std::copy_n(found->second.data(), 3, &mesh.node_xyz[3 * n]);
  }
  if (dim == 2) {
    // Plane strain lives in the x-y plane.
    for (std::size_t n = 0; n < gmsh_node_tag.size(); ++n)
      if (std::abs(mesh.node_xyz[3 * n + 2]) > 1e-9 * options.cell_size)
        throw InputError(geometry.string(), 0,
                         "node " + std::to_string(gmsh_node_tag[n]) +
                             " has z = " + std::to_string(mesh.node_xyz[3 * n + 2]) +
                             ": a 2D geometry must lie in the plane z = 0");
  }

  for (const auto& [entity, range] : entity_cells)
    orient_cells(mesh, range.first, range.second, options.cell_size, gmsh_node_tag, geometry,
                 entity);

  // Physical groups: the cells of each group of dimension `dim`, the facets of each group of
  // dimension `dim - 1`; others (e.g. points) are only listed.
  gmsh::vectorpair physical;
  gmsh::model::getPhysicalGroups(physical);
  for (const auto& [group_dim, group_tag] : physical) {
    PhysicalGroup group{"", group_dim, group_tag};
    gmsh::model::getPhysicalName(group_dim, group_tag, group.name);
    if (group.name.empty()) group.name = std::to_string(group_tag);
    if (mesh.find_group(group.name, group_dim))
      throw InputError(geometry.string(), 0,
                       "two physical groups of dimension " + std::to_string(group_dim) +
                           " are named \"" + group.name + "\"");
    std::vector<std::size_t> cells;
    std::vector<std::int64_t> facets;
    std::vector<int> group_entities;
    gmsh::model::getEntitiesForPhysicalGroup(group_dim, group_tag, group_entities);
    for (int entity : group_entities) {
      if (group_dim == dim) {
        for (const auto& [e, range] : entity_cells)
          if (e == entity)
            for (std::size_t c = range.first; c < range.second; ++c) cells.push_back(c);
      } else if (group_dim == dim - 1) {
        GmshElements e = entity_elements(geometry, group_dim, entity, facet_type, facet_words);
        for (std::size_t k = 0; k < e.node_tags.size(); ++k) {
          auto it = node_index.find(e.node_tags[k]);
          if (it == node_index.end())
            throw InputError(geometry.string(), 0,
                             "physical group \"" + group.name + "\": element " +
                                 std::to_string(e.tags[k / dim]) + " uses node " +
                                 std::to_string(e.node_tags[k]) + ", which no " +
                                 std::to_string(dim) +
                                 "D cell uses (a boundary must lie on the mesh)");
          facets.push_back(it->second);
        }
      }
    }
    mesh.groups.push_back(group);
    mesh.group_cells.push_back(std::move(cells));
    mesh.group_facets.push_back(std::move(facets));
  }
  return mesh;
}

// gmsh 4.8's reader of ASCII .msh 4.1 files trusts the counts and tags of the $Nodes and
// $Elements sections: a count that does not match the blocks that follow, or a tag outside
// the declared range, crashes the process (segmentation fault or abort) inside gmsh::open,
// where no error handling can catch it. These sections are read once here first, token by
// token as gmsh reads them, and an inconsistency becomes an input error at its line. Other
// versions and binary files are left to gmsh.
class MshTokens {
 public:
  explicit MshTokens(const std::filesystem::path& file) : file_(file.string()) {
    std::ifstream in(file);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      std::istringstream words(line);
      for (std::string word; words >> word;) tokens_.emplace_back(std::move(word), number);
    }
  }
  // Moves past the first token equal to `word`; false when there is none.
  bool find(const std::string& word) {
    for (next_ = 0; next_ < tokens_.size(); ++next_)
      if (tokens_[next_].first == word) {
        ++next_;
        return true;
      }
    return false;
  }
  const std::string& word(const std::string& what) {
    if (next_ >= tokens_.size()) fail(what + " missing: the file ends early");
    return tokens_[next_++].first;
  }
  long long integer(const std::string& what, long long low, long long high) {
    const std::string& text = word(what);
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (end == text.c_str() || *end != '\0' || errno != 0)
      fail("expected an integer (" + what + "), found '" + text + "'");
    if (value < low || value > high)
      fail(what + " = " + text + " is outside [" + std::to_string(low) + ", " +
           std::to_string(high) + "]");
    return value;
  }
  void real(const std::string& what) {
    const std::string& text = word(what);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(value))
      fail("expected a finite number (" + what + "), found '" + text + "'");
  }
  void expect(const std::string& keyword) {
    const std::string& text = word(keyword);
    if (text != keyword) fail("expected " + keyword + ", found '" + text + "' (a count is wrong?)");
  }
  // The line of the last token read (0 before the first).
  int line() const { return next_ == 0 ? 0 : tokens_[std::min(next_, tokens_.size()) - 1].second; }
  // at_line: the line to report, 0 for the line of the last token read.
  [[noreturn]] void fail(const std::string& message, int at_line = 0) const {
    throw InputError(file_, at_line > 0 ? at_line : line(), "invalid .msh file: " + message);
  }

 private:
  std::string file_;
  std::vector<std::pair<std::string, int>> tokens_;
  std::size_t next_ = 0;
};

// Nodes per element of gmsh's element types (gmsh's MSH format documentation); 0: unknown.
int msh_element_nodes(long long type) {
  static const int nodes[] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13};
  return type >= 0 && type < static_cast<long long>(std::size(nodes)) ? nodes[type] : 0;
}

void check_msh_sections(const std::filesystem::path& mesh) {
  MshTokens msh(mesh);
  if (!msh.find("$MeshFormat")) return;  // gmsh reports it
  if (msh.word("version") != "4.1") return;
  if (msh.integer("file type", 0, 1) != 0) return;  // binary
  constexpr long long big = std::numeric_limits<long long>::max();
  long long node_min = 0, node_max = big;
  if (msh.find("$Nodes")) {
    const long long blocks = msh.integer("number of node blocks", 0, big);
    const long long total = msh.integer("number of nodes", 0, big);
    const int header = msh.line();
    node_min = msh.integer("smallest node tag", 0, big);
    node_max = msh.integer("largest node tag", node_min, big);
    long long sum = 0;
    for (long long b = 0; b < blocks; ++b) {
      const long long dim = msh.integer("entity dimension", 0, 3);
      msh.integer("entity tag", std::numeric_limits<long long>::min(), big);
      const long long parametric = msh.integer("parametric flag", 0, 1);
      const long long count = msh.integer("nodes in the block", 0, big);
      if (count > total - sum)
        msh.fail(
            "the blocks hold more nodes than the " + std::to_string(total) + " the header says",
            header);
      sum += count;
      for (long long k = 0; k < count; ++k) msh.integer("node tag", node_min, node_max);
      for (long long k = 0; k < count * (3 + parametric * dim); ++k) msh.real("coordinate");
    }
    if (sum != total)
      msh.fail("the node blocks hold " + std::to_string(sum) + " nodes, the header says " +
                   std::to_string(total),
               header);
    msh.expect("$EndNodes");
  }
  if (msh.find("$Elements")) {
    const long long blocks = msh.integer("number of element blocks", 0, big);
    const long long total = msh.integer("number of elements", 0, big);
    const int header = msh.line();
    const long long min = msh.integer("smallest element tag", 0, big);
    const long long max = msh.integer("largest element tag", min, big);
    long long sum = 0;
    for (long long b = 0; b < blocks; ++b) {
      msh.integer("entity dimension", 0, 3);
      msh.integer("entity tag", std::numeric_limits<long long>::min(), big);
      const long long type = msh.integer("element type", 1, big);
      const int nodes = msh_element_nodes(type);
      if (nodes == 0) msh.fail("unknown element type " + std::to_string(type));
      const long long count = msh.integer("elements in the block", 0, big);
      if (count > total - sum)
        msh.fail(
            "the blocks hold more elements than the " + std::to_string(total) + " the header says",
            header);
      sum += count;
      for (long long k = 0; k < count; ++k) {
        msh.integer("element tag", min, max);
        for (int j = 0; j < nodes; ++j) msh.integer("node tag", node_min, node_max);
      }
    }
    if (sum != total)
      msh.fail("the element blocks hold " + std::to_string(sum) + " elements, the header says " +
                   std::to_string(total),
               header);
    msh.expect("$EndElements");
  }
}

// The geometry's extension (lower case), after checking the file and the options.
std::string checked_extension(const std::filesystem::path& geometry,
                              const MeshingOptions& options) {
  std::error_code error;  // e.g. a symbolic link loop: reported, not thrown
  if (!std::filesystem::is_regular_file(geometry, error))
    throw InputError(geometry.string(), 0, "geometry file not found");
  std::string extension = geometry.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".geo" && extension != ".msh")
    throw InputError(
        geometry.string(), 0,
        "expected a gmsh .geo script or .msh mesh, found extension '" + extension + "'");
  if (options.dimension != 2 && options.dimension != 3)
    throw InputError(geometry.string(), 0, "the mesh dimension must be 2 or 3");
  // gmsh's Exit statement ends the whole process (exit code 0) while the .geo is read, so
  // `lituya pre` would stop silently without writing the case: refused before gmsh reads it.
  if (extension == ".msh") check_msh_sections(geometry);
  if (extension == ".geo") {
    const int exit_line = line_matching(geometry, std::regex(R"((^|[;)}])\s*Exit\s*;)"));
    if (exit_line > 0)
      throw InputError(geometry.string(), exit_line,
                       "the Exit statement is not supported: it ends gmsh and Lituya with it; "
                       "remove it");
  }
  return extension;
}

// Turns whatever gmsh throws into an InputError naming the geometry.
template <class GmshWork>
auto with_gmsh_errors(const std::filesystem::path& geometry, GmshWork work) {
  try {
    return work();
  } catch (const InputError&) {
    throw;
  } catch (const std::string& message) {  // how gmsh 4.8 reports errors
    throw gmsh_error(geometry, message);
  } catch (const std::exception& e) {
    throw gmsh_error(geometry, e.what());
  } catch (...) {
    std::string message;
    gmsh::logger::getLastError(message);
    throw gmsh_error(geometry, message.empty() ? "unknown gmsh error" : message);
  }
}

}  // namespace

MeshSizeEstimate estimate_gmsh_mesh(const std::filesystem::path& geometry,
                                    const MeshingOptions& options) {
  checked_extension(geometry, options);
  GmshSession session(options.verbose);
  return with_gmsh_errors(geometry, [&] {
    call_without_throwing(geometry, [&] { gmsh::open(geometry.string()); });
    return estimate_open_model(options);
  });
}

Mesh read_gmsh_mesh(const std::filesystem::path& geometry, const MeshingOptions& options) {
  const std::string extension = checked_extension(geometry, options);
  GmshSession session(options.verbose);
  return with_gmsh_errors(geometry, [&] {
    // The scene's cell size caps gmsh's element size; sizes a .geo gives its points may still
    // refine locally. Set before opening (a .geo may mesh while it is read) and after (a .geo
    // may set its own value).
    gmsh::option::setNumber("Mesh.MeshSizeMax", options.cell_size);
    if (options.seed > 0) gmsh::option::setNumber("Mesh.RandomSeed", options.seed);
    call_without_throwing(geometry, [&] { gmsh::open(geometry.string()); });
    if (extension == ".geo") {
      gmsh::option::setNumber("Mesh.MeshSizeMax", options.cell_size);
      if (options.seed > 0) gmsh::option::setNumber("Mesh.RandomSeed", options.seed);
      refuse_crashing_algorithms(geometry, options.dimension);
      refuse_too_large_mesh(geometry, options);
      // Quadrangles for a crossed mesh: gmsh's default triangulation, then recombined in
      // pairs (blossom); read_current_model cuts each at its centre.
      if (options.crossed) gmsh::option::setNumber("Mesh.RecombineAll", 1);
      call_without_throwing(geometry, [&] { gmsh::model::mesh::generate(options.dimension); });
    }
    return read_current_model(geometry, options);
  });
}

}  // namespace lituya::pre
