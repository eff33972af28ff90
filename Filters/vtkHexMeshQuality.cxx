// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHexMeshQuality.h"

#include "HexMeshValidity.h"
#include "PolycubeHexArrayNames.h"
#include "PolycubeHexArrays.h"
#include "PolycubeHexConversion.h"
#include "PolycubeHexSurfaceDistance.h"

#include <vtkAlgorithm.h>
#include <vtkCellData.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMeshQuality.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkStaticPointLocator.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkHexMeshQuality);

namespace
{
namespace names = polycubehex::ArrayNames;

/// Bin 0 holds (-inf, 0]; bin k = 1..10 holds ((k-1)/10, k/10].
constexpr int HistogramBins = 11;

/// Verdict's hex scaled Jacobian of every cell, with its summary.
struct ScaledJacobianSummary
{
  vtkSmartPointer<vtkDoubleArray> Values;
  double Min = std::numeric_limits<double>::infinity();
  double Mean = 0.0;
  int InvertedCount = 0;
  vtkIdType FirstInverted = -1;
  std::array<int, HistogramBins> Histogram{};
};

ScaledJacobianSummary ComputeScaledJacobians(vtkUnstructuredGrid* hexes)
{
  ScaledJacobianSummary summary;
  const vtkIdType count = hexes->GetNumberOfCells();
  summary.Values = vtkSmartPointer<vtkDoubleArray>::New();
  summary.Values->SetName(names::ScaledJacobian);
  summary.Values->SetNumberOfTuples(count);
  vtkNew<vtkGenericCell> cell;
  double sum = 0.0; // in cell order, so the mean does not depend on threads
  for (vtkIdType c = 0; c < count; ++c)
  {
    hexes->GetCell(c, cell);
    double value = vtkMeshQuality::HexScaledJacobian(cell);
    // A true scaled Jacobian lies in [-1, 1]. Verdict returns its sentinel 1e30 for a hex with
    // a zero-length edge (a repeated or coincident vertex): that hex has no volume at a
    // corner, so it gets 0 and counts as inverted, instead of skewing the mean.
    if (!(std::fabs(value) <= 1.0 + 1e-6))
    {
      value = 0.0;
    }
    summary.Values->SetValue(c, value);
    sum += value;
    summary.Min = std::min(summary.Min, value);
    if (value <= 0.0)
    {
      ++summary.Histogram[0];
      summary.FirstInverted = summary.InvertedCount++ == 0 ? c : summary.FirstInverted;
    }
    else
    {
      const int bin = static_cast<int>(std::ceil(value * 10.0));
      ++summary.Histogram[std::min(std::max(bin, 1), HistogramBins - 1)];
    }
  }
  summary.Mean = count > 0 ? sum / static_cast<double>(count) : 0.0;
  return summary;
}

/// Pairs of vertices closer than `tolerance`, with the first pair described in `first`.
vtkIdType CountCloseVertexPairs(vtkDataSet* hexes, double tolerance, std::string& first)
{
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(hexes);
  locator->BuildLocator();
  vtkNew<vtkIdList> nearby;
  vtkIdType pairs = 0;
  for (vtkIdType p = 0; p < hexes->GetNumberOfPoints(); ++p)
  {
    double x[3];
    hexes->GetPoint(p, x);
    locator->FindPointsWithinRadius(tolerance, x, nearby);
    for (vtkIdType i = 0; i < nearby->GetNumberOfIds(); ++i)
    {
      const vtkIdType q = nearby->GetId(i);
      if (q <= p)
      {
        continue; // each pair once, and not the point itself
      }
      if (pairs++ == 0)
      {
        std::ostringstream message;
        message << "first pair is vertices " << p << " and " << q << "\n";
        first = message.str();
      }
    }
  }
  return pairs;
}

/// Everything vtkHexMeshQuality computes; `progress` may be empty.
bool Compute(vtkUnstructuredGrid* hexes,
  vtkDataSet* reference,
  vtkUnstructuredGrid* output,
  std::string& why,
  int numberOfDistanceSamples,
  int randomSeed,
  const polycubehex::Progress& progress)
{
  // Check: hexahedra only, and at least one.
  polycubehex::HexMesh mesh;
  if (!polycubehex::ToHexMesh(hexes, mesh, why))
  {
    return false;
  }
  polycubehex::HexMeshValidity validity;
  const polycubehex::Status status = polycubehex::checkHexMeshValidity(mesh, validity);
  if (!status)
  {
    why = status.Message();
    return false;
  }
  if (!polycubehex::ReportProgress(progress, 0.1))
  {
    why = "aborted";
    return false;
  }

  // Geometry: scaled Jacobians and coincident vertices.
  const ScaledJacobianSummary jacobians = ComputeScaledJacobians(hexes);
  std::string closePair;
  const vtkIdType closePairs = CountCloseVertexPairs(hexes, 1e-9 * hexes->GetLength(), closePair);
  if (!polycubehex::ReportProgress(progress, 0.3))
  {
    why = "aborted";
    return false;
  }

  // Distances, only against a reference.
  polycubehex::SurfaceDistance distance;
  if (reference)
  {
    const auto distanceProgress = [&progress](double fraction)
    { return polycubehex::ReportProgress(progress, 0.3 + 0.7 * fraction); };
    if (!polycubehex::ComputeSurfaceDistance(hexes,
          reference,
          numberOfDistanceSamples,
          static_cast<unsigned int>(randomSeed),
          distance,
          why,
          distanceProgress))
    {
      return false;
    }
  }

  const bool valid = validity.IsValid() && jacobians.InvertedCount == 0 && closePairs == 0;
  std::ostringstream report;
  report << (valid ? "valid" : "INVALID") << " hex mesh: " << validity.HexCount
         << " hexes, scaled Jacobian min " << jacobians.Min << " mean " << jacobians.Mean << "\n"
         << validity.Report;
  if (jacobians.InvertedCount > 0)
  {
    report << "hexes with scaled Jacobian <= 0: " << jacobians.InvertedCount << ", first is hex "
           << jacobians.FirstInverted << " (" << jacobians.Values->GetValue(jacobians.FirstInverted)
           << ")\n";
  }
  if (closePairs > 0)
  {
    report << "vertex pairs closer than 1e-9 of the bounding-box diagonal: " << closePairs << ", "
           << closePair;
  }

  // Attach: a shallow copy of the hexes plus the new arrays. ShallowCopy gives the output its
  // own field data object, so the input's field data is left untouched.
  if (output != hexes)
  {
    output->ShallowCopy(hexes);
  }
  output->GetCellData()->AddArray(jacobians.Values);
  vtkFieldData* fieldData = output->GetFieldData();
  polycubehex::SetFieldValue<vtkIntArray>(fieldData, names::HexCount, validity.HexCount);
  polycubehex::SetFieldValue<vtkDoubleArray>(fieldData, names::ScaledJacobianMin, jacobians.Min);
  polycubehex::SetFieldValue<vtkDoubleArray>(fieldData, names::ScaledJacobianMean, jacobians.Mean);
  vtkNew<vtkIntArray> histogram;
  histogram->SetName(names::ScaledJacobianHistogram);
  histogram->SetNumberOfTuples(HistogramBins);
  for (int bin = 0; bin < HistogramBins; ++bin)
  {
    histogram->SetValue(bin, jacobians.Histogram[bin]);
  }
  fieldData->AddArray(histogram);
  polycubehex::SetFieldValue<vtkIntArray>(
    fieldData, names::InvertedHexCount, jacobians.InvertedCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fieldData, names::DegenerateHexCount, validity.DegenerateHexCount);
  polycubehex::SetFieldValue<vtkIntArray>(
    fieldData, names::IrregularBoundaryVertexCount, validity.IrregularBoundaryVertexCount);
  polycubehex::SetFieldValue<vtkIntArray>(fieldData, names::ValidHexMesh, valid ? 1 : 0);
  polycubehex::SetFieldValue<vtkStringArray>(fieldData, names::ValidityReport, report.str());
  if (reference)
  {
    polycubehex::SetFieldValue<vtkDoubleArray>(fieldData, names::DistanceMean, distance.Mean);
    polycubehex::SetFieldValue<vtkDoubleArray>(
      fieldData, names::DistanceHausdorff, distance.Hausdorff);
  }
  polycubehex::ReportProgress(progress, 1.0);
  return true;
}
} // namespace

