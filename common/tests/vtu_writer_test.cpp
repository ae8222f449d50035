// The VTU writer is checked by reading its files back with VTK's own reader (what ParaView
// uses), so a format mistake shows up as a failed read or a wrong value.
#include "lituya/common/vtu_writer.hpp"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lituya/common/input_error.hpp"
#include "lituya/common/output_folder.hpp"

namespace {

TEST(VtuWriter, TriangleMeshRoundTripsThroughVtk) {
  lituya::VtuWriter w;
  std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  w.set_points(xyz);
  w.set_cells({0, 1, 2, 1, 3, 2, 0, 1}, {3, 6, 8},
              {static_cast<std::uint8_t>(lituya::VtkCellType::kTriangle),
               static_cast<std::uint8_t>(lituya::VtkCellType::kTriangle),
               static_cast<std::uint8_t>(lituya::VtkCellType::kLine)});
  std::vector<double> velocity = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  w.add_point_data("velocity", 3, velocity);
  std::vector<std::int32_t> group = {-1, 4, 2};
  w.add_cell_data("group", group);
  auto file = std::filesystem::temp_directory_path() / "lituya_writer_test.vtu";
  w.write(file);

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfPoints(), 4);
  ASSERT_EQ(grid->GetNumberOfCells(), 3);
  EXPECT_EQ(grid->GetCellType(2), 3);
  double p[3];
  grid->GetPoint(3, p);
  EXPECT_DOUBLE_EQ(p[0], 1.0);
  EXPECT_DOUBLE_EQ(p[1], 1.0);
  EXPECT_DOUBLE_EQ(grid->GetPointData()->GetArray("velocity")->GetComponent(2, 1), 8.0);
  EXPECT_EQ(grid->GetCellData()->GetArray("group")->GetTuple1(1), 4.0);
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
}

TEST(PvdWriter, ListsEveryEntry) {
  auto file = std::filesystem::temp_directory_path() / "lituya_writer_test.pvd";
  lituya::PvdWriter pvd(file);
  pvd.add(0.0, "a_0000.vtu");
  pvd.add(0.25, "a_0001.vtu");
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_NE(s.str().find("timestep=\"0.25\""), std::string::npos);
  EXPECT_NE(s.str().find("a_0001.vtu"), std::string::npos);
}

// Names are checked where they are read, but the writers must not rely on it: a .pvd once
// listed a stage "a&b" unescaped and was not well-formed XML. An XML parser (expat, through
// VTK) must accept the file and give the attribute back unchanged.
TEST(PvdWriter, EscapesFileNamesAndParsesBack) {
  auto file = std::filesystem::temp_directory_path() / "lituya_writer_escape_test.pvd";
  const std::string dataset = "a&b<c>\"d'e_0000.vtu";
  lituya::PvdWriter pvd(file);
  pvd.add(0.5, dataset);

  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(file.c_str());
  ASSERT_EQ(parser->Parse(), 1) << "the .pvd is not well-formed XML";
  vtkXMLDataElement* collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
  ASSERT_NE(collection, nullptr);
  ASSERT_EQ(collection->GetNumberOfNestedElements(), 1);
  EXPECT_EQ(std::string(collection->GetNestedElement(0)->GetAttribute("file")), dataset);
}

TEST(VtuWriter, EscapesArrayNames) {
  lituya::VtuWriter w;
  std::vector<double> xyz = {0, 0, 0, 1, 0, 0};
  w.set_points(xyz);
  w.set_vertex_cells();
  std::vector<double> values = {1.5, 2.5};
  const std::string name = "p&<\"q\">'";
  w.add_point_data(name, 1, values);
  auto file = std::filesystem::temp_directory_path() / "lituya_writer_escape_test.vtu";
  w.write(file);

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkDataArray* array = reader->GetOutput()->GetPointData()->GetArray(name.c_str());
  ASSERT_NE(array, nullptr) << "array name did not survive the round trip";
  EXPECT_DOUBLE_EQ(array->GetTuple1(1), 2.5);
}

TEST(OutputFolder, RefusesToOverwriteWithoutForce) {
  auto folder = std::filesystem::temp_directory_path() / "lituya_output_folder_test";
  std::filesystem::remove_all(folder);
  lituya::prepare_output_folder(folder, false);
  std::ofstream(folder / "earlier.txt") << "earlier run";
  EXPECT_THROW(lituya::prepare_output_folder(folder, false), lituya::InputError);
  EXPECT_TRUE(std::filesystem::exists(folder / "earlier.txt"));
  EXPECT_NO_THROW(lituya::prepare_output_folder(folder, true));
}

}  // namespace
