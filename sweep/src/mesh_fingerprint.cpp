// The numbering-free fingerprint of a case's mesh (mesh_fingerprint.hpp says why).
#include "lituya/sweep/mesh_fingerprint.hpp"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <system_error>
#include <vector>

#include "lituya/common/content_hash.hpp"

namespace lituya::sweep {

std::optional<std::uint64_t> mesh_fingerprint(const std::filesystem::path& geometry_vtu) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(geometry_vtu, error)) return std::nullopt;
  vtkObject::GlobalWarningDisplayOff();
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(geometry_vtu.string().c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || !grid || grid->GetNumberOfPoints() == 0) return std::nullopt;
  vtkDataArray* group = grid->GetCellData()->GetArray("group");
  double bounds[6];
  grid->GetBounds(bounds);
  const double extent =
      std::max({bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]});
  const double step = extent > 0 ? 1e-7 * extent : 1.0;

  // Each cell as a row of integers: its group, then its nodes' rounded x, y, z in sorted order
  // (Lituya's cells are triangles and tetrahedra: at most four nodes; a triangle's fourth is
  // zeros, sorted in with the others, the same for every triangle).
  using Node = std::array<long long, 3>;
  using Row = std::array<long long, 1 + 4 * 3>;
  std::vector<Row> cells(static_cast<std::size_t>(grid->GetNumberOfCells()));
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    grid->GetCellPoints(c, ids);
    if (ids->GetNumberOfIds() > 4) return std::nullopt;
    std::array<Node, 4> nodes{};
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      double x[3];
      grid->GetPoint(ids->GetId(k), x);
      for (int d = 0; d < 3; ++d) nodes[static_cast<std::size_t>(k)][d] = std::llround(x[d] / step);
    }
    std::sort(nodes.begin(), nodes.end());  // a triangle's unused fourth node is all zeros
    Row& row = cells[static_cast<std::size_t>(c)];
    row.fill(0);
    row[0] = group ? std::llround(group->GetComponent(c, 0)) : 0;
    for (std::size_t k = 0; k < 4; ++k)
      std::copy(nodes[k].begin(), nodes[k].end(), row.begin() + 1 + 3 * static_cast<long>(k));
  }
  std::sort(cells.begin(), cells.end());
  return fnv1a64(
      std::string_view(reinterpret_cast<const char*>(cells.data()), cells.size() * sizeof(Row)));
}

}  // namespace lituya::sweep
