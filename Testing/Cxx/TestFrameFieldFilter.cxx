// SPDX-License-Identifier: BSD-3-Clause
// vtkFrameFieldFilter on the torus: frames and glyphs attached, boundary alignment below 10
// degrees, singular edges near the boundary; a half-specified cut is refused.
#include "PolycubeHexTestErrors.h"
#include "TestAssert.h"
#include "vtkFrameFieldFilter.h"
#include "vtkTetrahedralizeFilter.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <string>

namespace
{
double FieldValue(vtkDataObject* data, const char* name)
{
  vtkDataArray* array =
    vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : std::nan("");
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    return 1;
  }
  const std::string data = argv[1];
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName((data + "/torus.obj").c_str());
  vtkNew<vtkTetrahedralizeFilter> tets;
  tets->SetInputConnection(reader->GetOutputPort());
  // A round torus needs several tets across its tube before one frame per tet can follow the
  // curved boundary: 2.5k tets (TetGen's default here) give 19.8 degrees, 10k 13.6, 30k 8.3.
  tets->SetTargetTetCount(30000);
  tets->Update();
  vtkUnstructuredGrid* torus = tets->GetOutput();
  PCH_CHECK(torus->GetNumberOfCells() > 20000);

  vtkNew<vtkFrameFieldFilter> frames;
  frames->SetInputData(torus);
  frames->SetMaximumGlyphCount(500);
  frames->Update();
  vtkUnstructuredGrid* output = frames->GetOutput(0);
  PCH_CHECK(output->GetNumberOfCells() == torus->GetNumberOfCells());
  vtkDataArray* frame = output->GetCellData()->GetArray("Frame");
  PCH_CHECK(frame && frame->GetNumberOfComponents() == 9);
  PCH_CHECK(output->GetCellData()->GetArray("FrameU") != nullptr);
  // Every frame is a rotation: rows orthonormal, determinant +1.
  double worst = 0.0;
  for (vtkIdType t = 0; frame && t < output->GetNumberOfCells(); t += 7)
  {
    const double* r = frame->GetTuple(t);
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        const double dot = r[3 * a] * r[3 * b] + r[3 * a + 1] * r[3 * b + 1] + r[3 * a + 2] * r[3 * b + 2];
        worst = std::max(worst, std::fabs(dot - (a == b ? 1.0 : 0.0)));
      }
    }
  }
  PCH_CHECK(worst < 1e-9);

  const double alignment = FieldValue(output, "BoundaryAlignmentError");
  const double singular = FieldValue(output, "SingularEdgeCount");
  const double depth = FieldValue(output, "MaxSingularEdgeDepth");
  std::cout << "torus: alignment error " << alignment << " deg, singular edges " << singular
            << ", interior " << FieldValue(output, "InteriorSingularEdgeCount") << ", max depth "
            << depth << ", iterations " << FieldValue(output, "FrameIterations") << "\n";
  PCH_CHECK(alignment < 10.0);
  PCH_CHECK(depth <= 0.03);
  vtkDataArray* transitions =
    vtkDataArray::SafeDownCast(output->GetFieldData()->GetAbstractArray("CutTransitions"));
  PCH_CHECK(transitions && transitions->GetNumberOfTuples() == 0); // no cuts given

  vtkPolyData* glyphs = vtkPolyData::SafeDownCast(frames->GetOutputDataObject(1));
  PCH_CHECK(glyphs->GetNumberOfPoints() > 0 && glyphs->GetNumberOfPoints() <= 500);
  PCH_CHECK(glyphs->GetPointData()->GetArray("FrameW") != nullptr);
  vtkPolyData* edges = vtkPolyData::SafeDownCast(frames->GetOutputDataObject(2));
  PCH_CHECK(edges->GetNumberOfLines() == static_cast<vtkIdType>(singular));

  // CutFaces without CutSide: refused with both names in the message.
  vtkNew<vtkUnstructuredGrid> halfCut;
  halfCut->ShallowCopy(torus);
  vtkNew<vtkIntArray> cutFaces;
  cutFaces->SetName("CutFaces");
  cutFaces->SetNumberOfComponents(4);
  cutFaces->SetNumberOfTuples(torus->GetNumberOfCells());
  cutFaces->Fill(-1);
  halfCut->GetCellData()->AddArray(cutFaces);
  vtkNew<ErrorCapture> errors;
  vtkNew<vtkFrameFieldFilter> refused;
  errors->Watch(refused);
  refused->SetInputData(halfCut);
  refused->Update();
  PCH_CHECK(refused->GetOutput(0)->GetNumberOfCells() == 0);
  PCH_CHECK(errors->Mentions("CutSide"));
  return PCH_TEST_RESULT();
}
