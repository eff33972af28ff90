// SPDX-License-Identifier: BSD-3-Clause
// vtkTetrahedralizeFilter on the shipped models (torus.obj, 3holes.obj, fertility.off): every tet
// positive, volume kept, and with PreserveBoundary the boundary equal to the input; open and
// non-manifold surfaces refused with an error naming the problem.
#include "PolycubeHexArrayNames.h"
#include "PolycubeHexTestErrors.h"
#include "TestAssert.h"
#include "vtkOFFReader.h"
#include "vtkTetrahedralizeFilter.h"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <chrono>
#include <iostream>
#include <string>

namespace
{
/// Volume and area of a closed triangle surface.
vtkSmartPointer<vtkMassProperties> Measure(vtkPolyData* surface)
{
  vtkNew<vtkTriangleFilter> triangles; // vtkMassProperties wants triangles only
  triangles->SetInputData(surface);
  auto mass = vtkSmartPointer<vtkMassProperties>::New();
  mass->SetInputConnection(triangles->GetOutputPort());
  mass->Update();
  return mass;
}

/// Tets with volume <= 0 in VTK's node order.
int NonPositiveTetCount(vtkUnstructuredGrid* tets, double& volume)
{
  int count = 0;
  volume = 0.0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < tets->GetNumberOfCells(); ++c)
  {
    tets->GetCellPoints(c, ids);
    double p[4][3];
    for (int k = 0; k < 4; ++k)
    {
      tets->GetPoint(ids->GetId(k), p[k]);
    }
    double a[3], b[3], d[3];
    for (int i = 0; i < 3; ++i)
    {
      a[i] = p[1][i] - p[0][i];
      b[i] = p[2][i] - p[0][i];
      d[i] = p[3][i] - p[0][i];
    }
    const double tetVolume =
      (d[0] * (a[1] * b[2] - a[2] * b[1]) + d[1] * (a[2] * b[0] - a[0] * b[2]) +
        d[2] * (a[0] * b[1] - a[1] * b[0])) /
      6.0;
    volume += tetVolume;
    count += tetVolume > 0.0 ? 0 : 1;
  }
  return count;
}

/// Tetrahedralizes `surface` and checks what every result must satisfy. Returns the tet count.
vtkIdType Check(const std::string& name,
  vtkPolyData* surface,
  bool preserveBoundary,
  const std::string& outputDir)
{
  vtkNew<vtkTetrahedralizeFilter> filter;
  vtkNew<ErrorCapture> errors;
  errors->Watch(filter);
  filter->SetInputData(surface);
  filter->SetPreserveBoundary(preserveBoundary);
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkUnstructuredGrid* tets = filter->GetOutput();
  auto* switches = vtkStringArray::SafeDownCast(
    tets->GetFieldData()->GetAbstractArray(polycubehex::ArrayNames::TetrahedralizeSwitches));
  std::cout << name << (preserveBoundary ? " (boundary kept)" : "") << ": "
            << surface->GetNumberOfPolys() << " triangles -> " << tets->GetNumberOfCells()
            << " tets, " << tets->GetNumberOfPoints() << " points in " << seconds << " s, -"
            << (switches ? switches->GetValue(0) : std::string("?")) << std::endl;
  PCH_CHECK(errors->Messages.empty());
  PCH_CHECK(tets->GetNumberOfCells() > 0);
  PCH_CHECK(switches != nullptr && switches->GetNumberOfValues() == 1);
  for (vtkIdType c = 0; c < tets->GetNumberOfCells(); ++c)
  {
    if (tets->GetCellType(c) != VTK_TETRA)
    {
      PCH_CHECK(tets->GetCellType(c) == VTK_TETRA);
      break;
    }
  }

  double volume = 0.0;
  PCH_CHECK(NonPositiveTetCount(tets, volume) == 0);
  const auto input = Measure(surface);
  PCH_CHECK_NEAR(volume, input->GetVolume(), 1e-6 * input->GetVolume());

  if (preserveBoundary)
  {
    PCH_CHECK(switches && switches->GetValue(0).find('Y') != std::string::npos);
    vtkNew<vtkDataSetSurfaceFilter> boundary;
    boundary->SetInputData(tets);
    boundary->Update();
    const auto kept = Measure(boundary->GetOutput());
    PCH_CHECK(boundary->GetOutput()->GetNumberOfPolys() == surface->GetNumberOfPolys());
    PCH_CHECK_NEAR(kept->GetSurfaceArea(), input->GetSurfaceArea(), 1e-9 * input->GetSurfaceArea());
  }

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(tets);
  writer->SetFileName((outputDir + "/TestTetrahedralizeFilter_" + name +
    (preserveBoundary ? "_boundary" : "") + ".vtu")
                        .c_str());
  writer->Write();
  return tets->GetNumberOfCells();
}

