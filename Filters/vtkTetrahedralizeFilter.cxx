// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTetrahedralizeFilter.h"

#include "PolycubeHexArrayNames.h"
#include "PolycubeHexConversion.h"
#include "SurfaceCheck.h"
#include "Tetrahedralize.h"

#include <vtkAlgorithm.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStaticCleanPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <string>

vtkStandardNewMacro(vtkTetrahedralizeFilter);

namespace
{
/// Input triangles with a smaller angle are reported (the shipped models' smallest is 5.4
/// degrees, on fertility; decimated or CAD-exported surfaces go down to 0.001).
constexpr double SmallAngleDegrees = 1.0;

/// Merges exactly coincident points (readers of OBJ and STL duplicate them per face), keeping
/// every cell as it is so that the surface check sees the input's real defects.
vtkSmartPointer<vtkPolyData> MergeCoincidentPoints(vtkPolyData* input)
{
  vtkNew<vtkPolyData> copy;
  copy->ShallowCopy(input);
  vtkNew<vtkStaticCleanPolyData> clean;
  clean->SetInputData(copy);
  clean->ToleranceIsAbsoluteOn();
  clean->SetAbsoluteTolerance(0.0);
  clean->ConvertPolysToLinesOff();
  clean->ConvertLinesToPointsOff();
  clean->ConvertStripsToPolysOff();
  clean->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  clean->Update();
  return clean->GetOutput();
}
} // namespace

int vtkTetrahedralizeFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkTetrahedralizeFilter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // 1. Get the input.
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (!input || input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro(<< "the input has no triangles: expected a closed triangle surface");
    return 0;
  }

  // 2. Check: a triangle surface, coincident points merged (the core checks the rest).
  this->UpdateProgress(0.0);
  vtkSmartPointer<vtkPolyData> merged = MergeCoincidentPoints(input);
  vtkDebugMacro(<< "merged " << input->GetNumberOfPoints() - merged->GetNumberOfPoints()
                << " coincident or unused points");
  polycubehex::SurfaceMesh surface;
  std::string why;
  if (!polycubehex::ToSurfaceMesh(merged, surface, why))
  {
    vtkErrorMacro(<< why);
    return 0;
  }

  // 3. Call the core: TetGen, from 5% to 95% of the progress.
  polycubehex::TetrahedralizeParameters params;
  params.RadiusEdgeRatio = this->RadiusEdgeRatio;
  params.MaxTetVolume = this->MaxTetVolume;
  params.TargetTetCount = this->TargetTetCount;
  params.PreserveBoundary = this->PreserveBoundary;
  const auto progress = [this](double fraction)
  {
    this->UpdateProgress(0.05 + 0.9 * fraction);
    return !this->CheckAbort();
  };
  polycubehex::TetMesh tets;
  std::string switches;
  const polycubehex::Status status =
    polycubehex::Tetrahedralize(surface, params, tets, switches, progress);
  if (!status)
  {
    vtkErrorMacro(<< status.Message());
    return 0;
  }

  // Needles and caps in the surface make many small tets and a poor polycube: say so.
  const polycubehex::SurfaceAngleReport angles =
    polycubehex::MeasureSurfaceAngles(surface, SmallAngleDegrees);
  if (angles.SmallAngleFaceCount > 0)
  {
    vtkWarningMacro(
      << angles.SmallAngleFaceCount << " of " << surface.Faces.rows()
      << " input triangles have an angle below " << SmallAngleDegrees << " degree (the smallest "
      << angles.SmallestAngleDegrees << " degrees, triangle " << angles.SmallestAngleFace
      << "). TetGen refines around such needles and caps"
      << (this->PreserveBoundary ? "" : " (here " + std::to_string(tets.Cells.rows()) + " tets)")
      << ", and the polycube cannot flatten them cleanly; remesh the surface into "
         "well-shaped triangles first for a faster pipeline and a better hex mesh.");
  }

  // 4. Attach the output: the tets, the input's field data and the switches that were run.
  output->ShallowCopy(polycubehex::ToUnstructuredGrid(tets));
  output->GetFieldData()->PassData(input->GetFieldData());
  vtkNew<vtkStringArray> switchesArray;
  switchesArray->SetName(polycubehex::ArrayNames::TetrahedralizeSwitches);
  switchesArray->InsertNextValue(switches);
  output->GetFieldData()->AddArray(switchesArray);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkTetrahedralizeFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RadiusEdgeRatio: " << this->RadiusEdgeRatio << "\n";
  os << indent << "MaxTetVolume: " << this->MaxTetVolume << "\n";
  os << indent << "TargetTetCount: " << this->TargetTetCount << "\n";
  os << indent << "PreserveBoundary: " << (this->PreserveBoundary ? "on" : "off") << "\n";
}
