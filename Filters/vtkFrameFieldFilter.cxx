// SPDX-License-Identifier: BSD-3-Clause
#include "vtkFrameFieldFilter.h"

#include "FrameField.h"
#include "PolycubeHexArrayNames.h"
#include "PolycubeHexArrays.h"
#include "PolycubeHexConversion.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>

vtkStandardNewMacro(vtkFrameFieldFilter);

namespace
{
namespace names = polycubehex::ArrayNames;

/// Reads `CutFaces` and `CutSide` when both are there; an empty CutFaces otherwise.
bool ReadCuts(vtkUnstructuredGrid* input, polycubehex::CutFaces& cuts, std::string& why)
{
  vtkDataArray* ids = input->GetCellData()->GetArray(names::CutFaces);
  vtkDataArray* sides = input->GetCellData()->GetArray(names::CutSide);
  if (!ids && !sides)
  {
    return true;
  }
  if (!ids || !sides || ids->GetNumberOfComponents() != 4 || sides->GetNumberOfComponents() != 4)
  {
    why = std::string("the cell arrays '") + names::CutFaces + "' and '" + names::CutSide +
      "' must both be present with 4 components (connect the Handle Cut filter's output)";
    return false;
  }
  const vtkIdType count = input->GetNumberOfCells();
  cuts.Ids.resize(count, 4);
  cuts.Sides.resize(count, 4);
  for (vtkIdType t = 0; t < count; ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      cuts.Ids(t, k) = static_cast<int>(ids->GetComponent(t, k));
      cuts.Sides(t, k) = static_cast<int>(sides->GetComponent(t, k));
    }
  }
  return true;
}

} // namespace

vtkFrameFieldFilter::vtkFrameFieldFilter()
{
  this->SetNumberOfOutputPorts(3);
}

int vtkFrameFieldFilter::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

