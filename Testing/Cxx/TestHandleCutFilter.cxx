// SPDX-License-Identifier: BSD-3-Clause
// vtkHandleCutFilter: the cut count equals beta_1 (sphere 0, torus 1, 3holes 3), the cut arrays
// pair up across every cut face, the frame field downstream gets one transition per cut, and
// an empty input is refused.
#include "PolycubeHexTestErrors.h"
#include "TestAssert.h"
#include "vtkFrameFieldFilter.h"
#include "vtkHandleCutFilter.h"
#include "vtkTetrahedralizeFilter.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <map>
#include <set>
#include <string>

namespace
{
const int TetFaces[4][3] = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 2, 1 } };

/// Every face marked as cut must be marked on both of its tets, with the same id and opposite
/// sides. Returns the number of distinct cut ids.
int CheckCutArrays(vtkUnstructuredGrid* grid)
{
  vtkDataArray* ids = grid->GetCellData()->GetArray("CutFaces");
  vtkDataArray* sides = grid->GetCellData()->GetArray("CutSide");
  PCH_CHECK(ids && sides && ids->GetNumberOfComponents() == 4);
  if (!ids || !sides)
  {
    return -1;
  }
  std::map<std::set<vtkIdType>, std::pair<int, int>> faces; // face -> (id, sum of sides)
  std::map<std::set<vtkIdType>, int> count;
  std::set<int> cutIds;
  for (vtkIdType t = 0; t < grid->GetNumberOfCells(); ++t)
  {
    const vtkIdType* points = nullptr;
    vtkIdType n = 0;
    grid->GetCellPoints(t, n, points);
    for (int k = 0; k < 4; ++k)
    {
      const int id = static_cast<int>(ids->GetComponent(t, k));
      const int side = static_cast<int>(sides->GetComponent(t, k));
      PCH_CHECK((id < 0) == (side == 0));
      if (id < 0)
      {
        continue;
      }
      cutIds.insert(id);
      const std::set<vtkIdType> face{ points[TetFaces[k][0]], points[TetFaces[k][1]],
        points[TetFaces[k][2]] };
      auto& entry = faces[face];
      PCH_CHECK(count[face] == 0 || entry.first == id);
      entry.first = id;
      entry.second += side;
      ++count[face];
    }
  }
  for (const auto& face : faces)
  {
    PCH_CHECK(count[face.first] == 2 && face.second.second == 0);
  }
  return static_cast<int>(cutIds.size());
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    return 1;
  }
  const std::string data = argv[1];
  const std::map<std::string, int> expected = { { "sphere_coarse.obj", 0 }, { "torus.obj", 1 },
    { "3holes.obj", 3 } };
  for (const auto& model : expected)
  {
    vtkNew<vtkOBJReader> reader;
    reader->SetFileName((data + "/" + model.first).c_str());
    vtkNew<vtkTetrahedralizeFilter> tets;
    tets->SetInputConnection(reader->GetOutputPort());
    vtkNew<vtkHandleCutFilter> cuts;
    cuts->SetInputConnection(tets->GetOutputPort());
    cuts->Update();
    vtkUnstructuredGrid* output = cuts->GetOutput(0);
    vtkDataArray* betti =
      vtkDataArray::SafeDownCast(output->GetFieldData()->GetAbstractArray("BettiNumber"));
    PCH_CHECK(betti && betti->GetTuple1(0) == model.second);
    const int cutCount = CheckCutArrays(output);
    std::cout << model.first << ": beta_1 " << (betti ? betti->GetTuple1(0) : -1) << ", "
              << cutCount << " cut(s)\n";
    PCH_CHECK(cutCount == model.second);
    // No subdivision here: the same tets, OriginalCellId the identity, the input's arrays kept.
    vtkDataArray* subdivided =
      vtkDataArray::SafeDownCast(output->GetFieldData()->GetAbstractArray("SubdividedTetCount"));
    PCH_CHECK(subdivided && subdivided->GetTuple1(0) == 0);
    vtkUnstructuredGrid* cutInput = tets->GetOutput();
    PCH_CHECK(output->GetNumberOfCells() == cutInput->GetNumberOfCells());
    vtkDataArray* originalCellId = output->GetCellData()->GetArray("OriginalCellId");
    PCH_CHECK(originalCellId && originalCellId->GetNumberOfTuples() == output->GetNumberOfCells());
    bool identity = originalCellId != nullptr;
    for (vtkIdType t = 0; identity && t < output->GetNumberOfCells(); ++t)
    {
      identity = originalCellId->GetTuple1(t) == t;
    }
    PCH_CHECK(identity);
    for (int a = 0; a < cutInput->GetCellData()->GetNumberOfArrays(); ++a)
    {
      PCH_CHECK(output->GetCellData()->GetArray(cutInput->GetCellData()->GetArrayName(a)));
    }
    vtkPolyData* surfaces = vtkPolyData::SafeDownCast(cuts->GetOutputDataObject(1));
    vtkPolyData* loops = vtkPolyData::SafeDownCast(cuts->GetOutputDataObject(2));
    PCH_CHECK((surfaces->GetNumberOfPolys() > 0) == (model.second > 0));
    PCH_CHECK(loops->GetNumberOfLines() >= model.second);

    // Downstream, the frame field has one transition per cut, each a cube rotation.
    vtkNew<vtkFrameFieldFilter> frames;
    frames->SetInputConnection(cuts->GetOutputPort());
    frames->SetMaxIterations(50);
    frames->Update();
    vtkDataArray* transitions = vtkDataArray::SafeDownCast(
      frames->GetOutput(0)->GetFieldData()->GetAbstractArray("CutTransitions"));
    PCH_CHECK(transitions && transitions->GetNumberOfTuples() == model.second);
    for (vtkIdType c = 0; transitions && c < transitions->GetNumberOfTuples(); ++c)
    {
      int nonZero = 0;
      for (int k = 0; k < 9; ++k)
      {
        const double value = transitions->GetComponent(c, k);
        PCH_CHECK(value == 0 || value == 1 || value == -1);
        nonZero += value != 0 ? 1 : 0;
      }
      PCH_CHECK(nonZero == 3);
    }
  }

  // An empty grid is refused.
  vtkNew<ErrorCapture> errors;
  vtkNew<vtkUnstructuredGrid> empty;
  vtkNew<vtkHandleCutFilter> refused;
  errors->Watch(refused);
  refused->SetInputData(empty);
  refused->Update();
  PCH_CHECK(errors->Mentions("no cells"));
  return PCH_TEST_RESULT();
}
