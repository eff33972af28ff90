// SPDX-License-Identifier: BSD-3-Clause
// Edge splits on a cut mesh keep the two copies of every cut face copies of each other. Two tets
// share one face, which is the cut; two edges of that face are split, one asked for on each
// side. Splitting them in the order asked would cut the face into different halves on the two
// sides (the pieces would then count as boundary faces of M and fold the polycube); with the
// edges ordered by SortCopiesAlike every piece has its copy across the cut.
#include "PolycubeCutMesh.h"
#include "TestAssert.h"
#include "TetEdgeSplit.h"
#include "TetGeometry.h"

#include <algorithm>
#include <iostream>
#include <map>

using namespace polycubehex;

namespace
{
/// The number of boundary faces of `cells` whose copy (the same points of M, by `identity`) is
/// also a boundary face: the faces of the cut, on both sides.
int PairedBoundaryFaces(int vertexCount, const Tets& cells, const std::vector<int>& identity)
{
  TetTopology topology;
  ComputeTetTopology(vertexCount, cells, topology);
  std::map<std::array<int, 3>, int> seen;
  for (Eigen::Index f = 0; f < topology.BoundaryFaces.rows(); ++f)
  {
    std::array<int, 3> key;
    for (int c = 0; c < 3; ++c)
    {
      key[static_cast<size_t>(c)] = identity[static_cast<size_t>(topology.BoundaryFaces(f, c))];
    }
    std::sort(key.begin(), key.end());
    ++seen[key];
  }
  int paired = 0;
  for (const auto& entry : seen)
  {
    paired += entry.second == 2 ? 2 : 0;
  }
  return paired;
}

/// Splits `requested` on the cut mesh as ComputePolycube does; returns the paired faces.
int SplitAndCount(const PolycubeCutMesh& cut,
  const std::vector<std::array<int, 2>>& requested,
  bool sortCopies)
{
  const int n = static_cast<int>(cut.CopiedVertex.size());
  std::vector<CopyRelation> copies = cut.Copies;
  std::vector<int> identity = cut.CopiedVertex;
  std::vector<std::array<int, 3>> partners;
  std::vector<std::array<int, 2>> edges = MirrorEdgesAcrossCuts(requested, copies, n, partners);
  if (sortCopies)
  {
    SortCopiesAlike(edges, partners, identity);
  }
  Tets cells = cut.Cells;
  std::vector<int> parentTet;
  std::vector<std::array<int, 2>> parents;
  SplitTetEdges(n, cells, edges, parentTet, parents);
  AddMidpointCopies(edges, partners, parents, n, copies, identity);
  return PairedBoundaryFaces(n + static_cast<int>(parents.size()), cells, identity);
}
} // namespace

int main()
{
  // Tets (0 1 2 3) and (0 2 1 4) share the face {0, 1, 2}, the cut (identity transition).
  TetMesh mesh;
  mesh.Vertices.resize(5, 3);
  mesh.Vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.3, 0.3, -1;
  mesh.Cells.resize(2, 4);
  mesh.Cells << 0, 1, 2, 3, 0, 2, 1, 4;
  PolycubeCuts cuts;
  cuts.FaceCut = Tets::Constant(2, 4, -1);
  cuts.FaceSide = Tets::Zero(2, 4);
  // Face {0, 1, 2} is local face 3 of the first tet ({0, 2, 1}) and of the second ({0, 1, 2}).
  cuts.FaceCut(0, 3) = 0;
  cuts.FaceCut(1, 3) = 0;
  cuts.FaceSide(0, 3) = -1;
  cuts.FaceSide(1, 3) = 1;
  cuts.Transitions.push_back(Eigen::Matrix3i::Identity());
  PolycubeCutMesh cut;
  const Status built = BuildPolycubeCutMesh(mesh, cuts, cut);
  PCH_CHECK(built);
  if (!built)
  {
    std::cerr << built.Message() << "\n";
    return polycubehex_test::FailureCount();
  }
  PCH_CHECK(cut.Copies.size() == 3);

  // The copies of input vertices 0, 1, 2 on each side.
  auto copyOf = [&](int input, bool minus)
  {
    for (const CopyRelation& r : cut.Copies)
    {
      if (cut.CopiedVertex[static_cast<size_t>(r.Minus)] == input)
      {
        return minus ? r.Minus : r.Plus;
      }
    }
    return -1;
  };
  // Edge {0, 1} asked for on the minus side, edge {1, 2} on the plus side: each is mirrored.
  const std::vector<std::array<int, 2>> requested = { { copyOf(0, true), copyOf(1, true) },
    { copyOf(1, false), copyOf(2, false) } };
  const int unsplit = PairedBoundaryFaces(
    static_cast<int>(cut.CopiedVertex.size()), cut.Cells, cut.CopiedVertex);
  const int unsorted = SplitAndCount(cut, requested, false);
  const int sorted = SplitAndCount(cut, requested, true);
  std::cout << "paired cut faces: before splitting " << unsplit << ", split in the order asked "
            << unsorted << ", split with SortCopiesAlike " << sorted << "\n";
  PCH_CHECK(unsplit == 2);
  // The cut face becomes three pieces per side; all six are paired only with the ordering.
  PCH_CHECK(sorted == 6);
  PCH_CHECK(unsorted < 6);
  return polycubehex_test::FailureCount();
}
