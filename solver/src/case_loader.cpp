#include "lituya/solver/case_loader.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>

#include "lituya/common/input_error.hpp"

namespace lituya::solver {

namespace {

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::string& file, bool may_be_empty = false) {
  if (!std::filesystem::exists(file))
    throw InputError(file, 0, "not found: is this a case folder written by `lituya pre`?");
  vtkObject::GlobalWarningDisplayOff();
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || !grid || (!may_be_empty && grid->GetNumberOfPoints() == 0))
    throw InputError(file, 0, "cannot be read as a VTK XML unstructured grid (.vtu) with points");
  return grid;
}

vtkDataArray* required_array(vtkUnstructuredGrid* grid, bool point_data, const char* name,
                             int components, const std::string& file) {
  vtkDataArray* a =
      point_data ? grid->GetPointData()->GetArray(name) : grid->GetCellData()->GetArray(name);
  if (!a)
    throw InputError(
        file, 0,
        std::string("missing ") + (point_data ? "point" : "cell") + " data array '" + name + "'");
  if (a->GetNumberOfComponents() != components)
    throw InputError(file, 0,
                     std::string("array '") + name + "' must have " + std::to_string(components) +
                         " components, has " + std::to_string(a->GetNumberOfComponents()));
  return a;
}

// liquid_points.vtu: the water points with their water volume, mass and pressure.
template <int dim>
void read_liquid_points(const CaseDescription& description, LiquidPoints<dim>& liquid) {
  const std::string& file = description.liquid_points_file;
  auto cloud = read_vtu(file);
  const vtkIdType n = cloud->GetNumberOfPoints();
  liquid.resize(static_cast<std::size_t>(n));
  vtkDataArray* material = required_array(cloud, true, "material", 1, file);
  vtkDataArray* volume = required_array(cloud, true, "volume", 1, file);
  vtkDataArray* mass = required_array(cloud, true, "mass", 1, file);
  vtkDataArray* pressure = required_array(cloud, true, "pressure", 1, file);
  vtkDataArray* velocity = cloud->GetPointData()->GetArray("velocity");
  vtkDataArray* cell = cloud->GetPointData()->GetArray("cell");
  for (vtkIdType q = 0; q < n; ++q) {
    double x[3];
    cloud->GetPoint(q, x);
    for (int d = 0; d < dim; ++d) liquid.position[q](d) = x[d];
    liquid.id[q] = static_cast<int>(q);
    liquid.material[q] = static_cast<int>(material->GetTuple1(q));
    if (liquid.material[q] < 0 ||
        liquid.material[q] >= static_cast<int>(description.materials.size()) ||
        !description.materials[liquid.material[q]].is_liquid())
      throw InputError(file, 0,
                       "liquid point " + std::to_string(q) + " has material " +
                           std::to_string(liquid.material[q]) +
                           ", not a water material of materials.toml");
    liquid.volume[q] = volume->GetTuple1(q);
    liquid.mass[q] = mass->GetTuple1(q);
    if (!(liquid.volume[q] > 0) || !(liquid.mass[q] > 0))
      throw InputError(file, 0,
                       "liquid point " + std::to_string(q) + " has non-positive volume or mass");
    liquid.pressure[q] = pressure->GetTuple1(q);
    if (!(liquid.pressure[q] >= 0))
      throw InputError(file, 0,
                       "liquid point " + std::to_string(q) +
                           " has a negative or invalid pressure (compression positive, >= 0)");
    if (velocity && velocity->GetNumberOfComponents() == 3) {
      const double* v = velocity->GetTuple(q);
      for (int d = 0; d < dim; ++d) liquid.velocity[q](d) = v[d];
    }
    liquid.cell[q] = cell ? static_cast<int>(cell->GetTuple1(q)) : -1;
  }
}

}  // namespace

