// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHexExtractFilter.h"

#include "HexExtraction.h"
#include "PolycubeHexArrayNames.h"
#include "PolycubeHexArrays.h"
#include "PolycubeHexConversion.h"
#include "vtkHexMeshQuality.h"

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
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkHexExtractFilter);

namespace
{
namespace names = polycubehex::ArrayNames;

// The header spells the default out to stay free of the core's headers.
static_assert(polycubehex::DefaultSoftFeatureAngle == 20.0,
  "vtkHexExtractFilter::SoftFeatureAngle's default must follow the core's");

/// Reads the deform filter's output into the core's input, or says what is missing.
bool ToPolycubeTetMesh(vtkUnstructuredGrid* input,
  polycubehex::PolycubeTetMesh& mesh,
  std::string& why)
{
  polycubehex::TetMesh tets;
  if (!polycubehex::ToTetMesh(input, tets, why))
  {
    return false;
  }
  vtkDataArray* original = input->GetPointData()->GetArray(names::OriginalPoints);
  vtkDataArray* labels = input->GetCellData()->GetArray(names::PolycubeLabels);
  if (!original || original->GetNumberOfComponents() != 3)
  {
    why = std::string("the input has no 3-component point array '") + names::OriginalPoints +
      "': connect the output of the Polycube Deform filter";
    return false;
  }
  if (!labels || labels->GetNumberOfComponents() != 4)
  {
    why = std::string("the input has no 4-component cell array '") + names::PolycubeLabels +
      "': connect the output of the Polycube Deform filter";
    return false;
  }
  mesh.PolycubeVertices = tets.Vertices;
  mesh.Cells = tets.Cells;
  mesh.OriginalVertices.resize(tets.Vertices.rows(), 3);
  for (Eigen::Index v = 0; v < tets.Vertices.rows(); ++v)
  {
    original->GetTuple(v, mesh.OriginalVertices.data() + 3 * v);
  }
  if (!mesh.OriginalVertices.allFinite() || !mesh.PolycubeVertices.allFinite())
  {
    why = "the input has non-finite point coordinates";
    return false;
  }
  mesh.FaceLabels.resize(tets.Cells.rows(), 4);
  for (Eigen::Index t = 0; t < tets.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      mesh.FaceLabels(t, k) = static_cast<int>(labels->GetComponent(t, k));
    }
  }
  return true;
}

/// Reads the cuts of a closed-form polycube (field CutTransitions and CutTranslations); none
/// for a uniform one.
bool ReadCuts(vtkUnstructuredGrid* input, polycubehex::PolycubeTetMesh& mesh, std::string& why)
{
  vtkDataArray* translations = input->GetFieldData()->GetArray(names::CutTranslations);
  if (!translations || translations->GetNumberOfTuples() == 0)
  {
    return true;
  }
  vtkDataArray* transitions = input->GetFieldData()->GetArray(names::CutTransitions);
  if (translations->GetNumberOfComponents() != 3 || !transitions ||
    transitions->GetNumberOfComponents() != 9 ||
    transitions->GetNumberOfTuples() != translations->GetNumberOfTuples())
  {
    why = std::string("the polycube is cut open (field '") + names::CutTranslations +
      "') but its field '" + names::CutTransitions +
      "' is missing or does not hold one 9-component rotation per cut";
    return false;
  }
  for (vtkIdType c = 0; c < translations->GetNumberOfTuples(); ++c)
  {
    Eigen::Matrix3i rotation;
    Eigen::Vector3d translation;
    for (int a = 0; a < 9; ++a)
    {
      rotation(a / 3, a % 3) = static_cast<int>(std::lround(transitions->GetComponent(c, a)));
    }
    for (int a = 0; a < 3; ++a)
    {
      translation[a] = translations->GetComponent(c, a);
    }
    if (rotation.cast<double>().determinant() != 1.0 ||
      (rotation.transpose() * rotation) != Eigen::Matrix3i::Identity())
    {
      why = "cut " + std::to_string(c) + " has a transition that is not a cube rotation";
      return false;
    }
    mesh.CutRotations.push_back(rotation);
    mesh.CutTranslations.push_back(translation);
  }
  return true;
}

/// The input tets at their original positions: the reference surface for distances. The copies
/// of a cut polycube's points are merged, so that the cut faces are inside again.
vtkSmartPointer<vtkUnstructuredGrid> OriginalTets(const polycubehex::PolycubeTetMesh& mesh)
{
  std::map<std::array<double, 3>, int> merged;
  std::vector<int> index(static_cast<size_t>(mesh.OriginalVertices.rows()));
  std::vector<Eigen::RowVector3d> points;
  for (Eigen::Index v = 0; v < mesh.OriginalVertices.rows(); ++v)
  {
    const std::array<double, 3> key = {
      mesh.OriginalVertices(v, 0), mesh.OriginalVertices(v, 1), mesh.OriginalVertices(v, 2)
    };
    const auto found = merged.emplace(key, static_cast<int>(points.size()));
    if (found.second)
    {
      points.push_back(mesh.OriginalVertices.row(v));
    }
    index[static_cast<size_t>(v)] = found.first->second;
  }
  polycubehex::TetMesh tets;
  tets.Vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t p = 0; p < points.size(); ++p)
  {
    tets.Vertices.row(static_cast<Eigen::Index>(p)) = points[p];
  }
  tets.Cells = mesh.Cells;
  for (Eigen::Index t = 0; t < tets.Cells.rows(); ++t)
  {
    for (int k = 0; k < 4; ++k)
    {
      tets.Cells(t, k) = index[static_cast<size_t>(tets.Cells(t, k))];
    }
  }
  return polycubehex::ToUnstructuredGrid(tets);
}

} // namespace

