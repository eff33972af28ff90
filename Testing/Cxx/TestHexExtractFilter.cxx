// SPDX-License-Identifier: BSD-3-Clause
// vtkHexExtractFilter on a box that is already a polycube: n^3 hexes of scaled Jacobian 1, the
// quality and distance fields, the boundary quads, and clear refusals of bad inputs.
#include "PolycubeHexTestErrors.h"
#include "TestAssert.h"
#include "vtkHexExtractFilter.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace
{
const int TetFaces[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

double SignedVolume(vtkPoints* points, const vtkIdType ids[4])
{
  double p[4][3];
  for (int k = 0; k < 4; ++k)
  {
    points->GetPoint(ids[k], p[k]);
  }
  double a[3], b[3], c[3];
  for (int i = 0; i < 3; ++i)
  {
    a[i] = p[1][i] - p[0][i];
    b[i] = p[2][i] - p[0][i];
    c[i] = p[3][i] - p[0][i];
  }
  return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0])) /
    6.0;
}

/// A box [0,sx]x[0,sy]x[0,sz] of m^3 grid cells, 6 positive tets each, with the arrays the deform
/// filter would output: OriginalPoints = points, PolycubeLabels from the box face each boundary
/// tet face lies on.
vtkSmartPointer<vtkUnstructuredGrid> MakeBoxPolycube(int m, const double size[3])
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto id = [m](int i, int j, int k)
  { return static_cast<vtkIdType>((k * (m + 1) + j) * (m + 1) + i); };
  for (int k = 0; k <= m; ++k)
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= m; ++i)
        points->InsertNextPoint(size[0] * i / m, size[1] * j / m, size[2] * k / m);
  grid->SetPoints(points);
  const int permutations[6][3] = {
    { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 }
  };
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        for (const auto& order : permutations)
        {
          int corner[3] = { i, j, k };
          vtkIdType ids[4];
          ids[0] = id(corner[0], corner[1], corner[2]);
          for (int step = 0; step < 3; ++step)
          {
            ++corner[order[step]];
            ids[step + 1] = id(corner[0], corner[1], corner[2]);
          }
          if (SignedVolume(points, ids) < 0)
          {
            std::swap(ids[1], ids[2]);
          }
          grid->InsertNextCell(VTK_TETRA, 4, ids);
        }
  vtkNew<vtkDoubleArray> original;
  original->DeepCopy(points->GetData());
  original->SetName("OriginalPoints");
  grid->GetPointData()->AddArray(original);

  vtkNew<vtkIntArray> labels;
  labels->SetName("PolycubeLabels");
  labels->SetNumberOfComponents(4);
  labels->SetNumberOfTuples(grid->GetNumberOfCells());
  for (vtkIdType t = 0; t < grid->GetNumberOfCells(); ++t)
  {
    const vtkIdType* ids = nullptr;
    vtkIdType count = 0;
    grid->GetCellPoints(t, count, ids);
    for (int f = 0; f < 4; ++f)
    {
      int label = -1;
      for (int axis = 0; axis < 3 && label < 0; ++axis)
      {
        for (int side = 0; side < 2 && label < 0; ++side)
        {
          const double plane = side == 0 ? size[axis] : 0.0;
          bool onPlane = true;
          for (int c = 0; c < 3; ++c)
          {
            onPlane =
              onPlane && std::fabs(points->GetPoint(ids[TetFaces[f][c]])[axis] - plane) < 1e-12;
          }
          label = onPlane ? 2 * axis + side : -1; // +X, -X, +Y, -Y, +Z, -Z
        }
      }
      labels->SetComponent(t, f, label);
    }
  }
  grid->GetCellData()->AddArray(labels);
  return grid;
}

double FieldValue(vtkUnstructuredGrid* grid, const char* name)
{
  vtkDataArray* array = vtkDataArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray(name));
  return array ? array->GetTuple1(0) : std::nan("");
}
} // namespace