template <int dim>
LoadedCase<dim> load_case(const CaseDescription& description) {
  LoadedCase<dim> loaded;
  const std::string& gfile = description.geometry_file;
  auto grid = read_vtu(gfile);
  Mesh<dim>& mesh = loaded.mesh;
  const vtkIdType n_nodes = grid->GetNumberOfPoints();
  mesh.node_position.resize(n_nodes);
  for (vtkIdType i = 0; i < n_nodes; ++i) {
    double x[3];
    grid->GetPoint(i, x);
    for (int d = 0; d < dim; ++d) mesh.node_position[i](d) = x[d];
  }
  vtkDataArray* group = required_array(grid, false, "group", 1, gfile);
  const int volume_type = dim == 2 ? 5 : 10;  // VTK_TRIANGLE, VTK_TETRA
  const int facet_type = dim == 2 ? 3 : 5;    // VTK_LINE, VTK_TRIANGLE
  std::vector<std::vector<std::array<int, dim>>> facets_of_group(description.groups.size());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    const int type = grid->GetCellType(c);
    grid->GetCellPoints(c, ids);
    if (type == volume_type && ids->GetNumberOfIds() == dim + 1) {
      typename Mesh<dim>::CellNodes nodes;
      for (int k = 0; k <= dim; ++k) nodes[k] = static_cast<int>(ids->GetId(k));
      mesh.cell_nodes.push_back(nodes);
    } else if (type == facet_type && ids->GetNumberOfIds() == dim) {
      const int g = static_cast<int>(group->GetTuple1(c));
      if (g < 0 || g >= static_cast<int>(facets_of_group.size()))
        throw InputError(gfile, 0,
                         "boundary facet " + std::to_string(c) + " has group " + std::to_string(g) +
                             ", not a group of stages.toml");
      std::array<int, dim> f;
      for (int k = 0; k < dim; ++k) f[k] = static_cast<int>(ids->GetId(k));
      facets_of_group[g].push_back(f);
    } else {
      throw InputError(
          gfile, 0,
          "cell " + std::to_string(c) + " has VTK type " + std::to_string(type) + "; a " +
              std::to_string(dim) + "D case expects linear " +
              (dim == 2 ? "triangles (5) and lines (3)" : "tetrahedra (10) and triangles (5)"));
    }
  }
  if (mesh.cell_nodes.empty())
    throw InputError(gfile, 0, "has no background cells of dimension " + std::to_string(dim));
  const int invalid = mesh.build();
  if (invalid >= 0)
    throw InputError(gfile, 0,
                     "background cell " + std::to_string(invalid) +
                         " is inverted or degenerate (volume " +
                         std::to_string(mesh.cell_volume[invalid]) +
                         "); fix the mesh (gmsh: check element orientation)");

  // Boundary conditions from the facets of their groups.
  for (const BoundaryCondition& bc : description.boundaries) {
    int g = -1;
    for (std::size_t i = 0; i < description.groups.size(); ++i)
      if (description.groups[i].name == bc.group) g = static_cast<int>(i);
    if (g < 0) throw InputError(gfile, 0, "no group '" + bc.group + "' for boundary " + bc.name);
    loaded.constraints.push_back(make_constraint<dim>(bc, facets_of_group[g], mesh, gfile));
  }

  // Material points (a water-only case has none).
  const std::string& pfile = description.points_file;
  const bool has_liquid = !description.liquid_points_file.empty();
  auto cloud = read_vtu(pfile, has_liquid);
  const vtkIdType n = cloud->GetNumberOfPoints();
  MaterialPoints<dim>& points = loaded.points;
  points.resize(static_cast<std::size_t>(n));
  vtkDataArray* material = required_array(cloud, true, "material", 1, pfile);
  vtkDataArray* volume = required_array(cloud, true, "volume", 1, pfile);
  vtkDataArray* mass = required_array(cloud, true, "mass", 1, pfile);
  vtkDataArray* stress = required_array(cloud, true, "stress", 6, pfile);
  vtkDataArray* velocity = cloud->GetPointData()->GetArray("velocity");
  vtkDataArray* cell = cloud->GetPointData()->GetArray("cell");
  for (vtkIdType p = 0; p < n; ++p) {
    double x[3];
    cloud->GetPoint(p, x);
    for (int d = 0; d < dim; ++d) points.position[p](d) = x[d];
    points.id[p] = static_cast<int>(p);
    points.material[p] = static_cast<int>(material->GetTuple1(p));
    if (points.material[p] < 0 ||
        points.material[p] >= static_cast<int>(description.materials.size()) ||
        description.materials[points.material[p]].is_liquid())
      throw InputError(pfile, 0,
                       "point " + std::to_string(p) + " has material " +
                           std::to_string(points.material[p]) +
                           ", not a soil material of materials.toml");
    points.volume[p] = volume->GetTuple1(p);
    points.mass[p] = mass->GetTuple1(p);
    if (!(points.volume[p] > 0) || !(points.mass[p] > 0))
      throw InputError(pfile, 0, "point " + std::to_string(p) + " has non-positive volume or mass");
    const double* s = stress->GetTuple(p);
    for (int k = 0; k < 6; ++k) points.stress[p](k) = s[k];
    if (velocity && velocity->GetNumberOfComponents() == 3) {
      const double* v = velocity->GetTuple(p);
      for (int d = 0; d < dim; ++d) points.velocity[p](d) = v[d];
    }
    points.cell[p] = cell ? static_cast<int>(cell->GetTuple1(p)) : -1;
  }
  if (has_liquid) read_liquid_points(description, loaded.liquid);
  return loaded;
}

template LoadedCase<2> load_case<2>(const CaseDescription&);
template LoadedCase<3> load_case<3>(const CaseDescription&);

}  // namespace lituya::solver