/// Runs the filter on a bad surface: it must fail, produce nothing, and say `words`.
bool Refuses(vtkPolyData* surface, const std::string& words)
{
  vtkNew<vtkTetrahedralizeFilter> filter;
  vtkNew<ErrorCapture> errors;
  errors->Watch(filter);
  filter->SetInputData(surface);
  filter->Update();
  std::cout << "refused: " << errors->Messages;
  return filter->GetOutput()->GetNumberOfCells() == 0 && errors->Mentions(words);
}

vtkSmartPointer<vtkPolyData> Read(vtkAlgorithm* reader)
{
  reader->Update();
  return vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
}

/// Two tet surfaces glued along the edge (0, 1): that edge is in four triangles.
vtkSmartPointer<vtkPolyData> TwoTetsSharingAnEdge()
{
  vtkNew<vtkPoints> points;
  const double coordinates[6][3] = {
    { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, -1, 0 }, { 0, 0, -1 }
  };
  for (const auto& p : coordinates)
  {
    points->InsertNextPoint(p);
  }
  // VTK's outward faces of the positive tets (0, 1, 2, 3) and (0, 1, 4, 5).
  const vtkIdType faces[8][3] = { { 0, 1, 3 },
    { 1, 2, 3 },
    { 2, 0, 3 },
    { 0, 2, 1 },
    { 0, 1, 5 },
    { 1, 4, 5 },
    { 4, 0, 5 },
    { 0, 4, 1 } };
  vtkNew<vtkCellArray> polys;
  for (const auto& f : faces)
  {
    polys->InsertNextCell(3, f);
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  return surface;
}

/// `surface` without its first triangle.
vtkSmartPointer<vtkPolyData> WithoutFirstTriangle(vtkPolyData* surface)
{
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 1; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    polys->InsertNextCell(ids);
  }
  auto open = vtkSmartPointer<vtkPolyData>::New();
  open->SetPoints(surface->GetPoints());
  open->SetPolys(polys);
  return open;
}

/// Every triangle with its own three points, as some OBJ and STL writers store surfaces.
vtkSmartPointer<vtkPolyData> TriangleSoup(vtkPolyData* surface)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    vtkIdType copies[3];
    for (int k = 0; k < 3; ++k)
    {
      copies[k] = points->InsertNextPoint(surface->GetPoint(ids->GetId(k)));
    }
    polys->InsertNextCell(3, copies);
  }
  auto soup = vtkSmartPointer<vtkPolyData>::New();
  soup->SetPoints(points);
  soup->SetPolys(polys);
  return soup;
}
/// `surface` with a point inserted on the edge of its first triangle, `fraction` of the way
/// from the edge's first vertex: the two triangles at that vertex become needles.
vtkSmartPointer<vtkPolyData> WithNeedles(vtkPolyData* surface, double fraction)
{
  vtkNew<vtkIdList> first;
  surface->GetCellPoints(0, first);
  const vtkIdType a = first->GetId(0);
  const vtkIdType b = first->GetId(1);
  double pa[3];
  double pb[3];
  surface->GetPoint(a, pa);
  surface->GetPoint(b, pb);
  vtkNew<vtkPoints> points;
  points->DeepCopy(surface->GetPoints());
  const vtkIdType p = points->InsertNextPoint(pa[0] + fraction * (pb[0] - pa[0]),
    pa[1] + fraction * (pb[1] - pa[1]),
    pa[2] + fraction * (pb[2] - pa[2]));
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    int k = 0;
    for (; k < 3; ++k)
    {
      const vtkIdType u = ids->GetId(k);
      const vtkIdType v = ids->GetId((k + 1) % 3);
      if ((u == a && v == b) || (u == b && v == a))
      {
        break;
      }
    }
    if (k == 3)
    {
      polys->InsertNextCell(ids);
      continue;
    }
    // The triangle (u, v, w) on the edge becomes (u, p, w) and (p, v, w).
    const vtkIdType u = ids->GetId(k);
    const vtkIdType v = ids->GetId((k + 1) % 3);
    const vtkIdType w = ids->GetId((k + 2) % 3);
    const vtkIdType halves[2][3] = { { u, p, w }, { p, v, w } };
    polys->InsertNextCell(3, halves[0]);
    polys->InsertNextCell(3, halves[1]);
  }
  auto needles = vtkSmartPointer<vtkPolyData>::New();
  needles->SetPoints(points);
  needles->SetPolys(polys);
  return needles;
}

