// SPDX-License-Identifier: BSD-3-Clause
// vtkMeditReader and vtkMeditWriter: real models, surface elements, round trip, bad input.
#include "PolycubeHexTestErrors.h"
#include "TestAssert.h"
#include "vtkMeditReader.h"
#include "vtkMeditWriter.h"

#include <vtkCellType.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <fstream>
#include <string>

namespace
{
int CountCells(vtkUnstructuredGrid* grid, int type)
{
  int count = 0;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    count += grid->GetCellType(c) == type ? 1 : 0;
  }
  return count;
}

vtkSmartPointer<vtkUnstructuredGrid> Read(const std::string& path, bool surface, ErrorCapture* errors)
{
  vtkNew<vtkMeditReader> reader;
  errors->Watch(reader);
  reader->SetFileName(path.c_str());
  reader->SetReadSurfaceElements(surface);
  reader->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->ShallowCopy(reader->GetOutput());
  return grid;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: TestMeditReader <data dir> <output dir>\n";
    return 1;
  }
  const std::string data = argv[1];
  const std::string output = argv[2];
  vtkNew<ErrorCapture> errors;

  // A tet mesh.
  auto rockerarm = Read(data + "/rockerarm.mesh", false, errors);
  PCH_CHECK(rockerarm->GetNumberOfPoints() == 8040);
  PCH_CHECK(CountCells(rockerarm, VTK_TETRA) == 30813);
  PCH_CHECK(rockerarm->GetNumberOfCells() == 30813);
  PCH_CHECK(vtkMeditReader::CanReadFile((data + "/rockerarm.mesh").c_str()) == 1);
  PCH_CHECK(vtkMeditReader::CanReadFile((data + "/fertility.off").c_str()) == 0);

  // A hex mesh ("Dimension" and "3" on separate lines).
  auto hexes = Read(data + "/reference_rockerarm_hex.mesh", false, errors);
  PCH_CHECK(hexes->GetNumberOfPoints() == 12751);
  PCH_CHECK(CountCells(hexes, VTK_HEXAHEDRON) == 10600);
  PCH_CHECK(errors->Messages.empty());

  // Surface elements only when asked for.
  const std::string small = output + "/medit_small.mesh";
  {
    std::ofstream out(small);
    out << "MeshVersionFormatted 2\nDimension 3\nVertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
        << "Triangles 4\n1 3 2 1\n1 2 4 1\n2 3 4 1\n1 4 3 1\nEdges 1 1 2 0\n"
        << "Tetrahedra 1\n1 2 3 4 0\nNormals 1 0 0 1\nEnd\n";
  }
  errors->Clear();
  auto volumeOnly = Read(small, false, errors);
  PCH_CHECK(volumeOnly->GetNumberOfCells() == 1);
  PCH_CHECK(errors->Mentions("Normals")); // skipped with a warning
  auto withSurface = Read(small, true, errors);
  PCH_CHECK(withSurface->GetNumberOfCells() == 6);
  PCH_CHECK(CountCells(withSurface, VTK_TRIANGLE) == 4 && CountCells(withSurface, VTK_LINE) == 1);

  // Round trip through the writer: same points, same cells, same order.
  const std::string copy = output + "/medit_roundtrip.mesh";
  {
    vtkNew<vtkMeditWriter> writer;
    writer->SetInputData(hexes);
    writer->SetFileName(copy.c_str());
    PCH_CHECK(writer->Write() == 1);
  }
  auto again = Read(copy, false, errors);
  PCH_CHECK(again->GetNumberOfCells() == hexes->GetNumberOfCells());
  PCH_CHECK(again->GetNumberOfPoints() == hexes->GetNumberOfPoints());
  bool same = true;
  for (vtkIdType p = 0; p < hexes->GetNumberOfPoints() && same; p += 97)
  {
    double a[3], b[3];
    hexes->GetPoint(p, a);
    again->GetPoint(p, b);
    same = a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
  }
  PCH_CHECK(same);

  // Bad files: an error naming the problem, an empty output, no crash.
  const std::string truncated = output + "/medit_truncated.mesh";
  {
    std::ofstream out(truncated);
    out << "MeshVersionFormatted 2\nDimension 3\nVertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
        << "Tetrahedra 1\n1 2 3\n";
  }
  errors->Clear();
  PCH_CHECK(Read(truncated, false, errors)->GetNumberOfCells() == 0);
  PCH_CHECK(errors->Mentions("Tetrahedra"));
  errors->Clear();
  PCH_CHECK(Read(output + "/no-such-file.mesh", false, errors)->GetNumberOfCells() == 0);
  PCH_CHECK(errors->Mentions("cannot open"));

  // The writer refuses cells MEDIT cannot hold and writes nothing.
  {
    vtkNew<vtkUnstructuredGrid> wedge;
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 6; ++i)
    {
      points->InsertNextPoint(i % 3 == 1, i % 3 == 2, i / 3);
    }
    wedge->SetPoints(points);
    const vtkIdType ids[6] = { 0, 1, 2, 3, 4, 5 };
    wedge->InsertNextCell(VTK_WEDGE, 6, ids);
    vtkNew<vtkMeditWriter> writer;
    errors->Clear();
    errors->Watch(writer);
    writer->SetInputData(wedge);
    const std::string path = output + "/medit_wedge.mesh";
    std::remove(path.c_str());
    writer->SetFileName(path.c_str());
    PCH_CHECK(writer->Write() == 0);
    PCH_CHECK(errors->Mentions("vtkWedge"));
    PCH_CHECK(!std::ifstream(path).good());
  }
  return PCH_TEST_RESULT();
}