int vtkFrameFieldFilter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // 1. Get the input and outputs.
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* glyphs = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* singular = vtkPolyData::GetData(outputVector, 2);

  // 2. Check and convert it.
  polycubehex::TetMesh mesh;
  polycubehex::CutFaces cuts;
  std::string why;
  if (!polycubehex::ToTetMesh(input, mesh, why) || !ReadCuts(input, cuts, why))
  {
    vtkErrorMacro(<< "Cannot compute a frame field: " << why);
    return 0;
  }

  // 3. Call the core.
  polycubehex::FrameFieldParameters params;
  params.BoundaryAlignmentWeight = this->BoundaryAlignmentWeight;
  params.CutMeshBoundaryAlignmentWeight = this->CutMeshBoundaryAlignmentWeight;
  params.AlignmentWeight = this->AlignmentWeight;
  params.NormalDifferenceWeight = this->NormalDifferenceWeight;
  params.NormalDifferenceMaxAngle = this->NormalDifferenceMaxAngle;
  params.OrthogonalityWeight = this->OrthogonalityWeight;
  params.L1Epsilon = this->L1Epsilon;
  params.GradientTolerance = this->GradientTolerance;
  params.MaxIterations = this->MaxIterations;
  auto progress = [this](double fraction)
  {
    this->UpdateProgress(fraction);
    return !this->CheckAbort();
  };
  polycubehex::FrameFieldResult result;
  const polycubehex::Status status =
    polycubehex::ComputeFrameField(mesh, cuts, params, result, progress);
  if (!status)
  {
    vtkErrorMacro(<< "Frame field failed: " << status.Message());
    return 0;
  }
  if (!result.Converged)
  {
    vtkWarningMacro(<< "L-BFGS stopped after " << result.FrameIterations
                    << " iterations with gradient norm " << result.FinalGradientNorm
                    << " above the tolerance " << this->GradientTolerance);
  }

  // 4. Attach the outputs.
  output->ShallowCopy(input);
  const vtkIdType cellCount = input->GetNumberOfCells();
  auto frame = polycubehex::NewArray<vtkDoubleArray>(names::Frame, 9, cellCount);
  auto axisU = polycubehex::NewArray<vtkDoubleArray>(names::FrameU, 3, cellCount);
  auto axisV = polycubehex::NewArray<vtkDoubleArray>(names::FrameV, 3, cellCount);
  auto axisW = polycubehex::NewArray<vtkDoubleArray>(names::FrameW, 3, cellCount);
  for (vtkIdType t = 0; t < cellCount; ++t)
  {
    const double* rotation = result.Frames.data() + 9 * t;
    frame->SetTuple(t, rotation);
    axisU->SetTuple(t, rotation);
    axisV->SetTuple(t, rotation + 3);
    axisW->SetTuple(t, rotation + 6);
  }
  vtkCellData* cellData = output->GetCellData();
  cellData->AddArray(frame);
  cellData->AddArray(axisU);
  cellData->AddArray(axisV);
  cellData->AddArray(axisW);

  vtkNew<vtkFieldData> fields;
  fields->DeepCopy(input->GetFieldData());
  vtkNew<vtkIntArray> transitions;
  transitions->SetName(names::CutTransitions);
  transitions->SetNumberOfComponents(9);
  for (Eigen::Index c = 0; c < result.CutTransitions.rows(); ++c)
  {
    for (int k = 0; k < 9; ++k)
    {
      transitions->InsertNextValue(result.CutTransitions(c, k));
    }
  }
  fields->AddArray(transitions);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, names::SingularEdgeCount, result.SingularEdgeCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, names::InteriorSingularEdgeCount, result.InteriorSingularEdgeCount);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "MaxSingularEdgeDepth", result.MaxSingularEdgeDepth);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, names::BoundaryAlignmentError, result.BoundaryAlignmentError);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, names::FrameEnergy, result.FrameEnergy);
  polycubehex::SetFieldValue<vtkIntArray>(fields, names::FrameIterations, result.FrameIterations);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "InitialAlignmentWeight", result.InitialAlignmentWeight);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "AlignedSingularEdgeCount", result.AlignedSingularEdgeCount);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields,
    "FrameSeconds",
    result.InitialFieldSeconds + result.MatchingSeconds + result.OptimizationSeconds +
      result.MeasureSeconds + result.DiscardedSeconds);
  output->SetFieldData(fields);

  // Glyph points: every stride-th tet centre.
  const vtkIdType stride = this->MaximumGlyphCount > 0
    ? std::max<vtkIdType>(1, (cellCount + this->MaximumGlyphCount - 1) / this->MaximumGlyphCount)
    : 1;
  vtkNew<vtkPoints> centres;
  centres->SetDataTypeToDouble();
  const vtkIdType glyphCount = (cellCount + stride - 1) / stride;
  auto glyphU = polycubehex::NewArray<vtkDoubleArray>(names::FrameU, 3, glyphCount);
  auto glyphV = polycubehex::NewArray<vtkDoubleArray>(names::FrameV, 3, glyphCount);
  auto glyphW = polycubehex::NewArray<vtkDoubleArray>(names::FrameW, 3, glyphCount);
  vtkNew<vtkCellArray> vertices;
  for (vtkIdType g = 0; g < glyphCount; ++g)
  {
    const vtkIdType t = g * stride;
    Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k)
    {
      centre += mesh.Vertices.row(mesh.Cells(t, k)) / 4.0;
    }
    centres->InsertNextPoint(centre.data());
    vertices->InsertNextCell(1, &g);
    glyphU->SetTuple(g, axisU->GetTuple(t));
    glyphV->SetTuple(g, axisV->GetTuple(t));
    glyphW->SetTuple(g, axisW->GetTuple(t));
  }
  glyphs->SetPoints(centres);
  glyphs->SetVerts(vertices);
  glyphs->GetPointData()->AddArray(glyphU);
  glyphs->GetPointData()->AddArray(glyphV);
  glyphs->GetPointData()->AddArray(glyphW);
  glyphs->GetPointData()->SetActiveVectors(names::FrameU);

  // Singular edges as lines.
  singular->SetPoints(output->GetPoints());
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> type;
  type->SetName(names::SingularityType);
  auto depth = polycubehex::NewArray<vtkDoubleArray>("SingularEdgeDepth", 1, 0);
  for (const polycubehex::SingularEdge& edge : result.SingularEdges)
  {
    const vtkIdType ids[2] = { edge.Vertices[0], edge.Vertices[1] };
    lines->InsertNextCell(2, ids);
    type->InsertNextValue(static_cast<int>(edge.Type));
    depth->InsertNextValue(edge.Depth);
  }
  singular->SetLines(lines);
  singular->GetCellData()->AddArray(type);
  singular->GetCellData()->AddArray(depth);
  return 1;
}

void vtkFrameFieldFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BoundaryAlignmentWeight: " << this->BoundaryAlignmentWeight << "\n";
  os << indent << "CutMeshBoundaryAlignmentWeight: " << this->CutMeshBoundaryAlignmentWeight
     << "\n";
  os << indent << "AlignmentWeight: " << this->AlignmentWeight << "\n";
  os << indent << "NormalDifferenceWeight: " << this->NormalDifferenceWeight << "\n";
  os << indent << "NormalDifferenceMaxAngle: " << this->NormalDifferenceMaxAngle << "\n";
  os << indent << "OrthogonalityWeight: " << this->OrthogonalityWeight << "\n";
  os << indent << "L1Epsilon: " << this->L1Epsilon << "\n";
  os << indent << "GradientTolerance: " << this->GradientTolerance << "\n";
  os << indent << "MaxIterations: " << this->MaxIterations << "\n";
  os << indent << "MaximumGlyphCount: " << this->MaximumGlyphCount << "\n";
}
