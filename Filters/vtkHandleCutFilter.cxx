// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHandleCutFilter.h"

#include "HandleCuts.h"
#include "PolycubeHexArrayNames.h"
#include "PolycubeHexConversion.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
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

  // 4. Attach the outputs: the same tets with the cut arrays, the cut surfaces, the loops.
  output->ShallowCopy(input);
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
      const vtkIdType ids[3] = { mesh.Cells(face[0], local[0]), mesh.Cells(face[0], local[1]),
        mesh.Cells(face[0], local[2]) };
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
  surfaces->SetPoints(input->GetPoints());
  surfaces->SetPolys(triangles);
  surfaces->GetCellData()->AddArray(surfaceCutId);
  loops->SetPoints(input->GetPoints());
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
}
