#pragma once
// Reading the case's VTU files back with VTK in the preprocessor tests.
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

namespace lituya::pre::testing {

inline vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::filesystem::path& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetErrorCode(), 0) << file;
  return reader->GetOutput();
}

// The point data array `name`, expected with `components` components.
inline vtkDataArray* point_array(vtkUnstructuredGrid* grid, const char* name, int components) {
  vtkDataArray* a = grid->GetPointData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  if (a) {
    EXPECT_EQ(a->GetNumberOfComponents(), components) << name;
  }
  return a;
}

inline double sum_of(vtkDataArray* a) {
  double s = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) s += a->GetComponent(i, 0);
  return s;
}

// Barycentric coordinates of point p in cell c of the geometry (2D triangles or tetrahedra).
inline std::vector<double> barycentric(vtkUnstructuredGrid* geometry, vtkIdType cell,
                                       const double* p, int dimension) {
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  vtkNew<vtkIdList> list;
  geometry->GetCellPoints(cell, list);
  n = list->GetNumberOfIds();
  ids = list->GetPointer(0);
  double x[4][3];
  for (int i = 0; i < n; ++i) geometry->GetPoint(ids[i], x[i]);
  auto det3 = [](const double* a, const double* b, const double* c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
  };
  if (dimension == 2) {
    auto area = [](const double* a, const double* b, const double* c) {
      return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    };
    const double total = area(x[0], x[1], x[2]);
    return {area(p, x[1], x[2]) / total, area(x[0], p, x[2]) / total, area(x[0], x[1], p) / total};
  }
  auto volume = [&](const double* a, const double* b, const double* c, const double* d) {
    double e1[3], e2[3], e3[3];
    for (int k = 0; k < 3; ++k) {
      e1[k] = b[k] - a[k];
      e2[k] = c[k] - a[k];
      e3[k] = d[k] - a[k];
    }
    return det3(e1, e2, e3);
  };
  const double total = volume(x[0], x[1], x[2], x[3]);
  return {volume(p, x[1], x[2], x[3]) / total, volume(x[0], p, x[2], x[3]) / total,
          volume(x[0], x[1], p, x[3]) / total, volume(x[0], x[1], x[2], p) / total};
}

}  // namespace lituya::pre::testing
