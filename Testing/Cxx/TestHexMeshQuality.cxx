// SPDX-License-Identifier: BSD-3-Clause
// vtkHexMeshQuality: the reference hex mesh's scaled Jacobian, hand-made invalid hexes, and
// the sampled surface distance against an analytic value.
#include "PolycubeHexTestErrors.h"
#include "TestAssert.h"
#include "vtkHexMeshQuality.h"
#include "vtkMeditReader.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <iostream>
#include <string>

namespace
{
/// An n x n x n grid of hexes filling the cube [0,1]^3 scaled by `scale` about its centre.
vtkSmartPointer<vtkUnstructuredGrid> CubeGrid(int n, double scale = 1.0)
{
  const int m = n + 1;
  auto id = [m](int i, int j, int k) { return static_cast<vtkIdType>(i + m * (j + m * k)); };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int k = 0; k < m; ++k)
  {
    for (int j = 0; j < m; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        auto coordinate = [&](int c) { return 0.5 + scale * (static_cast<double>(c) / n - 0.5); };
        points->InsertNextPoint(coordinate(i), coordinate(j), coordinate(k));
      }
    }
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType hex[8] = { id(i, j, k),
          id(i + 1, j, k),
          id(i + 1, j + 1, k),
          id(i, j + 1, k),
          id(i, j, k + 1),
          id(i + 1, j, k + 1),
          id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }
    }
  }
  return grid;
}

/// Runs the filter; returns its output, or null when it failed (errors go to `errors`).
vtkSmartPointer<vtkUnstructuredGrid> Quality(vtkUnstructuredGrid* hexes,
  vtkDataSet* reference,
  ErrorCapture* errors,
  int seed = 0)
{
  vtkNew<vtkHexMeshQuality> quality;
  errors->Watch(quality);
  quality->SetInputData(hexes);
  if (reference)
  {
    quality->SetReferenceData(reference);
  }
  quality->SetRandomSeed(seed);
  if (!quality->GetExecutive()->Update())
  {
    return nullptr;
  }
  auto output = vtkSmartPointer<vtkUnstructuredGrid>::New();
  output->ShallowCopy(quality->GetOutput());
  return output;
}

double Field(vtkDataSet* data, const char* name, int tuple = 0)
{
  vtkDataArray* array = data ? data->GetFieldData()->GetArray(name) : nullptr;
  PCH_CHECK(array != nullptr);
  return array ? array->GetTuple1(tuple) : std::nan("");
}

std::string Report(vtkDataSet* data)
{
  auto* array =
    vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray("ValidityReport"));
  return array ? array->GetValue(0) : std::string();
}

void Print(const char* what, vtkDataSet* output)
{
  std::cout << "--- " << what << "\n" << Report(output);
  for (const char* name : { "HexCount",
         "ScaledJacobianMin",
         "ScaledJacobianMean",
         "InvertedHexCount",
         "DegenerateHexCount",
         "IrregularBoundaryVertexCount",
         "ValidHexMesh",
         "DistanceMean",
         "DistanceHausdorff" })
  {
    if (vtkDataArray* array = output->GetFieldData()->GetArray(name))
    {
      std::cout << "  " << name << " = " << array->GetTuple1(0) << "\n";
    }
  }
  std::cout << std::flush;
}

// (a) The reference rockerarm hex mesh, in file order: known Verdict numbers, valid.
void TestReferenceMesh(const std::string& data)
{
  vtkNew<vtkMeditReader> reader;
  reader->SetFileName((data + "/reference_rockerarm_hex.mesh").c_str());
  reader->Update();
  vtkNew<ErrorCapture> errors;
  const auto output = Quality(reader->GetOutput(), nullptr, errors);
  PCH_CHECK(output != nullptr);
  if (!output)
  {
    return;
  }
  Print("reference_rockerarm_hex.mesh", output);
  PCH_CHECK_NEAR(Field(output, "ScaledJacobianMin"), 0.5374, 5e-4);
  PCH_CHECK_NEAR(Field(output, "ScaledJacobianMean"), 0.9365, 5e-4);
  PCH_CHECK(Field(output, "ValidHexMesh") == 1);
  PCH_CHECK(Field(output, "InvertedHexCount") == 0);
  PCH_CHECK(Field(output, "DegenerateHexCount") == 0);
  const double hexCount = Field(output, "HexCount");
  PCH_CHECK(hexCount == output->GetNumberOfCells());
  PCH_CHECK(output->GetCellData()->GetArray("ScaledJacobian") != nullptr);
  PCH_CHECK(output->GetFieldData()->GetArray("DistanceMean") == nullptr);

  // The histogram counts every hex once; min 0.5374 puts nothing at or below 0.5.
  double histogramTotal = 0.0;
  std::cout << "  ScaledJacobianHistogram =";
  for (int bin = 0; bin < 11; ++bin)
  {
    const double count = Field(output, "ScaledJacobianHistogram", bin);
    histogramTotal += count;
    std::cout << " " << count;
    if (bin <= 5)
    {
      PCH_CHECK(count == 0);
    }
  }
  std::cout << std::endl;
  PCH_CHECK(histogramTotal == hexCount);
}