int main(int, char*[])
{
  const double cube[3] = { 1.0, 1.0, 1.0 };
  auto box = MakeBoxPolycube(2, cube);

  // A cube at resolution n gives n^3 hexes of scaled Jacobian 1 (no padding, no smoothing).
  for (int n : { 3, 5 })
  {
    vtkNew<vtkHexExtractFilter> extract;
    extract->SetInputData(box);
    extract->SetTargetHexCount(n * n * n);
    extract->PaddingOff();
    extract->SmoothingOff();
    extract->SetNumberOfDistanceSamples(20000);
    extract->Update();
    vtkUnstructuredGrid* hexes = extract->GetOutput(0);
    PCH_CHECK(hexes->GetNumberOfCells() == n * n * n);
    PCH_CHECK(FieldValue(hexes, "HexCount") == n * n * n);
    PCH_CHECK_NEAR(FieldValue(hexes, "ScaledJacobianMin"), 1.0, 1e-9);
    PCH_CHECK_NEAR(FieldValue(hexes, "ScaledJacobianMean"), 1.0, 1e-9);
    PCH_CHECK(FieldValue(hexes, "InvertedHexCount") == 0);
    PCH_CHECK(FieldValue(hexes, "ValidHexMesh") == 1);
    PCH_CHECK_NEAR(FieldValue(hexes, "DistanceHausdorff"), 0.0, 1e-6);
    PCH_CHECK(hexes->GetCellData()->GetArray("ScaledJacobian") != nullptr);
    // Without smoothing neither the untangling nor the sweeps run.
    PCH_CHECK(FieldValue(hexes, "UntanglingRounds") == 0);
    PCH_CHECK(FieldValue(hexes, "SmoothingSweeps") == 0);
    PCH_CHECK(FieldValue(hexes, "UntanglingPath") == 0);
    vtkPolyData* quads = vtkPolyData::SafeDownCast(extract->GetOutputDataObject(1));
    PCH_CHECK(quads->GetNumberOfPolys() == 6 * n * n);
    PCH_CHECK(quads->GetCellData()->GetArray("PolycubeLabel") != nullptr);
  }

  // With padding and smoothing (the defaults) the mesh stays valid near the target count.
  {
    const double slab[3] = { 2.0, 1.0, 1.0 };
    vtkNew<vtkHexExtractFilter> extract;
    extract->SetInputData(MakeBoxPolycube(2, slab));
    extract->SetTargetHexCount(1000);
    extract->SetNumberOfDistanceSamples(20000);
    extract->Update();
    vtkUnstructuredGrid* hexes = extract->GetOutput(0);
    std::cout << "slab with padding: " << hexes->GetNumberOfCells() << " hexes, SJ min "
              << FieldValue(hexes, "ScaledJacobianMin") << "\n";
    PCH_CHECK(std::fabs(hexes->GetNumberOfCells() - 1000.0) <= 100.0);
    PCH_CHECK(FieldValue(hexes, "ValidHexMesh") == 1);
    PCH_CHECK(FieldValue(hexes, "ScaledJacobianMin") > 0.3);
    // The work the untangling and the smoothing did is reported.
    PCH_CHECK(FieldValue(hexes, "UntanglingRounds") >= 1);
    PCH_CHECK(FieldValue(hexes, "UntanglingIterations") >= 1);
    PCH_CHECK(FieldValue(hexes, "SmoothingSweeps") >= 1);
    PCH_CHECK(extract->GetUntanglingPaths() == 2);
    PCH_CHECK(FieldValue(hexes, "UntanglingPath") == 1 || FieldValue(hexes, "UntanglingPath") == 2);

    // Two untangling paths (the default) keep the better mesh: never a lower minimum than one.
    vtkNew<vtkHexExtractFilter> onePath;
    onePath->SetInputData(MakeBoxPolycube(2, slab));
    onePath->SetTargetHexCount(1000);
    onePath->SetNumberOfDistanceSamples(20000);
    onePath->SetUntanglingPaths(1);
    onePath->Update();
    vtkUnstructuredGrid* single = onePath->GetOutput(0);
    std::cout << "slab with one untangling path: SJ min " << FieldValue(single, "ScaledJacobianMin")
              << " (two: " << FieldValue(hexes, "ScaledJacobianMin") << ", path "
              << FieldValue(hexes, "UntanglingPath") << ")\n";
    PCH_CHECK(FieldValue(single, "ValidHexMesh") == 1);
    PCH_CHECK(FieldValue(single, "UntanglingPath") == 1);
    PCH_CHECK(FieldValue(hexes, "ScaledJacobianMin") >= FieldValue(single, "ScaledJacobianMin"));

    // Above ScaleRetryBelow nothing is extracted again; a bar no mesh reaches makes both
    // retries run, keeps a mesh no worse, and counts their seconds.
    PCH_CHECK(FieldValue(hexes, "ScaleRetryCount") == 0);
    PCH_CHECK(FieldValue(hexes, "DiscardedSeconds") == 0.0);
    vtkNew<vtkHexExtractFilter> retried;
    retried->SetInputData(MakeBoxPolycube(2, slab));
    retried->SetTargetHexCount(1000);
    retried->SetNumberOfDistanceSamples(20000);
    retried->SetScaleRetryBelow(1.0);
    retried->Update();
    vtkUnstructuredGrid* again = retried->GetOutput(0);
    const double factor = FieldValue(again, "ScaleFactor");
    std::cout << "slab with forced scale retries: SJ min " << FieldValue(again, "ScaledJacobianMin")
              << ", kept scale x" << factor << ", discarded "
              << FieldValue(again, "DiscardedSeconds") << " s\n";
    PCH_CHECK(FieldValue(again, "ScaleRetryCount") == 2);
    PCH_CHECK(FieldValue(again, "ValidHexMesh") == 1);
    PCH_CHECK(
      FieldValue(again, "ScaledJacobianMin") >= FieldValue(hexes, "ScaledJacobianMin") - 0.01);
    PCH_CHECK(factor > 0.98 && factor < 1.02);
    PCH_CHECK(FieldValue(again, "DiscardedSeconds") > 0.0);
    PCH_CHECK(FieldValue(again, "ExtractionSeconds") >= FieldValue(again, "DiscardedSeconds"));
  }

  // Padding without smoothing: the placement of the inner copies lowers no minimum (it ranks the
  // minimum first, so on this undistorted map it may trade a little of the padding hexes' mean
  // for it); with smoothing it is left to the smoothing.
  {
    const double slab[3] = { 2.0, 1.0, 1.0 };
    double minimum[2] = { 0.0, 0.0 };
    for (int placement : { 0, 1 })
    {
      vtkNew<vtkHexExtractFilter> extract;
      extract->SetInputData(MakeBoxPolycube(2, slab));
      extract->SetTargetHexCount(1000);
      extract->SmoothingOff();
      extract->SetPaddingPlacement(placement != 0);
      extract->SetNumberOfDistanceSamples(20000);
      extract->Update();
      vtkUnstructuredGrid* hexes = extract->GetOutput(0);
      minimum[placement] = FieldValue(hexes, "ScaledJacobianMin");
      std::cout << "slab, raw, placement " << placement << ": SJ min " << minimum[placement]
                << ", padding hexes' mean "
                << FieldValue(hexes, "PaddingScaledJacobianMeanBeforePlacement") << " -> "
                << FieldValue(hexes, "PaddingScaledJacobianMean") << ", "
                << FieldValue(hexes, "PlacedPaddingVertexCount") << " copies placed ("
                << FieldValue(hexes, "OptimizedPaddingVertexCount") << " by the joint move)\n";
      PCH_CHECK(FieldValue(hexes, "ValidHexMesh") == 1);
      if (placement)
      {
        PCH_CHECK(FieldValue(hexes, "PlacedPaddingVertexCount") > 0);
        PCH_CHECK(FieldValue(hexes, "OptimizedPaddingVertexCount") <=
          FieldValue(hexes, "PlacedPaddingVertexCount"));
        PCH_CHECK(FieldValue(hexes, "PaddingScaledJacobianMean") >=
          FieldValue(hexes, "PaddingScaledJacobianMeanBeforePlacement") - 0.01);
      }
      else
      {
        PCH_CHECK(FieldValue(hexes, "PlacedPaddingVertexCount") == 0);
        PCH_CHECK(FieldValue(hexes, "OptimizedPaddingVertexCount") == 0);
      }
    }
    PCH_CHECK(minimum[1] >= minimum[0]);
    vtkNew<vtkHexExtractFilter> smoothed;
    smoothed->SetInputData(MakeBoxPolycube(2, slab));
    smoothed->SetTargetHexCount(1000);
    smoothed->SetNumberOfDistanceSamples(20000);
    smoothed->Update();
    PCH_CHECK(FieldValue(smoothed->GetOutput(0), "PlacedPaddingVertexCount") == 0);
  }

  // SoftFeatureAngle: the box's edges are sharp (the normals about them 45 degrees from their
  // mean), so the default 20 degrees keeps every edge and corner vertex on its feature; at 90
  // degrees every box edge counts as smooth and its vertices may leave it.
  {
    const double slab[3] = { 2.0, 1.0, 1.0 };
    double released[2] = { -1.0, -1.0 };
    for (int i : { 0, 1 })
    {
      vtkNew<vtkHexExtractFilter> extract;
      extract->SetInputData(MakeBoxPolycube(2, slab));
      extract->SetTargetHexCount(1000);
      extract->SetNumberOfDistanceSamples(20000);
      PCH_CHECK_NEAR(extract->GetSoftFeatureAngle(), 20.0, 0.0);
      if (i == 1)
      {
        extract->SetSoftFeatureAngle(90.0);
      }
      extract->Update();
      vtkUnstructuredGrid* hexes = extract->GetOutput(0);
      released[i] = FieldValue(hexes, "ReleasedBoundaryVertexCount");
      PCH_CHECK(FieldValue(hexes, "ValidHexMesh") == 1);
    }
    std::cout << "slab, released feature vertices at 20 and 90 degrees: " << released[0] << ", "
              << released[1] << "\n";
    PCH_CHECK(released[0] == 0.0);
    PCH_CHECK(released[1] > 0.0);
  }

  // Refusals: no labels, not tets, an empty grid.
  vtkNew<ErrorCapture> errors;
  {
    auto unlabelled = MakeBoxPolycube(1, cube);
    unlabelled->GetCellData()->RemoveArray("PolycubeLabels");
    vtkNew<vtkHexExtractFilter> extract;
    errors->Watch(extract);
    extract->SetInputData(unlabelled);
    extract->Update();
    PCH_CHECK(extract->GetOutput(0)->GetNumberOfCells() == 0);
    PCH_CHECK(errors->Mentions("PolycubeLabels"));
  }
  {
    errors->Clear();
    vtkNew<vtkUnstructuredGrid> empty;
    vtkNew<vtkHexExtractFilter> extract;
    errors->Watch(extract);
    extract->SetInputData(empty);
    extract->Update();
    PCH_CHECK(errors->Mentions("no cells"));
  }
  {
    // An inverted tet: swap two vertices of one tet.
    errors->Clear();
    auto inverted = MakeBoxPolycube(1, cube);
    vtkIdType ids[4];
    const vtkIdType* cell = nullptr;
    vtkIdType count = 0;
    inverted->GetCellPoints(0, count, cell);
    std::copy(cell, cell + 4, ids);
    std::swap(ids[0], ids[1]);
    inverted->ReplaceCell(0, 4, ids);
    vtkNew<vtkHexExtractFilter> extract;
    errors->Watch(extract);
    extract->SetInputData(inverted);
    extract->Update();
    PCH_CHECK(extract->GetOutput(0)->GetNumberOfCells() == 0);
    std::cout << "inverted tet: " << errors->Messages;
    PCH_CHECK(
      errors->Mentions("invert") || errors->Mentions("negative") || errors->Mentions("flat"));
  }
  return PCH_TEST_RESULT();
}