vtkHexMeshQuality::vtkHexMeshQuality()
{
  this->SetNumberOfInputPorts(2);
}

void vtkHexMeshQuality::SetReferenceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkHexMeshQuality::SetReferenceData(vtkDataObject* reference)
{
  this->SetInputData(1, reference);
}

int vtkHexMeshQuality::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
    return 1;
  }
  // The reference may be a surface, a tet mesh or a hex mesh: its boundary is what counts.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

bool vtkHexMeshQuality::ComputeQuality(vtkUnstructuredGrid* hexes,
  vtkDataSet* reference,
  vtkUnstructuredGrid* output,
  std::string& why,
  int numberOfDistanceSamples,
  int randomSeed)
{
  if (!hexes || !output)
  {
    why = "no hex mesh or no output";
    return false;
  }
  return Compute(hexes, reference, output, why, numberOfDistanceSamples, randomSeed, {});
}

int vtkHexMeshQuality::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // 1. Get the input: the hex mesh and the optional reference.
  vtkUnstructuredGrid* hexes = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkDataSet* reference = vtkDataSet::GetData(inputVector[1], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);

  // 2.-4. Check, compute and attach (shared with the hex extraction filter).
  const auto progress = [this](double fraction)
  {
    this->UpdateProgress(fraction);
    return !this->CheckAbort();
  };
  std::string why;
  if (!hexes ||
    !Compute(
      hexes, reference, output, why, this->NumberOfDistanceSamples, this->RandomSeed, progress))
  {
    vtkErrorMacro(<< (hexes ? why : std::string("no input hex mesh")));
    return 0;
  }
  return 1;
}

void vtkHexMeshQuality::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfDistanceSamples: " << this->NumberOfDistanceSamples << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
}
