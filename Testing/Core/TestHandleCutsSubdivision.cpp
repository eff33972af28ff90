// SPDX-License-Identifier: BSD-3-Clause
// Subdivision for the handle cuts (CutSubdivision, HandleCutParameters::MaxSubdivisionRounds).
//  1. On a torus one tet thick (every vertex on the boundary), splitting the interior edges
//     between two boundary vertices gives positive children whose volumes sum to their parent's,
//     midpoints inside, no such edge left, and a mesh whose cut is still one proper disk.
//  2. A mesh that needs no subdivision gets bit-identical cuts with 0 and 2 rounds, Mesh equal to
//     the input and OriginalCellId the identity.
// No mesh is known here on which round 0 fails (see the commit message): the retry loop itself is
// exercised only through the same functions as in 1.
#include "CutSubdivision.h"
#include "CutSurface.h"
#include "HandleCuts.h"
#include "TestAssert.h"
#include "TestMeshGenerators.h"
#include "TetGeometry.h"
#include "TopologyAdjacency.h"

#include <cmath>
#include <iostream>
#include <numeric>
#include <vector>

using polycubehex::TetMesh;

namespace
{
/// Checks every cut of `result` as the other handle-cut tests do: one cut per handle, each a
/// connected, manifold, two-sided surface on result.Mesh, and beta_1 = 0 after.
void CheckCuts(const polycubehex::HandleCutResult& result, int beta1)
{
  PCH_CHECK(result.Beta1 == beta1);
  PCH_CHECK(static_cast<int>(result.Cuts.size()) == beta1);
  PCH_CHECK(result.Beta1After == 0);
  polycubehex::TetAdjacency adjacency;
  PCH_CHECK(polycubehex::BuildTetAdjacency(
    static_cast<int>(result.Mesh.Vertices.rows()), result.Mesh.Cells, adjacency));
  for (const polycubehex::HandleCut& cut : result.Cuts)
  {
    std::vector<polycubehex::CutFaceEntry> faces;
    for (const auto& minus : cut.Faces)
    {
      const int face = adjacency.InteriorFaceId(minus[0], minus[1]);
      PCH_CHECK(face >= 0);
      faces.push_back({ face, polycubehex::InteriorFaceSign(adjacency, minus[0], minus[1]) });
    }
    polycubehex::CutSurfaceReport report;
    polycubehex::AnalyzeCutSurface(
      result.Mesh.Cells, adjacency, result.Mesh.Vertices, faces, report);
    PCH_CHECK(report.Connected);
    PCH_CHECK(report.Manifold);
    PCH_CHECK(report.TwoSided);
    PCH_CHECK_NEAR(report.Area, cut.Area, 1e-12);
  }
}

void TestThinTorusSplit()
{
  const TetMesh input = polycubehex_test::ThinTorus(3.0, 1.0, 4, 8);
  const int tetCount = static_cast<int>(input.Cells.rows());
  polycubehex::TetAdjacency adjacency;
  PCH_CHECK(polycubehex::BuildTetAdjacency(
    static_cast<int>(input.Vertices.rows()), input.Cells, adjacency));
  int interiorVertices = 0;
  for (bool onBoundary : adjacency.VertexOnBoundary)
  {
    interiorVertices += onBoundary ? 0 : 1;
  }
  PCH_CHECK(interiorVertices == 0);
  const auto chords = polycubehex::BoundaryChordEdges(adjacency, {});
  std::cout << "thin torus: " << tetCount << " tets, " << chords.size()
            << " interior edges between boundary vertices" << std::endl;
  PCH_CHECK(!chords.empty());

  TetMesh refined = input;
  std::vector<int> original(tetCount);
  std::iota(original.begin(), original.end(), 0);
  std::vector<std::array<int, 2>> parents;
  const int split = polycubehex::SubdivideEdges(refined, chords, original, parents);
  std::cout << "split " << split << " tets into " << refined.Cells.rows() << std::endl;
  PCH_CHECK(split > 0);
  PCH_CHECK(static_cast<Eigen::Index>(original.size()) == refined.Cells.rows());
  PCH_CHECK(
    static_cast<Eigen::Index>(parents.size()) + input.Vertices.rows() == refined.Vertices.rows());
  PCH_CHECK(refined.Vertices.topRows(input.Vertices.rows()) == input.Vertices);

  // Children are positive and tile their parent.
  std::vector<double> childVolume(tetCount, 0.0);
  bool positive = true;
  for (int t = 0; t < refined.Cells.rows(); ++t)
  {
    const double volume = polycubehex::TetSignedVolume(refined.Vertices, refined.Cells, t);
    positive = positive && volume > 0.0;
    PCH_CHECK(original[t] >= 0 && original[t] < tetCount);
    childVolume[original[t]] += volume;
  }
  PCH_CHECK(positive);
  double worst = 0.0;
  for (int t = 0; t < tetCount; ++t)
  {
    const double volume = polycubehex::TetSignedVolume(input.Vertices, input.Cells, t);
    worst = std::max(worst, std::abs(childVolume[t] - volume) / volume);
  }
  PCH_CHECK(worst < 1e-12);

  // The midpoints are inside, and no interior edge joins two boundary vertices any more.
  polycubehex::TetAdjacency after;
  PCH_CHECK(polycubehex::BuildTetAdjacency(
    static_cast<int>(refined.Vertices.rows()), refined.Cells, after));
  bool inside = true;
  for (Eigen::Index v = input.Vertices.rows(); v < refined.Vertices.rows(); ++v)
  {
    inside = inside && !after.VertexOnBoundary[v];
  }
  PCH_CHECK(inside);
  PCH_CHECK(polycubehex::BoundaryChordEdges(after, {}).empty());

  // Both meshes still get one proper cut.
  for (const TetMesh* mesh : std::vector<const TetMesh*>{ &input, &refined })
  {
    polycubehex::HandleCutParameters params;
    params.MaxSubdivisionRounds = 0;
    polycubehex::HandleCutResult result;
    const auto status = polycubehex::ComputeHandleCuts(*mesh, params, result);
    PCH_CHECK(status.Ok());
    if (!status)
    {
      std::cout << status.Message() << std::endl;
      continue;
    }
    std::cout << mesh->Cells.rows() << " tets: cut area " << result.Cuts[0].Area << ", "
              << result.Cuts[0].Faces.size() << " faces" << std::endl;
    CheckCuts(result, 1);
  }
}

void TestNoSubdivisionNeeded()
{
  const TetMesh mesh = polycubehex_test::SweptTorus(2.0, 0.8, 0, 3, 24);
  polycubehex::HandleCutResult off;
  polycubehex::HandleCutResult on;
  polycubehex::HandleCutParameters params;
  params.MaxSubdivisionRounds = 0;
  PCH_CHECK(polycubehex::ComputeHandleCuts(mesh, params, off).Ok());
  params.MaxSubdivisionRounds = 2;
  PCH_CHECK(polycubehex::ComputeHandleCuts(mesh, params, on).Ok());
  PCH_CHECK(on.SubdivisionRounds == 0 && on.SubdividedTetCount == 0 && on.SplitEdgeCount == 0);
  PCH_CHECK(on.Mesh.Cells == mesh.Cells && on.Mesh.Vertices == mesh.Vertices);
  std::vector<int> identity(mesh.Cells.rows());
  std::iota(identity.begin(), identity.end(), 0);
  PCH_CHECK(on.OriginalCellId == identity);
  PCH_CHECK(on.MidpointParents.empty());
  PCH_CHECK(on.CutFaces == off.CutFaces && on.CutSide == off.CutSide);
  PCH_CHECK(on.Cuts.size() == off.Cuts.size());
  for (size_t c = 0; c < on.Cuts.size() && c < off.Cuts.size(); ++c)
  {
    PCH_CHECK(on.Cuts[c].Faces == off.Cuts[c].Faces && on.Cuts[c].Loops == off.Cuts[c].Loops);
    PCH_CHECK(on.Cuts[c].Area == off.Cuts[c].Area);
  }
  CheckCuts(on, 1);
}
} // namespace

int main(int, char*[])
{
  TestThinTorusSplit();
  TestNoSubdivisionNeeded();
  return PCH_TEST_RESULT();
}
