// SPDX-License-Identifier: BSD-3-Clause
// Combinatorics of a tet mesh used by the topology and cut code: face adjacency with numbered
// interior faces, numbered edges, the ring of tets around an edge, and the tets around a vertex.
// Only vertex ids matter here (no geometry, no orientation): a mesh whose cut faces carry
// different vertex ids on their two sides is simply a mesh whose cut faces are boundary.
#pragma once

#include "MeshTypes.h"
#include "Status.h"
#include "TetGeometry.h"

#include <array>
#include <vector>

namespace polycubehex
{

/// Local edges of a tet, VTK's vtkTetra order: edge e joins local vertices TetEdgeTable[e].
constexpr int TetEdgeTable[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
/// The local face opposite local vertex v (TetFaceTable[TetOppositeFace[v]] does not hold v).
constexpr int TetOppositeFace[4] = { 1, 2, 0, 3 };

/// Face, edge and vertex incidences of a tet mesh.
struct TetAdjacency
{
  int VertexCount = 0;
  int TetCount = 0;
  /// #T by 4: the tet across local face k, or -1 when that face is on the boundary.
  Tets Neighbor;
  /// #T by 4: the local face index of the same face in Neighbor(t, k), or -1.
  Tets NeighborFace;
  /// #T by 4: the id of the interior face at local face k (both tets carry it), or -1.
  Tets InteriorFaceId;
  /// Per interior face: its "first" side (tet, local face): the side with the smaller tet id.
  /// A value on an interior face (a cochain) is read across the face from first to second tet.
  std::vector<std::array<int, 2>> InteriorFaces;
  /// Per edge: its two vertices, smaller first; edges are sorted lexicographically.
  std::vector<std::array<int, 2>> EdgeVertices;
  /// #T by 6: the edge id of local edge e (TetEdgeTable) of tet t.
  Eigen::Matrix<int, Eigen::Dynamic, 6, Eigen::RowMajor> TetEdge;
  /// Per edge: one tet holding it and its local edge index there.
  std::vector<std::array<int, 2>> EdgeTet;
  /// Per edge: true when the edge lies on a boundary face.
  std::vector<char> EdgeOnBoundary;
  /// Per vertex: true when the vertex lies on a boundary face.
  std::vector<char> VertexOnBoundary;
  /// Tets around each vertex (CSR): VertexTets[VertexTetOffsets[v] .. VertexTetOffsets[v+1]).
  std::vector<int> VertexTetOffsets;
  std::vector<int> VertexTets;
  int BoundaryFaceCount = 0;
};

/// Builds the incidences. Fails, naming the face, when a face is shared by more than two tets,
/// and, naming the tet, when a tet repeats a vertex or refers to a vertex outside [0, #V).
Status BuildTetAdjacency(int vertexCount, const Tets& cells, TetAdjacency& adjacency);

/// +1 when (tet, local face) is the first side of its interior face, -1 when it is the second.
inline int InteriorFaceSign(const TetAdjacency& adjacency, int tet, int local)
{
  const auto& first = adjacency.InteriorFaces[adjacency.InteriorFaceId(tet, local)];
  return first[0] == tet && first[1] == local ? 1 : -1;
}

/// One step of the walk around an edge: from `Tet` through its local face `Exit`.
struct EdgeRingStep
{
  int Tet;
  int Exit;
};

/// The tets around edge `edge` in cyclic order. For an interior edge the ring closes: step i
/// goes from ring[i].Tet through ring[i].Exit into ring[i+1].Tet (indices modulo the size) and
/// `closed` is true. For a boundary edge the ring is the fan from one boundary face to the
/// other: the last step's Exit is a boundary face, the first tet's other face at the edge is the
/// other boundary face, and `closed` is false.
void WalkAroundEdge(const Tets& cells,
  const TetAdjacency& adjacency,
  int edge,
  std::vector<EdgeRingStep>& ring,
  bool& closed);

/// The two local faces of a tet that hold local edge `localEdge`.
inline std::array<int, 2> FacesOfLocalEdge(int localEdge)
{
  int others[2];
  int count = 0;
  for (int v = 0; v < 4; ++v)
  {
    if (v != TetEdgeTable[localEdge][0] && v != TetEdgeTable[localEdge][1])
    {
      others[count++] = v;
    }
  }
  return { TetOppositeFace[others[0]], TetOppositeFace[others[1]] };
}

/// The local edge index (TetEdgeTable) joining local vertices i and j (i != j).
inline int TetLocalEdge(int i, int j)
{
  for (int e = 0; e < 6; ++e)
  {
    if ((TetEdgeTable[e][0] == i && TetEdgeTable[e][1] == j) ||
      (TetEdgeTable[e][0] == j && TetEdgeTable[e][1] == i))
    {
      return e;
    }
  }
  return -1;
}

/// The three edge ids of interior face `face`.
inline std::array<int, 3> InteriorFaceEdges(const TetAdjacency& adjacency, int face)
{
  const int t = adjacency.InteriorFaces[face][0];
  const int k = adjacency.InteriorFaces[face][1];
  std::array<int, 3> edges{};
  for (int c = 0; c < 3; ++c)
  {
    edges[c] = adjacency.TetEdge(t, TetLocalEdge(TetFaceTable[k][c], TetFaceTable[k][(c + 1) % 3]));
  }
  return edges;
}

/// The local index of global vertex `vertex` in tet `tet`, or -1.
inline int LocalVertexIndex(const Tets& cells, int tet, int vertex)
{
  for (int i = 0; i < 4; ++i)
  {
    if (cells(tet, i) == vertex)
    {
      return i;
    }
  }
  return -1;
}

/// Number of connected components of the solid: tets joined through interior faces that are
/// not blocked (blocked may be empty, else one flag per interior face). `component` (optional)
/// receives each tet's component id.
int CountSolidComponents(const TetAdjacency& adjacency,
  const std::vector<char>& blocked,
  std::vector<int>* component = nullptr);

} // namespace polycubehex