/// Tetrahedralizes `surface` and returns the filter's warnings.
std::string Warnings(vtkPolyData* surface)
{
  vtkNew<vtkTetrahedralizeFilter> filter;
  vtkNew<ErrorCapture> messages;
  messages->Watch(filter);
  filter->SetInputData(surface);
  filter->Update();
  PCH_CHECK(filter->GetOutput()->GetNumberOfCells() > 0);
  return messages->Messages;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    return 1;
  }
  const std::string data = argv[1];
  const std::string output = argv[2];

  vtkNew<vtkSphereSource> sphereSource;
  sphereSource->SetThetaResolution(24);
  sphereSource->SetPhiResolution(16);
  vtkSmartPointer<vtkPolyData> sphere = Read(sphereSource);

  // A build without TetGen must say so, and then there is nothing more to test.
  {
    vtkNew<vtkTetrahedralizeFilter> filter;
    vtkNew<ErrorCapture> errors;
    errors->Watch(filter);
    filter->SetInputData(sphere);
    filter->Update();
    if (errors->Mentions("without TetGen"))
    {
      std::cout << "built without TetGen: " << errors->Messages;
      PCH_CHECK(filter->GetOutput()->GetNumberOfCells() == 0);
      return PCH_TEST_RESULT();
    }
  }

  Check("sphere", sphere, false, output);
  Check("sphere", sphere, true, output);
  // Coincident points are merged before the surface check.
  Check("soup", TriangleSoup(sphere), true, output);

  vtkNew<vtkOBJReader> torusReader;
  torusReader->SetFileName((data + "/torus.obj").c_str());
  vtkSmartPointer<vtkPolyData> torus = Read(torusReader);
  const vtkIdType torusTets = Check("torus", torus, false, output);
  Check("torus", torus, true, output);

  vtkNew<vtkOBJReader> holesReader;
  holesReader->SetFileName((data + "/3holes.obj").c_str());
  vtkSmartPointer<vtkPolyData> holes = Read(holesReader);
  const vtkIdType holesTets = Check("3holes", holes, false, output);
  Check("3holes", holes, true, output);

  vtkNew<vtkOFFReader> fertilityReader;
  fertilityReader->SetFileName((data + "/fertility.off").c_str());
  vtkSmartPointer<vtkPolyData> fertility = Read(fertilityReader);
  const vtkIdType fertilityTets = Check("fertility", fertility, false, output);
  Check("fertility", fertility, true, output);
  // TetGen's own command line gives about 78k tets at -pq2.0 (shared/PLATFORM.md).
  PCH_CHECK(fertilityTets > 70000 && fertilityTets < 90000);
  std::cout << "tets at default quality: torus " << torusTets << ", 3holes " << holesTets
            << ", fertility " << fertilityTets << std::endl;

  // Needles and caps are meshed, with a warning that names them; well-shaped surfaces get none.
  PCH_CHECK(Warnings(sphere).empty());
  PCH_CHECK(Warnings(torus).empty());
  const std::string needles = Warnings(WithNeedles(sphere, 1e-4));
  std::cout << "needles: " << needles;
  const std::string expected = "2 of " + std::to_string(sphere->GetNumberOfCells() + 2) +
    " input triangles have an angle below 1 degree";
  PCH_CHECK(needles.find(expected) != std::string::npos);
  PCH_CHECK(Warnings(WithNeedles(sphere, 0.3)).empty());

  // Bad surfaces: refused with the problem named.
  PCH_CHECK(Refuses(WithoutFirstTriangle(sphere), "the surface is not closed: 3 boundary edges"));
  vtkNew<vtkPolyData> empty;
  PCH_CHECK(Refuses(empty, "no triangles"));
  PCH_CHECK(Refuses(TwoTetsSharingAnEdge(), "not 2-manifold: 1 edge in more than two triangles"));
  return PCH_TEST_RESULT();
}
