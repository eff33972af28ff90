// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPolycubeDeformFilter.h"

#include "PolycubeDeformation.h"
#include "PolycubeHexArrayNames.h"
#include "PolycubeHexArrays.h"
#include "PolycubeHexConversion.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPolycubeDeformFilter);

namespace
{
namespace names = polycubehex::ArrayNames;

} // namespace

vtkPolycubeDeformFilter::vtkPolycubeDeformFilter()
{
  this->SetNumberOfOutputPorts(2);
  // The core owns the defaults (chosen by measurement there); the header and XML repeat them.
  const polycubehex::PolycubeParameters defaults;
  this->AlignInitialRotation = defaults.AlignInitialRotation;
  this->AlignmentWeight = defaults.AlignmentWeight;
  this->AlignmentWeightGrowth = defaults.AlignmentWeightGrowth;
  this->AlignmentEpsilon = defaults.AlignmentEpsilon;
  this->MinAlignmentEpsilon = defaults.MinAlignmentEpsilon;
  this->MaxRounds = defaults.MaxRounds;
  this->ResidualTolerance = defaults.ResidualTolerance;
  this->NormalDifferenceWeight = defaults.NormalDifferenceWeight;
  this->NormalDifferenceAcrossCuts = defaults.NormalDifferenceAcrossCuts;
  this->MonotoneRepairRounds = defaults.MonotoneRepairRounds;
  this->MinChartAreaFraction = defaults.MinChartAreaFraction;
  this->SquashedRetryStretch = defaults.SquashedRetryStretch;
  this->Flatten = defaults.Flatten;
  this->FlattenHomotopySteps = defaults.FlattenHomotopySteps;
}

int vtkPolycubeDeformFilter::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

namespace
{
/// The input's frames for FrameField guidance and, when it has cuts, the cuts and their
/// transitions (the closed form); false with what is missing in `problem`.
bool ReadFrames(vtkUnstructuredGrid* input,
  std::vector<Eigen::Matrix3d>& frames,
  polycubehex::PolycubeCuts& cuts,
  std::string& problem)
{
  cuts = polycubehex::PolycubeCuts();
  frames.clear();
  vtkDataArray* array = input ? input->GetCellData()->GetArray(names::Frame) : nullptr;
  if (!array || array->GetNumberOfComponents() != 9)
  {
    problem = "the cell array 'Frame' (9 components, row a = frame axis a) of vtkFrameFieldFilter "
              "on its input";
    return false;
  }
  // With cuts, the frame fit and the polycube run on the cut mesh, each cut's copies related
  // by its transition and an unknown translation (eq. 8).
  vtkDataArray* transitions = input->GetFieldData()->GetArray(names::CutTransitions);
  if (transitions && transitions->GetNumberOfTuples() > 0)
  {
    vtkDataArray* ids = input->GetCellData()->GetArray(names::CutFaces);
    vtkDataArray* sides = input->GetCellData()->GetArray(names::CutSide);
    if (transitions->GetNumberOfComponents() != 9 || !ids || !sides ||
      ids->GetNumberOfComponents() != 4 || sides->GetNumberOfComponents() != 4 ||
      ids->GetNumberOfTuples() != input->GetNumberOfCells() ||
      sides->GetNumberOfTuples() != input->GetNumberOfCells())
    {
      problem = "the cut cell arrays 'CutFaces' and 'CutSide' (4 components) with the field "
                "'CutTransitions' (9 components per cut), as vtkHandleCutFilter and "
                "vtkFrameFieldFilter write them";
      return false;
    }
    const vtkIdType cellCount = input->GetNumberOfCells();
    cuts.FaceCut.resize(cellCount, 4);
    cuts.FaceSide.resize(cellCount, 4);
    for (vtkIdType t = 0; t < cellCount; ++t)
    {
      for (int k = 0; k < 4; ++k)
      {
        cuts.FaceCut(t, k) = static_cast<int>(ids->GetComponent(t, k));
        cuts.FaceSide(t, k) = static_cast<int>(sides->GetComponent(t, k));
      }
    }
    for (vtkIdType c = 0; c < transitions->GetNumberOfTuples(); ++c)
    {
      Eigen::Matrix3i pi;
      for (int a = 0; a < 9; ++a)
      {
        pi(a / 3, a % 3) = static_cast<int>(std::lround(transitions->GetComponent(c, a)));
      }
      cuts.Transitions.push_back(pi);
    }
  }
  frames.resize(static_cast<size_t>(array->GetNumberOfTuples()));
  double row[9];
  for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
  {
    array->GetTuple(t, row);
    frames[static_cast<size_t>(t)] = Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(row);
  }
  return true;
}
} // namespace