// (b) Hand-made invalid hexes, and refused inputs.
void TestInvalidHexes()
{
  vtkNew<ErrorCapture> errors;

  // Top and bottom swapped: the hex is turned inside out.
  auto inverted = CubeGrid(1);
  const vtkIdType flipped[8] = { 4, 5, 7, 6, 0, 1, 3, 2 };
  inverted->GetCells()->ReplaceCellAtId(0, 8, flipped);
  auto output = Quality(inverted, nullptr, errors);
  PCH_CHECK(output != nullptr);
  Print("inverted hex", output);
  PCH_CHECK(Field(output, "InvertedHexCount") == 1);
  PCH_CHECK(Field(output, "ScaledJacobianMin") < 0);
  PCH_CHECK(Field(output, "ScaledJacobianHistogram", 0) == 1);
  PCH_CHECK(Field(output, "ValidHexMesh") == 0);

  // Vertex 6 replaced by vertex 5: the edge 5-6 collapses.
  auto degenerate = CubeGrid(1);
  const vtkIdType collapsed[8] = { 0, 1, 3, 2, 4, 5, 5, 6 };
  degenerate->GetCells()->ReplaceCellAtId(0, 8, collapsed);
  output = Quality(degenerate, nullptr, errors);
  PCH_CHECK(output != nullptr);
  Print("hex with a repeated vertex", output);
  PCH_CHECK(Field(output, "DegenerateHexCount") == 1);
  // Verdict's sentinel for the collapsed edge (1e30) is reported as 0, an inverted hex.
  PCH_CHECK(Field(output, "ScaledJacobianMin") == 0);
  PCH_CHECK(Field(output, "InvertedHexCount") == 1);
  PCH_CHECK(Field(output, "ValidHexMesh") == 0);

  // A perfect hex plus a stray copy of its first vertex: only the point locator sees it.
  auto duplicate = CubeGrid(1);
  double x[3];
  duplicate->GetPoint(0, x);
  duplicate->GetPoints()->InsertNextPoint(x[0] + 1e-12, x[1], x[2]);
  output = Quality(duplicate, nullptr, errors);
  PCH_CHECK(output != nullptr);
  Print("hex with a coincident extra vertex", output);
  PCH_CHECK(Field(output, "ScaledJacobianMin") > 0.999);
  PCH_CHECK(Field(output, "ValidHexMesh") == 0);
  PCH_CHECK(Report(output).find("closer than 1e-9") != std::string::npos);

  // The input's field data is not touched by the filter.
  PCH_CHECK(duplicate->GetFieldData()->GetArray("HexCount") == nullptr);

  // Refused: a tetrahedron, and an empty grid.
  vtkNew<vtkUnstructuredGrid> tet;
  tet->SetPoints(CubeGrid(1)->GetPoints());
  const vtkIdType tetIds[4] = { 0, 1, 2, 4 };
  tet->InsertNextCell(VTK_TETRA, 4, tetIds);
  errors->Clear();
  PCH_CHECK(Quality(tet, nullptr, errors) == nullptr);
  std::cout << "tet refused: " << errors->Messages;
  PCH_CHECK(errors->Mentions("hexahedron"));
  vtkNew<vtkUnstructuredGrid> empty;
  empty->SetPoints(vtkNew<vtkPoints>());
  errors->Clear();
  PCH_CHECK(Quality(empty, nullptr, errors) == nullptr);
  std::cout << "empty refused: " << errors->Messages;
  PCH_CHECK(errors->Mentions("no cells"));
}

