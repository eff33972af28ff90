// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHandleCutFilter.h"

#include "HandleCuts.h"
#include "PolycubeHexArrayNames.h"
#include "PolycubeHexConversion.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

vtkStandardNewMacro(vtkHandleCutFilter);

namespace
{
namespace names = polycubehex::ArrayNames;

// vtkTetra's local faces, outward for a positive tet (DESIGN.md section 2).
const int TetFaces[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

vtkSmartPointer<vtkIntArray> FourIntArray(const char* name, const polycubehex::Tets& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(4);
  array->SetNumberOfTuples(values.rows());
  for (Eigen::Index t = 0; t < values.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      array->SetComponent(t, k, values(t, k));
    }
  }
  return array;
}

/// The tets the cuts refer to, with the input's data. Without subdivision: the input itself.
/// With it: every tet copies its parent's cell data, and a new point (a split edge's midpoint)
/// gets the point data interpolated from the input points it is the mean of. `OriginalCellId`
/// is added unless the input has one already (it then names an earlier ancestor, DESIGN.md).
void AttachMesh(vtkUnstructuredGrid* input,
  const polycubehex::HandleCutResult& result,
  vtkUnstructuredGrid* output)
{
  const vtkIdType cellCount = static_cast<vtkIdType>(result.OriginalCellId.size());
  if (result.SubdivisionRounds == 0)
  {
    output->ShallowCopy(input);
  }
  else
  {
    output->ShallowCopy(polycubehex::ToUnstructuredGrid(result.Mesh));
    vtkPointData* inPoints = input->GetPointData();
    vtkPointData* outPoints = output->GetPointData();
    const vtkIdType inputPoints = input->GetNumberOfPoints();
    const vtkIdType pointCount = result.Mesh.Vertices.rows();
    outPoints->InterpolateAllocate(inPoints, pointCount);
    // Each point as weights over input points; a midpoint's parents precede it.
    std::vector<std::vector<std::pair<vtkIdType, double>>> weights(pointCount);
    vtkNew<vtkIdList> ids;
    std::vector<double> w;
    for (vtkIdType v = 0; v < pointCount; ++v)
    {
      if (v < inputPoints)
      {
        weights[v] = { { v, 1.0 } };
        outPoints->CopyData(inPoints, v, v);
        continue;
      }
      for (int parent : result.MidpointParents[v - inputPoints])
      {
        for (const auto& term : weights[parent])
        {
          weights[v].emplace_back(term.first, 0.5 * term.second);
        }
      }
      ids->Reset();
      w.clear();
      for (const auto& term : weights[v])
      {
        ids->InsertNextId(term.first);
        w.push_back(term.second);
      }
      outPoints->InterpolatePoint(inPoints, v, ids, w.data());
    }
    vtkCellData* inCells = input->GetCellData();
    vtkCellData* outCells = output->GetCellData();
    outCells->CopyAllocate(inCells, cellCount);
    for (vtkIdType t = 0; t < cellCount; ++t)
    {
      outCells->CopyData(inCells, result.OriginalCellId[t], t);
    }
  }
  if (!output->GetCellData()->HasArray(names::OriginalCellId))
  {
    vtkNew<vtkIdTypeArray> originalCellId;
    originalCellId->SetName(names::OriginalCellId);
    originalCellId->SetNumberOfTuples(cellCount);
    for (vtkIdType t = 0; t < cellCount; ++t)
    {
      originalCellId->SetValue(t, result.OriginalCellId[t]);
    }
    output->GetCellData()->AddArray(originalCellId);
  }
}
} // namespace

vtkHandleCutFilter::vtkHandleCutFilter()
{
  this->SetNumberOfOutputPorts(3);
}

int vtkHandleCutFilter::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

int vtkHandleCutFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // 1. Get the input and outputs.
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* surfaces = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* loops = vtkPolyData::GetData(outputVector, 2);

  // 2. Check and convert it.
  polycubehex::TetMesh mesh;
  std::string why;
  if (!polycubehex::ToTetMesh(input, mesh, why))
  {
    vtkErrorMacro(<< "Cannot cut the input: " << why);
    return 0;
  }

  // 3. Call the core.
  polycubehex::HandleCutParameters params;
  params.MatchedCuts = this->MatchedCuts;
  params.RecomputeEachStep = this->RecomputeEachStep;
  params.MaxMinCutRounds = this->MaxMinCutRounds;
  params.MaxSubdivisionRounds = this->MaxSubdivisionRounds;
  auto progress = [this](double fraction) {
    this->UpdateProgress(fraction);
    return !this->CheckAbort();
  };
  polycubehex::HandleCutResult result;
  const polycubehex::Status status = polycubehex::ComputeHandleCuts(mesh, params, result, progress);
  if (!status)
  {
    vtkErrorMacro(<< "Handle cuts failed: " << status.Message());
    return 0;
  }

  // 4. Attach the outputs: the tets (subdivided where a cut needed it) with the cut arrays, the
  //    cut surfaces, the loops.
  AttachMesh(input, result, output);
  output->GetCellData()->AddArray(FourIntArray(names::CutFaces, result.CutFaces));
  output->GetCellData()->AddArray(FourIntArray(names::CutSide, result.CutSide));
  vtkNew<vtkFieldData> fields;
  fields->DeepCopy(input->GetFieldData());
  vtkNew<vtkIntArray> betti;
  betti->SetName(names::BettiNumber);
  betti->InsertNextValue(result.Beta1);
  fields->AddArray(betti);
  vtkNew<vtkIntArray> genus;
  genus->SetName(names::BoundaryGenus);
  for (int g : result.BoundaryGenus)
  {
    genus->InsertNextValue(g);
  }
  fields->AddArray(genus);
  vtkNew<vtkDoubleArray> areas;
  areas->SetName("CutArea");
  for (const polycubehex::HandleCut& cut : result.Cuts)
  {
    areas->InsertNextValue(cut.Area);
  }
  fields->AddArray(areas);
  vtkNew<vtkIntArray> subdivided;
  subdivided->SetName("SubdividedTetCount");
  subdivided->InsertNextValue(result.SubdividedTetCount);
  fields->AddArray(subdivided);
  output->SetFieldData(fields);

  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkIntArray> surfaceCutId;
  surfaceCutId->SetName(names::CutId);
  vtkNew<vtkCellArray> polylines;
  vtkNew<vtkIntArray> loopCutId;
  loopCutId->SetName(names::CutId);
  for (std::size_t c = 0; c < result.Cuts.size(); ++c)
  {
    for (const auto& face : result.Cuts[c].Faces)
    {
      const int* local = TetFaces[face[1]];
      const polycubehex::Tets& cells = result.Mesh.Cells;
      const vtkIdType ids[3] = {
        cells(face[0], local[0]), cells(face[0], local[1]), cells(face[0], local[2])
      };
      triangles->InsertNextCell(3, ids);
      surfaceCutId->InsertNextValue(static_cast<int>(c));
    }
    for (const std::vector<int>& loop : result.Cuts[c].Loops)
    {
      polylines->InsertNextCell(static_cast<vtkIdType>(loop.size() + 1));
      for (int v : loop)
      {
        polylines->InsertCellPoint(v);
      }
      polylines->InsertCellPoint(loop.front()); // closed
      loopCutId->InsertNextValue(static_cast<int>(c));
    }
  }
  surfaces->SetPoints(output->GetPoints());
  surfaces->SetPolys(triangles);
  surfaces->GetCellData()->AddArray(surfaceCutId);
  loops->SetPoints(output->GetPoints());
  loops->SetLines(polylines);
  loops->GetCellData()->AddArray(loopCutId);
  return 1;
}

void vtkHandleCutFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MatchedCuts: " << this->MatchedCuts << "\n";
  os << indent << "RecomputeEachStep: " << this->RecomputeEachStep << "\n";
  os << indent << "MaxMinCutRounds: " << this->MaxMinCutRounds << "\n";
  os << indent << "MaxSubdivisionRounds: " << this->MaxSubdivisionRounds << "\n";
}