int vtkPolycubeDeformFilter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // 1. Get the input and outputs.
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* surface = vtkPolyData::GetData(outputVector, 1);

  // 2. Check it, and choose the guidance.
  std::vector<Eigen::Matrix3d> frames;
  polycubehex::PolycubeCuts cuts;
  std::string guidanceProblem;
  const bool hasFrames = ReadFrames(input, frames, cuts, guidanceProblem);
  bool frameGuided = false;
  if (this->Guidance == FRAME_FIELD)
  {
    if (!hasFrames)
    {
      vtkErrorMacro(<< "Guidance FrameField needs " << guidanceProblem);
      return 0;
    }
    frameGuided = true;
  }
  // AUTOMATIC: the closed form when the input has a frame field (DESIGN.md), else Uniform. The
  // Guidance field of the output says which one ran.
  if (this->Guidance == AUTOMATIC && hasFrames)
  {
    frameGuided = true;
  }
  if (!frameGuided)
  {
    frames.clear();
    cuts = polycubehex::PolycubeCuts();
  }
  polycubehex::TetMesh mesh;
  std::string why;
  if (!polycubehex::ToTetMesh(input, mesh, why))
  {
    vtkErrorMacro(<< "Cannot deform the input into a polycube: " << why);
    return 0;
  }

  // 3. Call the core.
  polycubehex::PolycubeParameters params;
  params.AlignInitialRotation = this->AlignInitialRotation;
  params.AlignmentWeight = this->AlignmentWeight;
  params.AlignmentWeightGrowth = this->AlignmentWeightGrowth;
  params.AlignmentEpsilon = this->AlignmentEpsilon;
  params.MinAlignmentEpsilon = this->MinAlignmentEpsilon;
  params.MaxRounds = this->MaxRounds;
  params.ResidualTolerance = this->ResidualTolerance;
  params.NormalDifferenceWeight = this->NormalDifferenceWeight;
  params.NormalDifferenceAcrossCuts = this->NormalDifferenceAcrossCuts;
  params.MonotoneRepairRounds = this->MonotoneRepairRounds;
  params.MinChartAreaFraction = this->MinChartAreaFraction;
  params.SquashedRetryStretch = this->SquashedRetryStretch;
  params.Flatten = this->Flatten;
  params.FlattenHomotopySteps = this->FlattenHomotopySteps;
  auto progress = [this](double fraction)
  {
    this->UpdateProgress(fraction);
    return !this->CheckAbort();
  };
  polycubehex::PolycubeResult result;
  polycubehex::Status status =
    polycubehex::ComputePolycube(mesh, params, result, progress, frames, &cuts);
  if (!status && frameGuided && this->Guidance == AUTOMATIC && result.FrameFieldRefused &&
    !this->CheckAbort())
  {
    // Automatic guidance keeps to the closed form only while the frame field describes a valid
    // map; otherwise the l1 polycube (which needs no frame field) still gives the user a mesh.
    vtkWarningMacro(<< "Automatic guidance: the closed form refused the frame field ("
                    << status.Message()
                    << "); the polycube is the l1 one (Uniform guidance) instead. Another frame "
                       "field (e.g. the frame filter's CutMeshBoundaryAlignmentWeight 0 or "
                       "another BoundaryAlignmentWeight) may give the closed form.");
    frameGuided = false;
    frames.clear();
    cuts = polycubehex::PolycubeCuts();
    result = polycubehex::PolycubeResult();
    status = polycubehex::ComputePolycube(mesh, params, result, progress, frames, &cuts);
  }
  if (!status)
  {
    vtkErrorMacro(<< "Polycube deformation failed: " << status.Message());
    return 0;
  }
  for (const std::string& warning : result.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!result.Converged)
  {
    vtkWarningMacro(<< "The polycube residual " << result.Residual << " is above the tolerance "
                    << this->ResidualTolerance << " after " << result.Rounds
                    << " rounds; the charts were flattened anyway.");
  }

  // 4. Attach the outputs: the cut mesh at polycube positions, then its boundary surface.
  polycubehex::TetMesh deformed;
  deformed.Vertices = result.Positions;
  deformed.Cells = result.Cells;
  output->ShallowCopy(polycubehex::ToUnstructuredGrid(deformed));

  const vtkIdType pointCount = result.Positions.rows();
  vtkNew<vtkIdTypeArray> originalPointId;
  originalPointId->SetName(names::OriginalPointId);
  originalPointId->SetNumberOfTuples(pointCount);
  vtkNew<vtkDoubleArray> originalPoints;
  originalPoints->SetName(names::OriginalPoints);
  originalPoints->SetNumberOfComponents(3);
  originalPoints->SetNumberOfTuples(pointCount);
  for (vtkIdType v = 0; v < pointCount; ++v)
  {
    originalPointId->SetValue(v, result.OriginalPointId[v]);
    originalPoints->SetTuple(v, result.OriginalPoints.data() + 3 * v);
  }
  output->GetPointData()->AddArray(originalPointId);
  output->GetPointData()->AddArray(originalPoints);

  // Cell data of the input follows each tet's parent (DESIGN.md: split tets copy it).
  const vtkIdType cellCount = result.Cells.rows();
  vtkCellData* inputCells = input->GetCellData();
  vtkCellData* outputCells = output->GetCellData();
  outputCells->CopyAllocate(inputCells, cellCount);
  vtkNew<vtkIdTypeArray> originalCellId;
  originalCellId->SetName(names::OriginalCellId);
  originalCellId->SetNumberOfTuples(cellCount);
  auto labels = polycubehex::NewArray<vtkIntArray>(names::PolycubeLabels, 4, cellCount);
  for (vtkIdType t = 0; t < cellCount; ++t)
  {
    outputCells->CopyData(inputCells, result.OriginalCellId[t], t);
    originalCellId->SetValue(t, result.OriginalCellId[t]);
    for (int k = 0; k < 4; ++k)
    {
      labels->SetComponent(t, k, result.FaceLabels(t, k));
    }
  }
  if (!outputCells->HasArray(names::OriginalCellId))
  {
    outputCells->AddArray(originalCellId);
  }
  outputCells->AddArray(labels);

  vtkFieldData* fields = output->GetFieldData();
  fields->ShallowCopy(input->GetFieldData());
  polycubehex::SetFieldValue<vtkIntArray>(fields, names::CornerCount, result.CornerCount);
  polycubehex::SetFieldValue<vtkIntArray>(fields, names::InvertedTetCount, result.InvertedTetCount);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, names::PolycubeResidual, result.Residual);
  polycubehex::SetFieldValue<vtkStringArray>(
    fields, names::Guidance, std::string(frameGuided ? "FrameField" : "Uniform"));
  if (frameGuided)
  {
    polycubehex::SetFieldValue<vtkDoubleArray>(fields, "FrameFitResidual", result.FrameFitResidual);
  }
  polycubehex::SetFieldValue<vtkIntArray>(fields, "ChartCount", result.ChartCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "UnflattenedVertexCount", result.UnflattenedVertexCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "ReleasedVertexCount", result.ReleasedVertexCount);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "MaxPlaneDeviation", result.MaxPlaneDeviation);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "CreaseTurnBack", result.CreaseTurnBack);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "CreaseTurnBackBeforeFlattening", result.CreaseTurnBackBeforeFlattening);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "TurnedBackCreaseCount", result.TurnedBackCreaseCount);
  polycubehex::SetFieldValue<vtkIntArray>(fields, "ShavedFaceCount", result.ShavedFaceCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "SquashedCreaseCount", result.SquashedCreaseCount);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "MinCreaseStretch", result.MinCreaseStretch);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "PolycubeSeconds", result.TotalSeconds);
  polycubehex::SetFieldValue<vtkIntArray>(fields, "PolycubeRetried", result.Retried ? 1 : 0);
  vtkNew<vtkDoubleArray> translations; // t_c of x_plus = Pi_c x_minus + t_c; none when uncut
  translations->SetName(names::CutTranslations);
  translations->SetNumberOfComponents(3);
  translations->SetNumberOfTuples(result.CutTranslations.rows());
  for (vtkIdType c = 0; c < result.CutTranslations.rows(); ++c)
  {
    for (int a = 0; a < 3; ++a)
    {
      translations->SetComponent(c, a, result.CutTranslations(c, a));
    }
  }
  fields->AddArray(translations);

  surface->SetPoints(output->GetPoints());
  vtkNew<vtkCellArray> triangles;
  const vtkIdType faceCount = result.BoundaryFaces.rows();
  auto faceLabel = polycubehex::NewArray<vtkIntArray>(names::PolycubeLabel, 1, faceCount);
  auto chartId = polycubehex::NewArray<vtkIntArray>(names::ChartId, 1, faceCount);
  for (vtkIdType f = 0; f < faceCount; ++f)
  {
    const vtkIdType ids[3] = {
      result.BoundaryFaces(f, 0), result.BoundaryFaces(f, 1), result.BoundaryFaces(f, 2)
    };
    triangles->InsertNextCell(3, ids);
    faceLabel->SetValue(f, result.BoundaryFaceLabel[f]);
    chartId->SetValue(f, result.ChartId[f]);
  }
  surface->SetPolys(triangles);
  surface->GetCellData()->AddArray(faceLabel);
  surface->GetCellData()->AddArray(chartId);
  // Where the polycube is defective, so that the user sees where the hexes will be poor.
  if (static_cast<vtkIdType>(result.VertexDefects.size()) == pointCount)
  {
    auto defects = polycubehex::NewArray<vtkIntArray>(names::PolycubeDefect, 1, pointCount);
    for (vtkIdType v = 0; v < pointCount; ++v)
    {
      defects->SetValue(v, result.VertexDefects[static_cast<size_t>(v)]);
    }
    surface->GetPointData()->AddArray(defects);
  }
  return 1;
}

void vtkPolycubeDeformFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Guidance: " << this->Guidance << "\n";
  os << indent << "AlignInitialRotation: " << this->AlignInitialRotation << "\n";
  os << indent << "AlignmentWeight: " << this->AlignmentWeight << "\n";
  os << indent << "AlignmentWeightGrowth: " << this->AlignmentWeightGrowth << "\n";
  os << indent << "AlignmentEpsilon: " << this->AlignmentEpsilon << "\n";
  os << indent << "MinAlignmentEpsilon: " << this->MinAlignmentEpsilon << "\n";
  os << indent << "MaxRounds: " << this->MaxRounds << "\n";
  os << indent << "ResidualTolerance: " << this->ResidualTolerance << "\n";
  os << indent << "NormalDifferenceWeight: " << this->NormalDifferenceWeight << "\n";
  os << indent << "NormalDifferenceAcrossCuts: " << this->NormalDifferenceAcrossCuts << "\n";
  os << indent << "MonotoneRepairRounds: " << this->MonotoneRepairRounds << "\n";
  os << indent << "MinChartAreaFraction: " << this->MinChartAreaFraction << "\n";
  os << indent << "SquashedRetryStretch: " << this->SquashedRetryStretch << "\n";
  os << indent << "Flatten: " << this->Flatten << "\n";
  os << indent << "FlattenHomotopySteps: " << this->FlattenHomotopySteps << "\n";
}
