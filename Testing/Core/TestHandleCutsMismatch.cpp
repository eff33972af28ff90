// SPDX-License-Identifier: BSD-3-Clause
// Mismatched edges (section 5.3 of the paper) on a hollow torus: the second cut crosses the
// first (an annulus joining the outer and the inner surface), so its boundary runs along both
// copies of every edge it shares with the first cut: no mismatched edge. Shifting its end along
// one copy only (a valid cut still, lowering beta_1 by one) must be reported as mismatched.
#include "CutMesh.h"
#include "CutRepair.h"
#include "CutSurface.h"
#include "HandleCuts.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"
#include "TopologyAdjacency.h"
#include "TopologyBoundary.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <numeric>
#include <vector>

using polycubehex::TetMesh;
using polycubehex_test::SweptTorus;

int main(int, char*[])
{
  const TetMesh mesh = SweptTorus(2.0, 0.8, 2, 5, 40);
  polycubehex::HandleCutParameters params;
  polycubehex::HandleCutResult result;
  const auto status = polycubehex::ComputeHandleCuts(mesh, params, result);
  PCH_CHECK(status.Ok());
  PCH_CHECK(result.Cuts.size() == 2);
  if (!status || result.Cuts.size() != 2)
  {
    return PCH_TEST_RESULT();
  }
  PCH_CHECK(result.Cuts[0].EulerCharacteristic == 0 && result.Cuts[0].Loops.size() == 2);
  PCH_CHECK(result.Cuts[1].MismatchedEdgeCount == 0);

  // M_1: the input opened along the first cut.
  const int vertexCount = static_cast<int>(mesh.Vertices.rows());
  polycubehex::TetAdjacency input;
  polycubehex::BuildTetAdjacency(vertexCount, mesh.Cells, input);
  std::vector<char> cut(input.InteriorFaces.size(), 0);
  for (size_t f = 0; f < input.InteriorFaces.size(); ++f)
  {
    cut[f] = result.CutFaces(input.InteriorFaces[f][0], input.InteriorFaces[f][1]) == 0 ? 1 : 0;
  }
  TetMesh opened;
  std::vector<int> toOriginal;
  polycubehex::SplitAlongFaces(vertexCount, mesh.Cells, input, cut, opened.Cells, toOriginal);
  opened.Vertices.resize(static_cast<Eigen::Index>(toOriginal.size()), 3);
  for (size_t v = 0; v < toOriginal.size(); ++v)
  {
    opened.Vertices.row(v) = mesh.Vertices.row(toOriginal[v]);
  }
  polycubehex::TetAdjacency adjacency;
  polycubehex::BuildTetAdjacency(static_cast<int>(toOriginal.size()), opened.Cells, adjacency);

  // The second cut on M_1: crosses the first, so no mismatched edge.
  std::vector<int> cocycle(adjacency.InteriorFaces.size(), 0);
  std::vector<polycubehex::CutFaceEntry> entries;
  for (const auto& face : result.Cuts[1].Faces)
  {
    const int id = adjacency.InteriorFaceId(face[0], face[1]);
    const int side = adjacency.InteriorFaces[id][0] == face[0] ? 1 : -1;
    entries.push_back({ id, side });
    cocycle[id] = side;
  }
  polycubehex::CutSurfaceReport report;
  polycubehex::AnalyzeCutSurface(opened.Cells, adjacency, opened.Vertices, entries, report);
  PCH_CHECK(report.Valid());
  const int matched = polycubehex::CountMismatchedCutEdges(input, report.Loops, toOriginal);
  std::cout << "second cut: " << report.Area << " area, " << matched << " mismatched edges"
            << std::endl;
  PCH_CHECK(matched == 0);

  // Shift its end along the copies of the first cut that got new vertex ids (one side only):
  // move the minus-side tets touching them across, then repair.
  std::vector<char> inK(adjacency.TetCount, 0);
  for (const auto& face : result.Cuts[1].Faces)
  {
    const int t = face[0];
    for (int i = 0; i < 4; ++i)
    {
      inK[t] = inK[t] || opened.Cells(t, i) >= vertexCount;
    }
  }
  for (int t = 0; t < adjacency.TetCount; ++t)
  {
    if (!inK[t])
    {
      continue;
    }
    for (int k = 0; k < 4; ++k)
    {
      const int n = adjacency.Neighbor(t, k);
      if (n >= 0 && !inK[n])
      {
        cocycle[adjacency.InteriorFaceId(t, k)] -= polycubehex::InteriorFaceSign(adjacency, t, k);
      }
    }
  }
  std::vector<double> faceArea(adjacency.InteriorFaces.size());
  for (size_t f = 0; f < faceArea.size(); ++f)
  {
    faceArea[f] =
      polycubehex::InteriorFaceArea(opened.Cells, adjacency, opened.Vertices, static_cast<int>(f));
  }
  PCH_CHECK(polycubehex::RepairCocycleSurface(opened.Cells, adjacency, faceArea, cocycle, 10000));
  entries.clear();
  for (size_t f = 0; f < cocycle.size(); ++f)
  {
    if (cocycle[f] != 0)
    {
      entries.push_back({ static_cast<int>(f), cocycle[f] > 0 ? 1 : -1 });
    }
  }
  polycubehex::AnalyzeCutSurface(opened.Cells, adjacency, opened.Vertices, entries, report);
  if (!report.Valid())
  {
    std::cerr << report.Problem << std::endl;
  }
  PCH_CHECK(report.Valid());
  const int mismatched = polycubehex::CountMismatchedCutEdges(input, report.Loops, toOriginal);
  std::cout << "shifted second cut: " << report.Area << " area, " << mismatched
            << " mismatched edges" << std::endl;
  PCH_CHECK(mismatched > 0);

  // It is still a valid cut: beta_1 of M_1 cut along it is 0.
  std::vector<char> second(adjacency.InteriorFaces.size(), 0);
  for (const auto& entry : entries)
  {
    second[entry.Face] = 1;
  }
  TetMesh twice;
  std::vector<int> splitToOld;
  polycubehex::SplitAlongFaces(
    static_cast<int>(toOriginal.size()), opened.Cells, adjacency, second, twice.Cells, splitToOld);
  polycubehex::TetAdjacency twiceAdjacency;
  polycubehex::BuildTetAdjacency(static_cast<int>(splitToOld.size()), twice.Cells, twiceAdjacency);
  polycubehex::BoundaryTopology boundary;
  PCH_CHECK(polycubehex::ComputeBoundaryTopology(twice.Cells, twiceAdjacency, boundary).Ok());
  PCH_CHECK(boundary.Beta1 == 0);
  return PCH_TEST_RESULT();
}