// (c) A hex mesh against itself: every sample lies on the other surface.
void TestSelfDistance()
{
  vtkNew<ErrorCapture> errors;
  const auto grid = CubeGrid(4);
  const auto output = Quality(grid, grid, errors);
  PCH_CHECK(output != nullptr);
  Print("4x4x4 cube against itself", output);
  PCH_CHECK(Field(output, "DistanceMean") < 1e-9);
  PCH_CHECK(Field(output, "DistanceHausdorff") < 1e-9);
  PCH_CHECK(Field(output, "ValidHexMesh") == 1);
  // 4x4x4 grid: the 8 corners are the only boundary vertices of valence other than 4.
  PCH_CHECK(Field(output, "IrregularBoundaryVertexCount") == 8);
  PCH_CHECK_NEAR(Field(output, "ScaledJacobianMin"), 1.0, 1e-12);
}

// (d) The unit cube against the same cube scaled by 1.01 about its centre (h = 0.005).
//
// Unit: 1e-3 of the REFERENCE diagonal D = 1.01 sqrt(3), so 1 unit = 1.7494e-3.
// Unit cube -> scaled cube: every point of the unit cube is inside the scaled cube, at distance
//   exactly h from the nearest face plane (near an edge the farther planes are even farther):
//   mean h, max h.
// Scaled cube -> unit cube: on a face of side 1 + 2h, the central 1 x 1 square is at distance
//   h; the 4 edge strips 1 x h at sqrt(h^2 + t^2), t uniform in [0, h], mean
//   h (sqrt(2) + asinh(1)) / 2 = 1.147794 h; the 4 corner squares h x h at
//   sqrt(h^2 + s^2 + t^2), mean 1.280789 h. Area-weighted mean:
//   h (1 + 4h 1.147794 + 4h^2 1.280789) / (1 + 2h)^2 = 1.002925 h; max h sqrt(3) at the corners.
// Same sample count both ways, so DistanceMean = h (1 + 1.002925) / 2 / (1e-3 D) = 2.8623 units
// (within 1% of the rough 0.005 / sqrt(3) * 1000 = 2.887). DistanceHausdorff is at most
// h sqrt(3) / (1e-3 D) = 4.9505; the samples in the edge strips with t > 0.98 h (about 40 of
// 100000) are farther than 1.4 h = 4.0 units, so the sampled maximum lies in [4.0, 4.9505].
void TestScaledCubeDistance()
{
  vtkNew<ErrorCapture> errors;
  const auto cube = CubeGrid(4);
  const auto scaled = CubeGrid(4, 1.01);
  const auto output = Quality(cube, scaled, errors);
  PCH_CHECK(output != nullptr);
  Print("unit cube against the cube scaled by 1.01", output);
  const double mean = Field(output, "DistanceMean");
  const double hausdorff = Field(output, "DistanceHausdorff");
  PCH_CHECK_NEAR(mean, 2.8623, 0.005 * 2.8623);
  PCH_CHECK_NEAR(mean, 0.005 / std::sqrt(3.0) * 1000.0, 0.03 * 2.887);
  PCH_CHECK(hausdorff <= 4.9505 + 1e-9);
  PCH_CHECK(hausdorff >= 4.0);

  // Deterministic: the same seed gives the same numbers bit for bit; another seed, close ones.
  const auto again = Quality(cube, scaled, errors);
  PCH_CHECK(Field(again, "DistanceMean") == mean);
  PCH_CHECK(Field(again, "DistanceHausdorff") == hausdorff);
  const auto otherSeed = Quality(cube, scaled, errors, 7);
  std::cout << "  seed 7: DistanceMean = " << Field(otherSeed, "DistanceMean")
            << ", DistanceHausdorff = " << Field(otherSeed, "DistanceHausdorff") << std::endl;
  PCH_CHECK(Field(otherSeed, "DistanceMean") != mean);
  PCH_CHECK_NEAR(Field(otherSeed, "DistanceMean"), mean, 0.001 * mean);
}

// The static entry point used by the hex extraction filter.
void TestComputeQuality()
{
  const auto grid = CubeGrid(2);
  vtkNew<vtkUnstructuredGrid> output;
  std::string why;
  PCH_CHECK(vtkHexMeshQuality::ComputeQuality(grid, nullptr, output, why));
  PCH_CHECK(Field(output, "HexCount") == 8);
  PCH_CHECK(Field(output, "ValidHexMesh") == 1);
  vtkNew<vtkUnstructuredGrid> empty;
  PCH_CHECK(!vtkHexMeshQuality::ComputeQuality(empty, nullptr, output, why));
  std::cout << "ComputeQuality on an empty grid: " << why << std::endl;
  PCH_CHECK(!why.empty());
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string data = argc > 1 ? argv[1] : ".";
  TestReferenceMesh(data);
  TestInvalidHexes();
  TestSelfDistance();
  TestScaledCubeDistance();
  TestComputeQuality();
  return PCH_TEST_RESULT();
}