vtkHexExtractFilter::vtkHexExtractFilter()
{
  this->SetNumberOfOutputPorts(2);
}

int vtkHexExtractFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

int vtkHexExtractFilter::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkPolyData");
  return 1;
}

int vtkHexExtractFilter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // 1. Get the input and outputs.
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* hexOutput = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* quadOutput = vtkPolyData::GetData(outputVector, 1);

  // 2. Check and convert it; a closed-form polycube also brings its cuts.
  polycubehex::PolycubeTetMesh mesh;
  std::string why;
  if (!ToPolycubeTetMesh(input, mesh, why) || !ReadCuts(input, mesh, why))
  {
    vtkErrorMacro(<< "Cannot extract hexes: " << why);
    return 0;
  }

  // 3. Call the core; progress to 80%, the quality measures take the rest.
  polycubehex::HexExtractionParameters params;
  params.TargetHexCount = this->TargetHexCount;
  params.TargetEdgeLength = this->TargetEdgeLength;
  params.Padding = this->Padding;
  params.PaddingPlacement = this->PaddingPlacement;
  params.Smoothing = this->Smoothing;
  params.SmoothingIterations = this->SmoothingIterations;
  params.Untangling = this->Untangling;
  params.MapSmoothing = this->MapSmoothing;
  params.RoundingCandidates = this->RoundingCandidates;
  params.SoftFeatureAngle = this->SoftFeatureAngle;
  params.Polish = this->Polish;
  params.PolishReleaseAngle = this->PolishReleaseAngle;
  params.PolishSharpEdgeAngle = this->PolishSharpEdgeAngle;
  params.MeanSearchSweeps = this->MeanSearchSweeps;
  params.UntanglingPaths = this->UntanglingPaths;
  params.ScaleRetries = this->ScaleRetries;
  params.ScaleRetryBelow = this->ScaleRetryBelow;
  auto progress = [this](double fraction)
  {
    this->UpdateProgress(0.8 * fraction);
    return !this->CheckAbort();
  };
  polycubehex::HexExtractionResult result;
  const polycubehex::Status status = polycubehex::extractHexMesh(mesh, params, result, progress);
  if (!status)
  {
    vtkErrorMacro(<< "Hex extraction failed: " << status.Message());
    return 0;
  }

  for (const std::string& warning : result.Warnings)
  {
    vtkWarningMacro(<< warning);
  }

  // 4. Attach the outputs: quality through vtkMeshQuality, distances to the input boundary.
  auto hexes = polycubehex::ToUnstructuredGrid(result.Mesh);
  vtkSmartPointer<vtkUnstructuredGrid> reference;
  if (this->ComputeDistances)
  {
    reference = OriginalTets(mesh);
  }
  if (!vtkHexMeshQuality::ComputeQuality(
        hexes, reference, hexOutput, why, this->NumberOfDistanceSamples, 0))
  {
    vtkErrorMacro(<< "Quality of the extracted hexes: " << why);
    return 0;
  }
  vtkFieldData* fields = hexOutput->GetFieldData();
  for (int a = 0; a < input->GetFieldData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = input->GetFieldData()->GetAbstractArray(a);
    if (array && array->GetName() && !fields->HasArray(array->GetName()))
    {
      fields->AddArray(array);
    }
  }
  polycubehex::SetFieldValue<vtkIntArray>(fields, "PaddingHexCount", result.PaddingHexCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "PlacedPaddingVertexCount", result.PlacedPaddingVertexCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "OptimizedPaddingVertexCount", result.OptimizedPaddingVertexCount);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields,
    "PaddingScaledJacobianMeanBeforePlacement",
    result.PaddingScaledJacobianMeanBeforePlacement);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "PaddingScaledJacobianMean", result.PaddingScaledJacobianMean);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "LatticeScale", result.LatticeScale);
  if (!result.IntegerCutTranslations.empty())
  {
    // Each cut's translation in hex edges: the seam's lattice shift (data contract).
    vtkNew<vtkIntArray> integerTranslations;
    integerTranslations->SetName(names::IntegerCutTranslations);
    integerTranslations->SetNumberOfComponents(3);
    integerTranslations->SetNumberOfTuples(
      static_cast<vtkIdType>(result.IntegerCutTranslations.size()));
    for (size_t c = 0; c < result.IntegerCutTranslations.size(); ++c)
    {
      for (int a = 0; a < 3; ++a)
      {
        integerTranslations->SetComponent(
          static_cast<vtkIdType>(c), a, std::round(result.IntegerCutTranslations[c][a]));
      }
    }
    fields->AddArray(integerTranslations);
  }
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "RoundingInvertedTetCount", result.RoundingInvertedTetCount);
  polycubehex::SetFieldValue<vtkStringArray>(fields, "RoundingPath", result.RoundingPath);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "MapEnergyBefore", result.MapEnergyBefore);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "MapEnergyAfter", result.MapEnergyAfter);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "MapSmoothingIterations", result.MapSmoothingIterations);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "RoundingSeconds", result.RoundingSeconds);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "ScaledJacobianMinBeforeSmoothing", result.ScaledJacobianMinBeforeSmoothing);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "ScaledJacobianMeanBeforeSmoothing", result.ScaledJacobianMeanBeforeSmoothing);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "ScaledJacobianMinAfterUntangling", result.ScaledJacobianMinAfterUntangling);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "ScaledJacobianMinBeforePolish", result.ScaledJacobianMinBeforePolish);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "PolishReleasedVertexCount", result.PolishReleasedVertexCount);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "ScaledJacobianMeanAfterUntangling", result.ScaledJacobianMeanAfterUntangling);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "InvertedHexCountAfterUntangling", result.InvertedHexCountAfterUntangling);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "ReleasedBoundaryVertexCount", result.ReleasedBoundaryVertexCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "RemovedDoubletHexCount", result.RemovedDoubletHexCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "RemovedPinchHexCount", result.RemovedPinchHexCount);
  polycubehex::SetFieldValue<vtkIntArray>(fields, "UntanglingRounds", result.UntanglingRounds);
  polycubehex::SetFieldValue<vtkIntArray>(fields, "UntanglingPath", result.UntanglingPath);
  polycubehex::SetFieldValue<vtkIntArray>(
    fields, "UntanglingIterations", result.UntanglingIterations);
  polycubehex::SetFieldValue<vtkIntArray>(fields, "SmoothingSweeps", result.SmoothingSweeps);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "UntanglingSeconds", result.UntanglingSeconds);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "SmoothingSeconds", result.SmoothingSeconds);
  polycubehex::SetFieldValue<vtkDoubleArray>(
    fields, "ScaleFactor", result.LatticeScale / result.TargetLatticeScale);
  polycubehex::SetFieldValue<vtkIntArray>(fields, "ScaleRetryCount", result.ScaleRetryCount);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "DiscardedSeconds", result.DiscardedSeconds);
  polycubehex::SetFieldValue<vtkDoubleArray>(fields, "ExtractionSeconds", result.TotalSeconds());

  quadOutput->SetPoints(hexOutput->GetPoints());
  vtkNew<vtkCellArray> quads;
  vtkNew<vtkIntArray> quadLabels;
  quadLabels->SetName(names::PolycubeLabel);
  for (Eigen::Index q = 0; q < result.BoundaryQuads.rows(); ++q)
  {
    const vtkIdType ids[4] = { result.BoundaryQuads(q, 0),
      result.BoundaryQuads(q, 1),
      result.BoundaryQuads(q, 2),
      result.BoundaryQuads(q, 3) };
    quads->InsertNextCell(4, ids);
    quadLabels->InsertNextValue(q < static_cast<Eigen::Index>(result.BoundaryQuadLabels.size())
        ? result.BoundaryQuadLabels[q]
        : -1);
  }
  quadOutput->SetPolys(quads);
  quadOutput->GetCellData()->AddArray(quadLabels);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkHexExtractFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetHexCount: " << this->TargetHexCount << "\n";
  os << indent << "TargetEdgeLength: " << this->TargetEdgeLength << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
  os << indent << "PaddingPlacement: " << this->PaddingPlacement << "\n";
  os << indent << "Smoothing: " << this->Smoothing << "\n";
  os << indent << "SmoothingIterations: " << this->SmoothingIterations << "\n";
  os << indent << "Untangling: " << this->Untangling << "\n";
  os << indent << "MapSmoothing: " << this->MapSmoothing << "\n";
  os << indent << "RoundingCandidates: " << this->RoundingCandidates << "\n";
  os << indent << "SoftFeatureAngle: " << this->SoftFeatureAngle << "\n";
  os << indent << "Polish: " << (this->Polish ? "On" : "Off") << "\n";
  os << indent << "PolishReleaseAngle: " << this->PolishReleaseAngle << "\n";
  os << indent << "PolishSharpEdgeAngle: " << this->PolishSharpEdgeAngle << "\n";
  os << indent << "MeanSearchSweeps: " << this->MeanSearchSweeps << "\n";
  os << indent << "UntanglingPaths: " << this->UntanglingPaths << "\n";
  os << indent << "ScaleRetries: " << this->ScaleRetries << "\n";
  os << indent << "ScaleRetryBelow: " << this->ScaleRetryBelow << "\n";
  os << indent << "ComputeDistances: " << this->ComputeDistances << "\n";
  os << indent << "NumberOfDistanceSamples: " << this->NumberOfDistanceSamples << "\n";
}
